/**
 * The notices' words (issue 30): the sentences the page writes into its notice box in English
 * (messages.ts: a worker restarted or stopped, link values replaced), each read back as the words
 * before, the part kept in English (a worker's reason not known, the link's values named by their
 * parameters), the words after, in a catalogue's language, and an exception's text for the box's
 * hover title. Pure (no DOM): language.ts writes them.
 */
import type { Catalogue } from './catalogue';
import { linkDetailsIn } from './linkNotices';
import { reasonParts } from './workerReason';

/**
 * A restart's sentence around its reason: the reason in the language (workerReason.ts), its detail
 * (an exception's text) for the hover title; a reason not known kept English whole.
 */
function aroundReason([before, after]: readonly [string, string], reason: string, c: Catalogue): NoticeParts {
  const parts = reasonParts(reason, c);
  return parts === null ? [before, reason, after, ''] : [`${before}${parts[0]}${after}`, '', '', parts[1]];
}

/** A notice in the language: the words before, the part kept English, the words after, and an exception's text for its hover title (or ''). */
export type NoticeParts = readonly [string, string, string, string];

/** The notice's sentences the page writes (messages.ts), the parts in between kept in English. */
const NOTICES: ReadonlyArray<{
  readonly english: RegExp;
  readonly words: (m: RegExpExecArray, c: Catalogue) => NoticeParts;
}> = [
  {
    english:
      /^(The solver|The teaching views' solver) stopped after (\d+) restarts in a row \((.*)\): (?:the numbers shown are|the views are) out of date, marked stale\. Change any input to try again\.$/s,
    words: (m, c) => {
      return aroundReason(c.said.restarted(m[1] === 'The solver' ? 'results' : 'views', m[2] ?? ''), m[3] ?? '', c);
    },
  },
  {
    english: /^(The solver|The teaching views' solver) was restarted: (.*)\. Your last request was sent again\.$/s,
    words: (m, c) => {
      return aroundReason(c.said.restarted(m[1] === 'The solver' ? 'results' : 'views', null), m[2] ?? '', c);
    },
  },
  {
    // The details in the language when each is read back (linkNotices.ts), else kept English whole.
    english: /^Some link values were replaced: (.*)$/s,
    words: (m, c) => {
      const local = linkDetailsIn(m[1] ?? '', c);
      return local === null
        ? [c.said.linkReplaced, m[1] ?? '', '', '']
        : [`${c.said.linkReplaced}${local}`, '', '', ''];
    },
  },
];

/** A notice's English (messages.ts) as NoticeParts; null: not one. */
export function noticeParts(english: string, words: Catalogue): NoticeParts | null {
  for (const notice of NOTICES) {
    const m = notice.english.exec(english);
    if (m !== null) return notice.words(m, words);
  }
  return null;
}
