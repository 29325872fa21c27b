/**
 * The input errors in German (issue 30): one sentence per error code, naming the constraint and
 * its limit in the user's unit with a decimal comma, as the English ones do
 * (core/input/inputErrors.ts). Part of de.ts.
 */
import { MAX_SURFACE_RADIUS_MM, MIN_SURFACE_RADIUS_MM } from '../../core/input/limits';
import type { Catalogue } from './catalogue';
import { type ErrorText, radiusGougingParts } from './errorText';

const gotOf = (t: ErrorText) => `(eingegeben: ${t.got})`;
const side = (s: 'right' | 'left' | undefined) => (s === 'left' ? 'linken' : 'rechten');

/** A radius-gouging error (a doubly curved point): what this radius must be, or the other. */
function radiusGouging(t: ErrorText): string {
  const { me, them, held: heldRadius, mag, kind, other: o } = radiusGougingParts(t);
  const held = heldRadius === null ? `${them} gerade` : `${them} = ${heldRadius}`;
  const need =
    kind === 'concave-at-least'
      ? `${t.label}: ein konkaves ${me} muss für dieses Werkzeug und diese Anstellung bei festem ${held} mindestens ${mag} betragen ${gotOf(t)}`
      : kind === 'convex-at-most'
        ? `${t.label} muss für dieses Werkzeug und diese Anstellung bei festem ${held} konvex und höchstens ${mag} sein ${gotOf(t)}`
        : kind === 'not-concave'
          ? `${t.label} muss für dieses Werkzeug und diese Anstellung bei festem ${held} gerade oder konvex sein ${gotOf(t)}: jedes konkave ${me} wird verletzt`
          : `Dieses Werkzeug verletzt den Punkt bei festem ${held} mit jedem Radius ${me} ${gotOf(t)}`;
  const other =
    o?.kind === 'concave-at-least' && o.radius !== null
      ? `; oder, bei festem ${me}, ein konkaves ${them} von mindestens ${o.radius}`
      : o?.kind === 'convex-at-most' && o.radius !== null
        ? `; oder, bei festem ${me}, ein konvexes ${them} von höchstens ${o.radius}`
        : o?.kind === 'not-concave'
          ? `; oder, bei festem ${me}, ein gerades oder konvexes ${them}`
          : o?.kind === 'none'
            ? `; bei festem ${me} hilft kein ${them}`
            : '';
  return `${need}${other} (das Werkzeug reicht abseits des Kontaktpunkts unter die Fläche).`;
}

/** The shank's lean and what would help, for a shank-gouging error. */
function shankHelp(t: ErrorText): { lean: string; help: string } {
  const lean = t.angle(t.e.shankLean?.leanDeg ?? 45);
  const help =
    t.e.shankLean?.axis === 'cross'
      ? 'Weniger Anstellwinkel hilft (längs der Zylinderachse gesehen neigt sich der Schaft um den Anstellwinkel; der Kippwinkel spielt keine Rolle).'
      : 'Weniger Kipp- oder Anstellwinkel hilft.';
  return { lean, help };
}

