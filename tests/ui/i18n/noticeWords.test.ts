/**
 * The notices' words (issue 30, i18n/noticeWords.ts): each sentence the page writes into its notice
 * box in English (messages.ts, read from its own functions here, not copied) is found again, put
 * into Japanese and German, and its English part (a reason not known; the link's details when not
 * read back) kept whole; an exception's own text goes to the hover title, out of the sentence. Compiled with the page (DOM types: messages.ts's Notice).
 */
import { describe, expect, it } from 'vitest';
import { catalogue as de } from '../../../src/ui/i18n/de';
import { catalogue as ja } from '../../../src/ui/i18n/ja';
import { noticeParts } from '../../../src/ui/i18n/noticeWords';
import { reasonIn } from '../../../src/ui/i18n/workerReason';
import { linkNotice, restartMessage } from '../../../src/ui/messages';
import { MAX_CONSECUTIVE_RESTARTS } from '../../../src/worker/client';

describe("the notices' words (language.ts noticeParts, from messages.ts's English)", () => {
  const reason = 'it stopped answering (30 s)';
  for (const [name, c] of [
    ['ja', ja],
    ['de', de],
  ] as const)
    it(`${name}: a worker restarted or stopped, link values replaced; the English part kept whole`, () => {
      for (const who of ['results', 'views'] as const)
        for (const gaveUp of [false, true]) {
          const english = restartMessage(who, { reason, gaveUp, request: null });
          const parts = noticeParts(english, c);
          expect(parts, english).not.toBeNull();
          expect(parts?.[1]).toBe(reason);
          expect(parts?.[3]).toBe('');
          expect(parts?.join('')).not.toMatch(/solver|restart|stale|input/i);
          if (gaveUp) expect(parts?.[0]).toContain(String(MAX_CONSECUTIVE_RESTARTS));
        }
      // A reason client.ts writes is in the language, nothing kept English: an exception's own text
      // is the box's hover title (the fourth part), not in the sentence.
      const threw = noticeParts(
        restartMessage('views', {
          reason: 'the solver threw (TypeError: x is undefined)',
          gaveUp: false,
          request: null,
        }),
        c,
      );
      expect(threw?.[1]).toBe('');
      expect(threw?.[3]).toBe('TypeError: x is undefined');
      const sentence = threw?.slice(0, 3).join('') ?? '';
      expect(sentence).toContain(reasonIn('the solver threw (TypeError: x is undefined)', c));
      expect(sentence).not.toMatch(/solver|threw|TypeError|undefined/);
      const link = linkNotice(['Rcr="abc" in the link is not a number; using the default 1.']);
      // The link's details in the language (linkNotices.ts), its parameter and value kept; nothing left English.
      expect(noticeParts(link, c)?.[1]).toBe('');
      expect(noticeParts(link, c)?.[0]).toContain('Rcr="abc"');
      expect(noticeParts('Something else.', c)).toBeNull();
    });
});
