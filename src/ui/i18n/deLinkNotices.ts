/**
 * A link notice's details in German (issue 30; read back by linkNotices.ts): the parameters' names
 * and the values quoted kept as the link gives them. Part of de.ts.
 */
import type { LinkNoticeWords } from './catalogue';

/** Values as a German list: "a, b oder c". */
const list = (values: readonly string[]) =>
  values.length < 2 ? values.join('') : `${values.slice(0, -1).join(', ')} oder ${values.at(-1)}`;

export const DE_LINK_NOTICES: LinkNoticeWords = {
  separator: ' ',
  missing: (name, fallback) => `${name} fehlt im Link; der Standardwert ${fallback} wird verwendet.`,
  notNumber: (quoted, then) =>
    `${quoted} im Link ist keine Zahl; ${
      then.kind === 'empty'
        ? 'das Feld bleibt leer.'
        : then.kind === 'default'
          ? `der Standardwert ${then.value} wird verwendet.`
          : then.kind === 'plane'
            ? `es wird eine Ebene verwendet (der Radius eines Zylinders ist standardmäßig ${then.value}).`
            : 'es wird eine Gerade verwendet (keine Krümmung).'
    }`,
  notUsed: (given, [a, b]) => `${given} steht im Link: ${a} und ${b} werden nicht verwendet.`,
  both: (a, b, used) => `${a} und ${b} stehen beide im Link; ${used} wird verwendet (${b} ignoriert).`,
  surfaceBoth: (radius, rf, rc) =>
    `${radius} und ${rf} oder ${rc} stehen beide im Link; ${rf} und ${rc} werden verwendet (ein Link gibt die Fläche nur auf eine Weise an).`,
  repeated: (name, times, first, ignored, more) =>
    `${name} steht ${times}-mal im Link; der erste Wert, ${first}, wird verwendet (${ignored.join(', ')}${more > 0 ? ` und ${more} weitere` : ''} ignoriert).`,
  notOneOf: (quoted, values, then) =>
    `${quoted} im Link ist nicht ${list(values)}${
      then === null
        ? '.'
        : then.kind === 'using'
          ? `; ${then.value} wird verwendet.`
          : then.kind === 'showing'
            ? `; angezeigt wird ${then.value}.`
            : then.kind === 'system'
              ? '; das Farbschema des Systems wird verwendet.'
              : '; der Präsentationsmodus ist aus.'
    }`,
};
