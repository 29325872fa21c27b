/**
 * The Machined surface view in German (issue 30): the simulation's lines, the heights' scale, the
 * comparison of the simulated with the exact cusp (Kamm, its height the Rautiefe as the results
 * name it), the profilometer trace (Rz, Ra, Rq kept: DIN EN ISO 4287). Part of de.ts.
 */
import type { Catalogue } from './catalogue';

export const DE_SURFACE: Catalogue['surface'] = {
  invalid: 'Veraltet: die Eingaben sind ungültig, es gibt nichts zu simulieren.',
  failed: 'Keine Simulation: ihr Löser hat aufgegeben; eine beliebige Eingabe ändern, um es erneut zu versuchen.',
  pending: (percent) => `Die Bahnen werden simuliert${percent === null ? '' : `: ${percent} %`} …`,
  reasons: {
    'planes-only':
      'Die Simulation deckt nur Ebenen ab: auf einem Zylinder gelten die exakten Werte oben weiter, aber es gibt keine simulierte Fläche zum Vergleich.',
    'no-scallop':
      'Kein Kamm: der ebene Boden liegt auf der Ebene und hinterlässt eine ebene Fläche, es gibt nichts zu simulieren.',
    none: 'Keine Simulation.',
  },
  exception: () => 'Keine Simulation: bei der Rechnung ist ein unerwarteter Fehler aufgetreten.',
  exaggeration: (k, unit) =>
    `${k === null ? 'Höhen maßstäblich' : `Höhen ${k}-fach überhöht (vertikale Überhöhung)`}; Farbe: Höhe über dem tiefsten Punkt (${unit}).`,
  comparison: (simulated, exact, diff, within, bound, cells, passes) =>
    `Simulierte Kammhöhe ${simulated} gegenüber exakt ${exact}: sie unterscheiden sich um ${diff}, ${within ? 'innerhalb' : 'außerhalb'} der angegebenen Auflösungsschranke ${bound} (${cells.replace(' x ', ' × ')} Zellen, ${passes} Bahnen).`,
  traceLabel: 'Tastschnitt quer zu den Bahnen mit Rz, Ra und Rq',
  traceCaption: (passes, rz, ra, rq) =>
    `Simulierter Tastschnitt, ${passes} Bahnen. Exakt: Rz ${rz}, Ra ${ra}, Rq ${rq}`,
  meanLine: 'Mittellinie',
  sceneLabel: '3D-Ansicht der simulierten bearbeiteten Fläche, nach Höhe eingefärbt',
};
