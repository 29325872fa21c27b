/**
 * A worker's reason for a restart in Japanese and German (issue 30, i18n/workerReason.ts): every
 * reason worker/client.ts writes (read from its source's restart calls, not copied) is recognised,
 * worded in each language as a sentence of its own, an exception's own text apart whole (for a hover
 * title); English and a reason not known stay as written (the notice around it: noticeWords.test.ts).
 */
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { catalogue as de } from '../../../src/ui/i18n/de';
import { catalogue as ja } from '../../../src/ui/i18n/ja';
import { reasonDetail, reasonIn, reasonParts } from '../../../src/ui/i18n/workerReason';

const CLIENT = readFileSync(fileURLToPath(new URL('../../../src/worker/client.ts', import.meta.url)), 'utf8');

/** client.ts's reasons: each restart call's string literals and templates, `${...}` standing for an exception's text. */
const REASONS = [...CLIENT.matchAll(/this\.restart\(([^;]*)\)/g)].flatMap((m) =>
  [...(m[1] ?? '').matchAll(/`(the solver[^`]*)`|'(the solver[^']*)'/g)].map((r) =>
    (r[1] ?? r[2] ?? '').replace(/\$\{[^}]*\}/g, 'TypeError: x is undefined'),
  ),
);

describe("a worker's reason for a restart (workerReason.ts, from worker/client.ts's English)", () => {
  it("reads client.ts's four reasons", () => {
    expect(REASONS).toHaveLength(4);
  });

  for (const [name, c] of [
    ['ja', ja],
    ['de', de],
  ] as const)
    it(`${name}: each reason in the language, an exception's text kept`, () => {
      const worded = REASONS.map((english) => {
        const parts = reasonParts(english, c);
        expect(parts, english).not.toBeNull();
        // The detail is the exception's text, whole, or none: for the hover title, not in the sentence.
        const detail = english.includes('TypeError') ? 'TypeError: x is undefined' : '';
        expect(parts?.[1]).toBe(detail);
        expect(reasonDetail(english, c)).toBe(detail);
        const text = reasonIn(english, c);
        expect(text).not.toMatch(/solver|failed|threw|load|answering|the|TypeError|undefined/i);
        return text;
      });
      expect(new Set(worded).size).toBe(REASONS.length);
      // A reason not known stays English (kept whole in the notice).
      expect(reasonIn('it stopped answering (30 s)', c)).toBe('it stopped answering (30 s)');
    });

  it('English: the reason as written, no detail apart', () => {
    for (const english of REASONS) {
      expect(reasonIn(english, null)).toBe(english);
      expect(reasonDetail(english, null)).toBe('');
    }
  });
});
