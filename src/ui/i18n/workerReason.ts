/**
 * A worker's reason for a restart (issue 30), as worker/client.ts writes it in English ("the solver
 * threw (TypeError: ...)", "the solver stopped answering"...), read back and worded in a catalogue's
 * language; an exception's own text (the detail in parentheses) is kept as it is. Pure (no DOM):
 * noticeWords.ts, finishPanel.ts and targetSaPanel.ts use it. Loaded with them, on first use.
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
 * A reason in `c`'s language as the words before its detail, the detail (an exception's text, kept
 * as it is; '' when none) and the words after; null when `english` is none of client.ts's reasons.
 */
export function reasonParts(english: string, c: Pick<Catalogue, 'said'>): readonly [string, string, string] | null {
  for (const [pattern, kind] of REASONS) {
    const m = pattern.exec(english);
    if (m === null) continue;
    const [before, after] = c.said.reason(kind);
    return [before, m[1] ?? '', after];
  }
  return null;
}

/** A reason in `c`'s language (null: English, as written); one not known is kept as it is. */
export function reasonIn(english: string, c: Pick<Catalogue, 'said'> | null): string {
  const parts = c === null ? null : reasonParts(english, c);
  return parts === null ? english : parts.join('');
}
