/**
 * The shop sheet in German (issue 30): the sheet's headings, lines, legend and buttons in the CAM
 * systems' terms (Bahnabstand, Rautiefe, Anstellwinkel, Z-Zustellung; as de.ts); the symbols and
 * the marks' letters kept. Part of de.ts.
 */
import type { Catalogue } from './catalogue';

const STEP = {
  interval: 'Bahnabstand L benachbarter Bahnen, entlang der Fläche',
  horizontalStep: 'waagerechter Bahnabstand Lxy benachbarter Zeilen, wie programmiert',
  stepDown: 'Z-Zustellung dz benachbarter Z-Ebenen, wie programmiert',
} as const;

export const DE_SHEET: Catalogue['sheet'] = {
  title: (step, u) => `Werkstattblatt: ${step} (${u})`,
  tool: (d, r, rcr) => `Werkzeug: D ${d} (R ${r}), Eckenradius Rcr ${rcr}`,
  fiveAxis: (tilt, pattern, surface) =>
    `5-Achs, Kippwinkel ${tilt}°; Bahnen ${pattern === 'one-way' ? 'in einer Richtung' : 'im Zickzack'}; Fläche: ${surface}`,
  threeAxis: (passes, angle, surface) =>
    `3-Achs, Werkzeug senkrecht; ${passes === 'raster' ? 'Zeilen' : 'Z-Ebenen'}${angle === null ? '' : ` unter ${angle}° zur Falllinie`}; Fläche: ${surface}`,
  surface: (s) => {
    if (s.kind === 'plane') return 'Ebene';
    if (s.kind === 'sloped-plane') return 'geneigte Ebene';
    if (s.kind === 'cylinder')
      return `${s.concave ? 'konkaver' : 'konvexer'} Zylinder, Rs ${s.radius}, Achse ${s.axis === 'feed' ? 'in Vorschubrichtung' : 'quer zum Vorschub'}`;
    if (s.kind === 'doubly-curved') return `doppelt gekrümmter Punkt, Rf ${s.feed}, Rc ${s.cross} (negativ: konkav)`;
    return `Rotationsfläche, Rf ${s.feed ?? 'gerade'}, Rc ${s.cross ?? 'gerade'} (negativ: konkav)`;
  },
  axes: (u, columns, step) =>
    `Zeilen: Rautiefe h (${u}). Spalten: ${columns === 'lead' ? 'Anstellwinkel rho (°)' : 'Flächenneigung (°)'}. Werte: ${STEP[step]} (${u}).`,
  made: (date) => `Exakte Lösung, Bahnabstandsrechner, ${date}.`,
  region: 'Tabelle der Bahnabstände',
  caption: (step, u, columns) =>
    `${step} (${u}) nach Rautiefe h (${u}, Zeilen) und ${columns === 'lead' ? 'Anstellwinkel' : 'Flächenneigung'} (°, Spalten)`,
  column: { lead: 'Anstellwinkel', slope: 'Neigung' },
  deg: '°',
  yourH: ' (Ihre Vorgabe)',
  where: (h, columns, deg) => `h ${h}, ${columns === 'lead' ? 'Anstellwinkel' : 'Neigung'} ${deg}°`,
  markLabel: (letter, where) => `${letter} bei ${where}: Grund anzeigen`,
  markReason: (letter, where) => `${letter} bei ${where}: `,
  marks: {
    wall: 'h auf oder über der Grenze dieser Anstellung: eine Flanke oder der Schaft hinterlässt eine Wand, keinen Kamm.',
    gouge: 'das Werkzeug verletzt die Fläche in dieser Anstellung.',
    range: 'außerhalb des Bereichs, den dieses Werkzeug hier zulässt (Anstell-, Kippwinkel oder Neigung).',
  },
  noScallop: 'kein Kamm: ein flach aufliegender Schaftfräser schneidet bei jedem Bahnabstand bis 2R eben.',
  ownRow: (h) => `Fette Zeile: Ihre Rautiefe h = ${h}.`,
  hintHover:
    'Den Zeiger auf ein Zeichen halten oder es anklicken zeigt den ganzen Grund; der Rechner beantwortet jeden Einzelfall.',
  hintTouch: 'Ein Zeichen antippen zeigt den ganzen Grund; der Rechner beantwortet jeden Einzelfall.',
  heightsLabel: (u, max) => `Rautiefen h (${u}), bis zu ${max}, durch Leerzeichen getrennt (Ihre Vorgabe kommt hinzu)`,
  heightsError: (u, max, got) =>
    `Rautiefen: 1 bis ${max} Rautiefen über 0 ${u} angeben, durch Leerzeichen getrennt${got === null ? '' : ` (eingegeben: ${got})`}.`,
  csv: 'CSV herunterladen',
  print: 'Drucken',
  close: 'Schließen',
  saved: (name) => `${name} gespeichert.`,
  refusals: {
    leadRange: 'Der Anstellwinkel rho muss mindestens 0° und unter 90° betragen.',
    curvedGouge:
      'Das Werkzeug verletzt diesen doppelt gekrümmten Punkt in dieser Anstellung: das bewegte Werkzeug reicht abseits des Kontaktpunkts in die Fläche.',
    curvedWall: (limit, got) =>
      `Die Rautiefe h muss an diesem Punkt und in dieser Anstellung unter ${limit} liegen (eingegeben: ${got}).`,
    noStepDown: 'Z-Ebenen haben hier keine Z-Zustellung.',
  },
};
