/**
 * The words of a number entry's common faults, shared by every field's messages (the tool and
 * surface fields' inputErrors.ts and the teeth-and-feed fields' finishInput.ts): one wording, one
 * place. Field-specific faults (ranges, gouging, the fz limit) stay with their fields.
 */

import { escapeControls } from './visibleText';

/**
 * What the user typed, as a message quotes it: at most 24 characters (21 and "..." beyond), each
 * character a message would not show written as its escape (`3\x07`, `\u202e`: visibleText.ts),
 * so that the quote never looks like a valid number.
 */
export function quotedEntry(typed: string): string {
  return escapeControls(typed.length > 24 ? `${typed.slice(0, 21)}...` : typed);
}

/** The faults every number entry shares. */
export type EntryFault = 'missing' | 'not-a-number' | 'not-finite' | 'negative' | 'too-small';

const ENTRY_FAULTS: ReadonlySet<string> = new Set<EntryFault>([
  'missing',
  'not-a-number',
  'not-finite',
  'negative',
  'too-small',
]);

/** True for a fault every number entry shares (worded by {@link entryFaultMessage}). */
export function isEntryFault(code: string): code is EntryFault {
  return ENTRY_FAULTS.has(code);
}

/**
 * The one-line message of a common entry fault.
 * @param label the field's label ("Feed per tooth fz")
 * @param fault the fault
 * @param typed what was typed (quoted as {@link quotedEntry} shortens it)
 * @param unitSymbolText the field's unit symbol ("mm", "in"; "" for a count or an angle)
 * @param limitText the limit in words with its unit, for `too-small` ("0.001 mm")
 */
export function entryFaultMessage(
  label: string,
  fault: EntryFault,
  typed: string,
  unitSymbolText: string,
  limitText = '',
): string {
  const shown = quotedEntry(typed);
  switch (fault) {
    case 'missing':
      return `${label} is missing: enter a number.`;
    case 'not-a-number':
      return `${label} must be a number (got "${shown}").`;
    case 'not-finite':
      return `${label} must be a finite number (got ${shown}).`;
    case 'negative':
      return `${label} must be 0${unitSymbolText === '' ? '' : ` ${unitSymbolText}`} or more (got ${shown}).`;
    case 'too-small':
      return `${label} must be at least ${limitText} (got ${shown}).`;
  }
}
