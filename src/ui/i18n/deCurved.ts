/**
 * A doubly curved point's refusals in German (issue 30), worded from the worker's data by
 * curvedText.ts in the terms of de.ts and the glossary (verletzen, Flanke, Schaft, Kamm). Part of de.ts.
 */
import type { CurvedWords } from './catalogue';

const gotOf = (g: string) => `(eingegeben: ${g})`;
const gouged = 'verletzt das Werkzeug die Fläche abseits des Kontakts';

export const DE_CURVED: CurvedWords = {
  beyondMax: (l, max, g) =>
    `${l} muss an diesem Punkt unter ${max} liegen ${gotOf(g)}: so weit auseinander liegende Bahnen hinterlassen eine Wand.`,
  aboveLimit: (l, limit, g, shank, right) =>
    `${l} muss an diesem Punkt unter ${limit} liegen ${gotOf(g)}: darüber ${
      shank
        ? `würde der Schaft (${right ? 'rechts' : 'links'}), nicht der Eckenradius, den Kamm bilden`
        : `hinterlässt die ${right ? 'rechte' : 'linke'} Flanke eine Wand statt eines Kamms`
    }.`,
  outOfRange: (l, from, to, g) =>
    `${l} muss ein Radius von ${from} bis ${to} sein ${gotOf(g)}; für keine Krümmung „gerade“ wählen.`,
  held: (other, r) => (r === null ? `bei geradem ${other}` : `bei festem ${other} = ${r}`),
  gouging: (kind, l, r, held, g) =>
    kind === 'concave-at-least'
      ? `${l} muss konkav mindestens ${r} betragen, ${held} ${gotOf(g)}: bei einem engeren ${gouged}.`
      : kind === 'convex-at-most'
        ? `${l} muss konvex sein und höchstens ${r} betragen, ${held} ${gotOf(g)}: bei einem flacheren ${gouged}.`
        : kind === 'not-concave'
          ? `${l} muss konvex oder gerade sein, ${held} ${gotOf(g)}: bei jedem konkaven verletzt das Werkzeug die Fläche.`
          : `${l}: das Werkzeug verletzt die Fläche bei jedem Radius, ${held} ${gotOf(g)}; den anderen Radius, das Werkzeug oder seine Anstellung ändern.`,
  missing: (l) => `${l} fehlt: einen Radius eingeben oder „gerade“ wählen.`,
  notNumber: (l, g) => `${l} muss eine Zahl sein ${gotOf(`"${g}"`)}.`,
  positive: (l, g) => `${l} muss eine positive Zahl sein: konvex oder konkav wird daneben gewählt ${gotOf(g)}.`,
  atPoint: ['auf dieser Fläche', 'an diesem Punkt'],
};