export const DE_ERRORS: Catalogue['errors'] = {
  missing: (t) => `${t.label} fehlt: bitte eine Zahl eingeben.`,
  'not-a-number': (t) => `${t.label} muss eine Zahl sein (eingegeben: „${t.got}“).`,
  'not-finite': (t) => `${t.label} muss eine endliche Zahl sein ${gotOf(t)}.`,
  'not-positive': (t) => `${t.label} muss größer als 0 ${t.unit} sein ${gotOf(t)}.`,
  negative: (t) => `${t.label} muss 0 ${t.unit} oder mehr betragen ${gotOf(t)}.`,
  'too-small': (t) => `${t.label} muss mindestens ${t.limit} betragen ${gotOf(t)}.`,
  'too-large': (t) => `${t.label} darf höchstens ${t.limit} betragen ${gotOf(t)}.`,
  'out-of-range': (t) =>
    t.e.field === 'surfaceRadius' || t.e.field === 'feedRadius' || t.e.field === 'crossRadius'
      ? `${t.label} muss ein Radius von ${t.length(MIN_SURFACE_RADIUS_MM)} bis ${t.length(MAX_SURFACE_RADIUS_MM)} sein ${gotOf(t)}.`
      : t.e.field === 'rho'
        ? `${t.label} muss mindestens 0 und unter 90 Grad liegen ${gotOf(t)}.`
        : `${t.label} muss über -90 und unter 90 Grad liegen ${gotOf(t)}.`,
  'not-a-pattern': (t) =>
    `${t.label} muss „in einer Richtung“ (one-way) oder „Zickzack“ (zigzag) sein (eingegeben: „${t.got}“).`,
  'not-an-axis': (t) => `${t.label} muss „Vorschub“ (feed) oder „quer“ (cross) sein (eingegeben: „${t.got}“).`,
  gouging: (t) =>
    t.e.limit === undefined || !Number.isFinite(t.e.limit)
      ? `Dieses Werkzeug verletzt mit dieser Achse und Anstellung einen konkaven Zylinder jedes Radius ${gotOf(t)}: ein ebener Boden ohne Anstellwinkel reicht beiderseits des Kontaktpunkts unter die Fläche. Anstell- oder Kippwinkel geben oder einen Kugelfräser nehmen.`
      : `${t.label}: ein konkaver Zylinder braucht für dieses Werkzeug und diese Anstellung einen Radius von mindestens ${t.length(Math.abs(t.e.limit))} ${gotOf(t)}; ein engerer wird verletzt (das Werkzeug reicht abseits des Kontaktpunkts unter die Fläche).`,
  'shank-gouging': (t) => {
    const { lean, help } = shankHelp(t);
    return t.e.limit === undefined || !Number.isFinite(t.e.limit)
      ? `Der Schaft dieses Werkzeugs kreuzt mit dieser Achse und Anstellung die Wand eines konkaven Zylinders jedes Radius ${gotOf(t)}: längs der Zylinderachse gesehen neigt er sich ${lean} Grad gegen die Flächennormale, und ab 45 Grad trifft er die Wand unterhalb der Achshöhe. ${help}`
      : `${t.label}: ein konkaver Zylinder braucht für dieses Werkzeug und diese Anstellung einen Radius von mindestens ${t.length(Math.abs(t.e.limit))} ${gotOf(t)}; in einem engeren kreuzt der Schaft (die zylindrische Seite des Werkzeugs, längs der Zylinderachse ${lean} Grad gegen die Flächennormale geneigt) die Fläche unterhalb der Achshöhe. ${help}`;
  },
  'corner-exceeds-radius': (t) =>
    t.diameter
      ? `${t.label} darf höchstens D/2 = ${t.limit} betragen ${gotOf(t)}; Rcr = D/2 ist ein Kugelfräser.`
      : `${t.label} darf den Werkzeugradius R = ${t.limit} nicht überschreiten ${gotOf(t)}; Rcr = R ist ein Kugelfräser.`,
  'flank-wall': (t) =>
    t.e.side === undefined
      ? `${t.label} muss unter der vollen Profilhöhe (R - Rcr) sin(rho) + Rcr = ${t.limit} liegen ${gotOf(t)}; ab dort hinterlässt die Werkzeugflanke eine Wand statt eines Kamms.`
      : `${t.label} muss unter ${t.limit} liegen, der Höhe der breitesten Stelle der ${side(t.e.side)} Flanke ${gotOf(t)}; ab dort hinterlässt diese Flanke eine Wand statt eines Kamms.`,
  'shank-cuts': (t) =>
    `${t.label} muss unter ${t.limit} liegen ${gotOf(t)}: darüber würde der Schaft (die zylindrische Seite des Werkzeugs, mit dem Kippwinkel zur ${side(t.e.side)} Seite geneigt) die Fläche schneiden.`,
  'beyond-diameter': (t) =>
    `${t.label} muss unter dem Werkzeugdurchmesser ${t.diameter ? 'D' : '2R'} = ${t.limit} liegen ${gotOf(t)}; ab dort hinterlassen benachbarte Bahnen eine Wand.`,
  'beyond-interval': (t) =>
    `${t.label} muss unter ${t.limit} liegen ${gotOf(t)}, dem größten Bahnabstand, den diese Flanken zulassen; ab dort hinterlassen benachbarte Bahnen eine Wand statt eines Kamms.`,
  'beyond-max-ra': (t) =>
    t.e.limit === undefined || !(t.e.limit > 0)
      ? `${t.label} ist nicht erreichbar ${gotOf(t)}: dieses Werkzeug hinterlässt in dieser Anstellung keinen Kamm (ein ebener Boden liegt auf der Fläche), also Ra = 0 bei jedem Bahnabstand bis zum Durchmesser.`
      : `${t.label} muss unter ${t.limit} liegen ${gotOf(t)}, dem größten Ra, das dieses Werkzeug mit dieser Anstellung und Bahnfolge auf dieser Fläche hinterlässt; weiter auseinander liegende Bahnen hinterlassen eine Wand statt eines Kamms.`,
  'wall-only': (t) =>
    `${t.label} lässt sich nicht beantworten ${gotOf(t)}: in dieser Anstellung schneidet das Werkzeug bei jedem Bahnabstand eine Stufe (eine Flanke oder der Schaft steigt senkrecht vom Kontaktpunkt auf, wie bei einem gekippten Schaftfräser), es entsteht kein Kamm. Einen Eckenradius, einen Anstellwinkel oder weniger Kippwinkel wählen.`,
  'radius-gouging': radiusGouging,
};
