/**
 * The notices' words (issue 30, i18n/noticeWords.ts): each sentence the page writes into its notice
 * box in English (messages.ts, read from its own functions here, not copied) is found again, put
 * into Japanese and German, and its English part (an exception's text in the worker's reason; the
 * link's details when not read back) kept whole. Compiled with the page (DOM types: messages.ts's Notice).
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
          expect(parts?.join('')).not.toMatch(/solver|restart|stale|input/i);
          if (gaveUp) expect(parts?.[0]).toContain(String(MAX_CONSECUTIVE_RESTARTS));
        }
      // A reason client.ts writes is in the language, only an exception's own text kept English.
      const threw = noticeParts(
        restartMessage('views', {
          reason: 'the solver threw (TypeError: x is undefined)',
          gaveUp: false,
          request: null,
        }),
        c,
      );
      expect(threw?.[1]).toBe('TypeError: x is undefined');
      expect(threw?.join('')).toContain(reasonIn('the solver threw (TypeError: x is undefined)', c));
      expect(threw?.join('')).not.toMatch(/solver|threw/);
      const link = linkNotice(['Rcr="abc" in the link is not a number; using the default 1.']);
      // The link's details in the language (linkNotices.ts), its parameter and value kept; nothing left English.
      expect(noticeParts(link, c)?.[1]).toBe('');
      expect(noticeParts(link, c)?.[0]).toContain('Rcr="abc"');
      expect(noticeParts('Something else.', c)).toBeNull();
    });
});
