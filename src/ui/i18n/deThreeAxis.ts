/**
 * The three-axis errors in German (issue 30): one sentence per error code of the three-axis
 * validation and solvers (core/threeAxis), naming the constraint and its limit in the user's unit,
 * as the English ones do. Part of de.ts.
 */
import type { Catalogue, ThreeAxisText } from './catalogue';

const gotOf = (t: ThreeAxisText) => `(eingegeben: ${t.got})`;

function outOfRange(t: ThreeAxisText): string {
  switch (t.e.field) {
    case 'R':
      return `${t.label} muss zwischen ${t.toolRange[0]} und ${t.toolRange[1]} liegen ${gotOf(t)}.`;
    case 'Rcr':
      return `${t.label} muss zwischen 0 und dem Werkzeugradius R${t.limit === '' ? '' : ` = ${t.limit}`} liegen ${gotOf(t)}; Rcr = R ist ein Kugelfräser.`;
    case 'slope':
      return `${t.label} muss ${t.waterline ? 'über 0° und höchstens 90° betragen' : 'zwischen 0° und 90° liegen'} ${gotOf(t)}.`;
    case 'rasterAngle':
      return `${t.label} muss zwischen 0° und 90° zur Falllinie liegen ${gotOf(t)}.`;
    case 'feedRadius':
    case 'crossRadius':
      return `${t.label} muss ein Radius von ${t.radiusRange[0]} bis ${t.radiusRange[1]} sein, negativ für konkav, oder leer für eine Gerade ${gotOf(t)}.`;
    case 'stepDown':
      if (!t.waterline)
        return `${t.label} ist die Zustellung von Z-Ebenen: Zeilen erhalten einen waagerechten Bahnabstand Lxy.`;
      return `${t.label} muss mindestens ${t.minLength} betragen ${gotOf(t)}.`;
    default:
      return t.isLength
        ? `${t.label} muss mindestens ${t.minLength} betragen ${gotOf(t)}.`
        : `${t.label} liegt außerhalb des Bereichs ${gotOf(t)}.`;
  }
}

export const DE_THREE_AXIS: Catalogue['threeAxis'] = {
  'out-of-range': outOfRange,
  'too-small': (t) => `${t.label} muss mindestens ${t.limit} betragen ${gotOf(t)}.`,
  'vertical-wall': (t) =>
    `${t.label} von 90° ist eine senkrechte Wand: die Seite des senkrechten Werkzeugs schneidet sie eben, also entsteht bei keinem Abstand ein Kamm und es gibt keinen Abstand zu berechnen.`,
  'needs-slope': (t) =>
    `${t.label} muss für Z-Ebenen über 0° liegen: auf ebenem Boden liegen alle Ebenen gleich hoch, es gibt keine Z-Zustellung.`,
  'shank-cuts': (t) =>
    t.noLimit
      ? `${t.label} ist bei dieser Neigung nicht zu beantworten ${gotOf(t)}: bei jedem Abstand bildet der Schaft (die zylindrische Werkzeugseite), nicht die Ecke, den Kamm und hinterlässt eine Stufe statt eines Kamms.`
      : `${t.label} muss bei dieser Neigung unter ${t.limit} liegen ${gotOf(t)}; darüber bildet der Schaft (die zylindrische Werkzeugseite), nicht die Ecke, den Kamm.`,
  'flank-wall': (t) =>
    t.noLimit
      ? `${t.label} ist bei keiner Neigung zu beantworten ${gotOf(t)}: eine Flanke oder der Schaft hinterlässt eine Wand statt eines Kamms.`
      : `${t.label} muss bei dieser Neigung unter ${t.limit} liegen ${gotOf(t)}; ab dort hinterlässt eine Flanke des Profils eine Wand statt eines Kamms.`,
  'wall-only': (t) =>
    `${t.label} ist mit einem Schaftfräser (Rcr = 0) hier nicht zu beantworten: die Werkzeugseite steigt am Kontaktpunkt senkrecht an und schneidet bei jedem Abstand eine Stufe statt eines Kamms. Einen Eckenradius nehmen.`,
  'beyond-step': (t) =>
    `${t.label} muss unter ${t.limit} liegen ${gotOf(t)}, dem größten Abstand bei dieser Neigung, der noch einen Kamm hinterlässt; darüber bleibt zwischen benachbarten Bahnen eine Wand (auf ebenem Boden ein ungeschnittener Grat).`,
  'past-surface': (t) =>
    t.e.limit === null
      ? `${t.label} ist hier zu groß ${gotOf(t)}: die Bahn darüber läge jenseits der Drehachse.`
      : t.noLimit
        ? `${t.label} ist hier nicht zu beantworten ${gotOf(t)}: die nächste Bahn läge außerhalb des nutzbaren Teils der Fläche (Überhang, Boden, jenseits der Drehachse).`
        : `${t.label} muss hier unter ${t.limit} liegen ${gotOf(t)}; darüber läge die nächste Bahn außerhalb des nutzbaren Teils der Fläche (Überhang, Boden, jenseits der Drehachse).`,
  gouging: (t) =>
    // The core's one gouging error with no radius to name: both radii together (waterlineErrors.ts).
    /together/.test(t.e.message)
      ? `${t.label} und der Radius längs Rf sind zusammen zu eng für dieses Werkzeug: keiner allein, wie groß auch immer, verhindert, dass das Werkzeug die Fläche abseits des Kontaktpunkts verletzt.`
      : t.limit === ''
        ? `${t.label} ist zu eng für dieses Werkzeug ${gotOf(t)}: nur eine Gerade (kein Radius) verhindert, dass es die Fläche verletzt.`
        : `${t.label} ist zu eng für dieses Werkzeug ${gotOf(t)}: der Radius muss dem Betrag nach mindestens ${t.limit.replace(/^-/, '')} sein; ein engerer wird verletzt (das Werkzeug reicht abseits des Kontaktpunkts in die Fläche).`,
  missing: (t) => `${t.label} fehlt.`,
  'not-a-number': (t) => `${t.label} muss eine endliche Zahl sein ${gotOf(t)}.`,
  'not-a-strategy': (t) => `${t.label} muss Zeilen oder Z-Ebenen sein ${gotOf(t)}.`,
  'not-with': (t) =>
    t.e.field === 'horizontalStep'
      ? `${t.label} ist der Abstand von Zeilen: Z-Ebenen werden mit ihrer Z-Zustellung dz programmiert.`
      : t.e.field === 'stepDown'
        ? `${t.label} ist die Zustellung von Z-Ebenen: Zeilen werden mit ihrem waagerechten Bahnabstand Lxy programmiert.`
        : `${t.label} passt nicht zu dieser Bahnstrategie ${gotOf(t)}.`,
};
