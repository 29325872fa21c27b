/**
 * A worker's reason for a restart (issue 30), as worker/client.ts writes it in English ("the solver
 * threw (TypeError: ...)", "the solver stopped answering"...), read back and worded in a catalogue's
 * language as a sentence of its own: an exception's own text (the detail in parentheses) is not in
 * it, the page shows it in a hover title (reasonDetail, setDetail). Pure (setDetail takes an element's title): noticeWords.ts,
 * finishPanel.ts, targetSaPanel.ts and lookupDownload.ts use it. Loaded with them, on first use.
 */
import type { Catalogue, WorkerReason } from './catalogue';

/** worker/client.ts's reasons (tests/ui/i18n/workerReason.test.ts reads its restart calls against these). */
const REASONS: ReadonlyArray<readonly [RegExp, WorkerReason]> = [
  [/^the solver failed \((.*)\)$/s, 'failed'],
  [/^the solver threw \((.*)\)$/s, 'threw'],
  [/^the solver did not load$/, 'load'],
  [/^the solver stopped answering$/, 'stopped'],
];

/**
 * A reason in `c`'s language and its detail (an exception's text, kept as it is for a hover title;
 * '' when none); null when `english` is none of client.ts's reasons.
 */
export function reasonParts(english: string, c: Pick<Catalogue, 'said'>): readonly [string, string] | null {
  for (const [pattern, kind] of REASONS) {
    const m = pattern.exec(english);
    if (m !== null) return [c.said.reason(kind), m[1] ?? ''];
  }
  return null;
}

/** A reason in `c`'s language, without an exception's text (null: English, as written); one not known is kept as it is. */
export function reasonIn(english: string, c: Pick<Catalogue, 'said'> | null): string {
  const parts = c === null ? null : reasonParts(english, c);
  return parts === null ? english : parts[0];
}

/** The exception's text a reason worded in `c`'s language leaves out ('' in English, or none). */
export function reasonDetail(english: string, c: Pick<Catalogue, 'said'> | null): string {
  return (c === null ? null : reasonParts(english, c))?.[1] ?? '';
}

/** Puts an exception's text (`detail`, '' for none) in `e`'s hover title, or takes it away. */
export function setDetail(e: { title: string; removeAttribute(name: string): void }, detail: string): void {
  if (detail === '') e.removeAttribute('title');
  else if (e.title !== detail) e.title = detail;
}
