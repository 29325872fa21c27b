/**
 * The three-axis chart "step against slope" in German (issue 30): captions, axis titles, legends and
 * notes in the terms of de.ts (waagerechter Bahnabstand, Z-Zustellung, Zeilen, Z-Ebenen, Neigung);
 * symbols kept. Part of de.ts.
 */
import type { SlopeWords } from './catalogue';

/** Why a constant step leaves no cusp, by the core's code (core/threeAxis/errors.ts). */
const REFUSAL_WORDS: Readonly<Record<string, string>> = {
  'beyond-step': 'so weit auseinander liegende Bahnen hinterlassen eine Wand statt eines Kamms',
  'shank-cuts': 'der Schaft des Werkzeugs, nicht seine Ecke, würde den Kamm bilden',
  'flank-wall': 'die Flanke steigt zur Wand an, bevor die Bahnen sich treffen',
  'wall-only': 'die Seite steigt am Kontaktpunkt senkrecht an: bei keinem Abstand ein Kamm',
  'past-surface': 'die nächste Bahn läge außerhalb der nutzbaren Fläche',
  'needs-slope': 'auf ebenem Boden hat eine Z-Zustellung keinen Sinn',
  gouging: 'das Werkzeug würde die Fläche verletzen',
};

export const DE_SLOPE: SlopeWords = {
  stepTitle: (u, h, slope) =>
    `Programmierter Abstand [${u}] über der Neigung [°] für h = ${h} (R, Rcr fest; gestrichelt: aktuelle Neigung = ${slope})`,
  cuspTitle: (u, constant, h) => `Rautiefe [${u}] eines festen ${constant} über der Neigung [°] (gepunktet: h = ${h})`,
  slopeAxis: 'Flächenneigung alpha [°]',
  stepAxis: (u) => `Abstand [${u}]`,
  scallopAxis: (u) => `Rautiefe [${u}]`,
  description: (title, sentence) => `${title}. ${sentence}`,
  legendHead: (slope) => `bei Neigung = ${slope}:`,
  strategy: (passes, psi) => (passes === 'raster' ? `Lxy (Zeilen, psi = ${psi})` : 'dz (Z-Ebenen)'),
  floor: 'Abstand Lxy0 auf ebenem Boden',
  scallopOf: (constant) => `Rautiefe bei ${constant}`,
  none: 'keine',
  gap: 'h auf oder über der Grenze',
  noStepAbove: (slope, h, revolution) =>
    `Kein Abstand über ${slope}: dort erreicht h = ${h} die größte Rautiefe, die das Werkzeug hinterlassen kann (Flanke oder Schaft${revolution ? ' oder das Ende der Fläche' : ''}); 90° ist eine senkrechte Wand.`,
  crossing: (crossing, psi, h, both, revolution) => {
    const raster = `Zeilen unter psi = ${psi}`;
    const where = revolution ? ' (auf einer Ebene dieser Neigung)' : '';
    if (crossing === null)
      return `Z-Ebenen und ${raster} schneiden sich bei einer Rautiefe von ${h} nicht${where}: ${raster} ergeben bei jeder Neigung, wo beide gelten, den größeren Abstand.`;
    return `Über ${crossing} ergeben Z-Ebenen bei gleicher Rautiefe von ${h} einen größeren Abstand als ${raster}, darunter ${raster}${both === null ? '' : ` (beide ${both} bei ${crossing})`}${where}.`;
  },
  refusal: (step, from, to, code) =>
    `Kein Kamm für den festen Abstand ${step} ${to === null ? `bei etwa ${from}` : `von etwa ${from} bis ${to}`}: ${REFUSAL_WORDS[code] ?? 'der Rechner lehnt ihn ab'}.`,
};
