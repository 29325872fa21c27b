/**
 * The step-through of the paper's 3D procedure in German (issue 30): its 31 steps' captions (the
 * boxes of the paper's Figure 1 as Abb. 1, Kasten), the counter, the gauge, the buttons and the
 * notes, in the terms of de.ts and the README's glossary (Flanke, Schnitt, Ringwinkel,
 * h-Pseudoebene, einziger Kontakt); the paper's symbols (L, h, Rcr, d_s, gamma, P_hp, wR, wL) kept.
 * Part of de.ts.
 */
import type { StepperWords } from './teachWords';

export const DE_STEPPER: StepperWords = {
  step: (k, n) => `Schritt ${k} von ${n}. `,
  side: (flank) => (flank === 'right' ? 'Rechte Flanke (+Y)' : 'Linke Flanke (-Y)'),
  merged: (what, from, to, count) =>
    what === 'sections'
      ? ` Schnitte ${from} bis ${to} zusammen gezeigt (${count} Schnitte, die Szene und Anzeige gleich darstellen).`
      : ` Suchdurchläufe ${from} bis ${to} zusammen gezeigt (${count} Durchläufe: jeder verengt den Bereich weiter, um weniger, als die Szene zeigen kann).`,
  start: (side, gamma, ds, rcr) =>
    `${side}. Abb. 1, Kasten 2 (Gl. 1): Beginn beim Schnitt mit Ringwinkel gamma = ${gamma}°, wo der Ring h/2 über seinem tiefsten Punkt liegt; d_s = ${ds} gegenüber Rcr = ${rcr}.`,
  approach: (side, merged, gamma, ds, gap) =>
    `${side}. Abb. 1, Kästen 6-11: entlang des Rings in Richtung d_s = Rcr.${merged} Schnitt bei gamma = ${gamma}°: d_s = ${ds} (Rcr - d_s = ${gap}).`,
  single: (side, gamma) =>
    `${side}. Abb. 1, Kästen 12-14: Der Schnitt bei gamma_scp = ${gamma}° berührt die h-Pseudoebene in einem einzigen Punkt (d_s = Rcr). Er begrenzt den Suchbereich.`,
  noSingle: (side) =>
    `${side}: Jeder Schnitt schneidet die h-Pseudoebene (kein einziger Kontakt), daher läuft die Suche über den ganzen halben Ring.`,
  search: (side, sections, from, to, gamma, out, merged) =>
    `${side}. Abb. 1, Kästen 16-25: ${sections} Schnitte von gamma = ${from}° bis ${to}°; ihre fernsten Schnittpunkte P_hp[i] mit der Ebene. Bester: gamma = ${gamma}°, ${out === null ? 'kein Schnittpunkt' : `${out} außerhalb des Kontakts`}; der Bereich verengt sich auf seine Nachbarn.${merged}`,
  flankConverged: (side, width, out, gamma) => `${side} konvergiert: ${width} = ${out} bei gamma* = ${gamma}°.`,
  closingUntilted: (half, exact) =>
    `Abb. 1, Kasten 26: konvergiert. L/2 = ${half} auf jeder Flanke; der exakte Löser ergibt ${exact}.`,
  closingTilted: (wR, wL, exactR, exactL) =>
    `Abb. 1, Kasten 26: auf beiden Flanken konvergiert. wR = ${wR}, wL = ${wL}; der exakte Löser ergibt wR = ${exactR}, wL = ${exactL}.`,
  same: {
    'single-contact':
      'Die Szene ändert sich kaum: Der letzte Annäherungsschnitt liegt bereits auf dem Schnitt des einzigen Kontakts; dieser Schritt bestätigt ihn (d_s = Rcr) und markiert seinen Punkt.',
    search: 'Die Szene ändert sich kaum: Die Suche beginnt am Punkt des einzigen Kontakts.',
    converged:
      'Die Szene zeigt den letzten Suchdurchlauf ohne seine Kandidaten: Die Suche bewegt sich nicht mehr, also ist ihr bester Punkt die Antwort für diese Flanke.',
  },
  counter: (k, n) => `Schritt ${k} von ${n}`,
  gaugeLabel: 'd_s / Rcr, linear ab 0:',
  noDs: ' hier kein d_s (Suche: Schnitte zwischen den Enden des Bereichs)',
  ds: (ratio, ds, rcr) => ` ${ratio}: d_s = ${ds}, Rcr = ${rcr}`,
  play: 'Abspielen',
  playOne: 'Abspielen (ein Schritt)',
  pause: 'Anhalten',
  back: '< Zurück',
  forward: 'Weiter >',
  names: {
    controls: 'Schrittsteuerung',
    first: 'Erster Schritt',
    back: 'Schritt zurück',
    forward: 'Schritt weiter',
    last: 'Letzter Schritt',
  },
  intro:
    'Die Szene zeigt jeden besuchten Schnitt (violett), die Kandidatenpunkte P_hp[i] jedes Suchdurchlaufs und den gefundenen Punkt, zuerst auf der rechten Flanke (+Y), dann auf der linken. Schritte, die gleich aussähen, werden zusammen gezeigt.',
  motion:
    'Reduzierte Bewegung ist eingeschaltet: Abspielen zeigt bei jedem Drücken den nächsten Schritt, statt die Schritte zu animieren.',
  cylinder:
    'Das 3D-Verfahren der Studie (Abbildung 1) durchsucht die Torusschnitte gegen die h-Pseudoebene und wird daher nur für eine Ebene gezeigt. Auf diesem Zylinder arbeitet der exakte Löser auf dem Zylinder selbst (siehe die Ergebnisse und das Profil quer zum Vorschub); eine Ebene wählen, um das Verfahren Schritt für Schritt zu sehen.',
};
