/**
 * The link's notices' details in a catalogue's language (issue 30): each sentence the page writes
 * in English when it replaces a link's value (state.ts, surfaceState.ts, fieldText.ts choice,
 * linkRepeats.ts, themeChoice.ts, present.ts, app.ts's view=, langChoice.ts's lang=) is read back
 * from its English, its parameters' names and the values quoted kept, and worded anew. Details that
 * are not all read back stay English whole (the notice keeps them in a part marked so). Pure (no
 * DOM): noticeWords.ts uses it. Loaded with the language code.
 */
import type { Catalogue, LinkNoticeWords } from './catalogue';

/** The words of a list of values ("mm or in", "light, dark or auto"): the values alone. */
const values = (list: string) => list.split(/, | or /);

/** Each detail's English (one sentence, its final full stop included) and its words in a language. */
const DETAILS: ReadonlyArray<readonly [RegExp, (m: RegExpExecArray, w: LinkNoticeWords) => string]> = [
  [/^(\S+) is missing from the link; using the default (\S+)\./, (m, w) => w.missing(m[1] ?? '', m[2] ?? '')],
  [
    /^(\S+="[^"]*") in the link is not a number; (left empty|using the default (\S+)|using a plane \(a cylinder's radius defaults to (\S+)\)|using a straight line \(no curvature\))\./,
    (m, w) =>
      w.notNumber(
        m[1] ?? '',
        m[2] === 'left empty'
          ? { kind: 'empty' }
          : m[3] !== undefined
            ? { kind: 'default', value: m[3] }
            : m[4] !== undefined
              ? { kind: 'plane', value: m[4] }
              : { kind: 'straight' },
      ),
  ],
  [/^(\S+) is in the link: (\S+) and (\S+) are not used\./, (m, w) => w.notUsed(m[1] ?? '', [m[2] ?? '', m[3] ?? ''])],
  [
    /^both (\S+) and (\S+) are in the link; using (\S+="[^"]*"|\S+=\S*) \(\S+ ignored\)\./,
    (m, w) => w.both(m[1] ?? '', m[2] ?? '', m[3] ?? ''),
  ],
  [
    /^(\S+) and (\S+) or (\S+) are both in the link; using \S+ and \S+ \(a link gives the surface one way\)\./,
    (m, w) => w.surfaceBoth(m[1] ?? '', m[2] ?? '', m[3] ?? ''),
  ],
  [
    /^(\S+) is in the link (\d+) times; using the first, (\S+="[^"]*") \((.*?)(?: and (\d+) more)? ignored\)\./,
    (m, w) => w.repeated(m[1] ?? '', Number(m[2]), m[3] ?? '', (m[4] ?? '').split(', '), Number(m[5] ?? 0)),
  ],
  [
    /^(\S+="[^"]*") is not (.+?); (using (\S+)|following the system's colour scheme|presentation mode is off|showing (\S+))\./,
    (m, w) =>
      w.notOneOf(
        m[1] ?? '',
        values(m[2] ?? ''),
        m[4] !== undefined
          ? { kind: 'using', value: m[4] }
          : m[5] !== undefined
            ? { kind: 'showing', value: m[5] }
            : { kind: m[3]?.startsWith('following') ? 'system' : 'presentOff' },
      ),
  ],
  [/^(view="[^"]*") is not one of (.+)\./, (m, w) => w.notOneOf(m[1] ?? '', (m[2] ?? '').split(', '), null)],
];

/** A link notice's details (the sentences after "Some link values were replaced: ") in `c`'s language, or null when one is not read back. */
export function linkDetailsIn(english: string, c: Pick<Catalogue, 'linkNotices'>): string | null {
  const out: string[] = [];
  let rest = english;
  while (rest !== '') {
    let worded: string | null = null;
    for (const [pattern, words] of DETAILS) {
      const m = pattern.exec(rest);
      if (m === null || (rest.length > m[0].length && rest[m[0].length] !== ' ')) continue;
      worded = words(m, c.linkNotices);
      rest = rest.slice(m[0].length).trimStart();
      break;
    }
    if (worded === null) return null;
    out.push(worded);
  }
  return out.join(c.linkNotices.separator);
}
