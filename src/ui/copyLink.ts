/**
 * The "Copy link" button: the current state as a URL (the full calculator's, plain numbers), for a
 * colleague or a bookmark. Copied to the clipboard with a confirmation; where the browser refuses,
 * the link is shown selected in a text box to copy by hand.
 */
import { html } from './dom';
import { localize } from './i18n/words';

/** What a copy button says: on success, when the clipboard is refused, and for how long (null: until the next). */
export interface CopyWords {
  readonly copied: string;
  readonly refused: string;
  readonly clearAfterMs: number | null;
}

/**
 * Wires a copy button: on click it copies `text()` and says so in `status` (a live region); if the
 * clipboard is refused, the text is shown in `fallback` (a read-only field placed after `status`), selected.
 */
export function wireClipboardCopy(
  button: HTMLButtonElement,
  status: HTMLElement,
  fallback: HTMLInputElement | HTMLTextAreaElement,
  text: () => string,
  words: CopyWords,
): void {
  fallback.hidden = true;
  status.after(fallback);
  let timer: ReturnType<typeof setTimeout> | null = null;
  const say = (message: string): void => {
    status.textContent = message;
    // In the language in force (language.ts reads the English back).
    localize(status);
    if (words.clearAfterMs === null) return;
    if (timer !== null) clearTimeout(timer);
    timer = setTimeout(() => {
      status.textContent = '';
    }, words.clearAfterMs);
  };
  button.addEventListener('click', () => {
    const value = text();
    fallback.value = value;
    const refused = (): void => {
      fallback.hidden = false;
      fallback.select();
      say(words.refused);
    };
    const clipboard = navigator.clipboard;
    if (!clipboard) {
      refused();
      return;
    }
    clipboard.writeText(value).then(() => {
      fallback.hidden = true;
      say(words.copied);
    }, refused);
  });
}

/**
 * Wires the button: on click it copies `link()` and says so in `status` (a live region); if the
 * clipboard is refused, the link is shown in a read-only field, selected.
 */
export function wireCopyLink(button: HTMLButtonElement, status: HTMLElement, link: () => string): void {
  const fallback = html('input', {
    type: 'text',
    class: 'link-text',
    readonly: '',
    'aria-label': 'Link to this state',
    'data-testid': 'link-text',
  });
  wireClipboardCopy(button, status, fallback, link, {
    copied: 'Link copied: it opens this calculator with these inputs.',
    refused: 'Copying was refused by the browser: the link is selected below, copy it by hand.',
    clearAfterMs: null,
  });
}
