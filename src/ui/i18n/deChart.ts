/**
 * The five-axis comparison charts in German (issue 30): captions, axis titles, legends and notes
 * in the terms of de.ts (Bahnabstand, Anstellwinkel, Kippwinkel); the procedures' names kept. Part
 * of de.ts.
 */
import type { ChartWords } from './catalogue';

export const DE_CHART: ChartWords = {
  leadTitle: (u, rho) =>
    `L [${u}] über dem Anstellwinkel rho [°] (R, Rcr, beta, h fest; gestrichelt: aktueller rho = ${rho})`,
  errorTitle: (u) =>
    `Vorzeichenbehaftete Abweichung jeder Näherung von der exakten Lösung, über dem Anstellwinkel [${u}]`,
  tiltTitle: (u, beta) =>
    `L [${u}] über dem Kippwinkel beta [°] (R, Rcr, rho, h fest; gestrichelt: aktueller beta = ${beta})`,
  leadAxis: 'Anstellwinkel rho [°]',
  tiltAxis: 'Kippwinkel beta [°]',
  errorAxis: (u) => `Abweichung [${u}]`,
  description: (title) => `${title}. Die Werte beim aktuellen Winkel stehen neben dem Diagramm.`,
  legendHead: (angle, deg) => `bei ${angle} = ${deg}°:`,
  leadOnly: ' (nur Anstellung)',
  seeBelow: 'keine Antwort (siehe unten)',
  none: 'keine',
  errorIn: { pct: 'Abweichung in %', length: 'Abweichung als Länge', name: 'Einheit der Abweichung' },
  rhoScale: { log: 'rho-Achse: logarithmisch', linear: 'rho-Achse: linear', name: 'Achse des Anstellwinkels' },
  summary: (rho, beta, values) => `Bei rho = ${rho}°, beta = ${beta}°, L: ${values}.`,
  noSummary: 'Die aktuelle Anstellung liegt außerhalb des dargestellten Bereichs.',
  cylinder: (concave, axis) =>
    ` Auf diesem ${concave ? 'konkaven' : 'konvexen'} Zylinder (Achse ${axis === 'feed' ? 'in Vorschubrichtung' : 'quer zum Vorschub'}) ist die exakte Kurve die des Zylinders (keine, wo die Anstellung die Fläche verletzen würde oder h über ihren Flanken liegt); die Näherungen sind wie auf einer Ebene, wie in der Tabelle.`,
  gap: (names, angle, from, to) =>
    `Keine Antwort von ${names} ${to === null ? `bei etwa ${angle} = ${from}°` : `für ${angle} von etwa ${from}° bis ${to}°`}: `,
  reasons: {
    exact:
      'h liegt bei oder über der höchsten Rautiefe, die diese Stellung hinterlassen kann (darüber hinterlässt das Werkzeug eine Wand, keinen Kamm)',
    sekineRhoZero:
      'bei rho = 0 entartet die projizierte Ellipse zu einer Strecke (ihr großer Radius Rshort/sin(rho) ist unendlich)',
    sekineShort: 'der kleine Radius der Ellipse ist 0',
    redonnetRhoZero: 'bei rho = 0 ist der effektive Radius Rb/sin(rho) + Rcr unendlich',
    bediRhoZero: 'bei rho = 0 ist ihre Ellipse (Halbachsen Rlong, Rlong sin(rho)) flach, und Gl. 11 teilt durch 0',
    overflow:
      'ihr effektiver Radius läuft über (rho liegt zu nahe an 0 für ihr 1/sin(rho)); das Modell hat hier keine Antwort',
    flatBottom:
      'der flache Boden liegt auf der Ebene (rho = 0 ohne Kippung, oder Anstell- und Kippwinkel zu klein, um zu zählen), daher ist der Krümmungsradius im Kontaktpunkt unendlich',
    sharpEdge: 'der Kontakt ist eine scharfe Kante (Rcr = 0), ein Kreis mit dem Radius 0',
    flatEnd: 'ein Schaftfräser (Rcr = 0) hat keine Eckenradius-Kugel',
  },
  widest: (shape, symbol) =>
    `h liegt über dem breitesten Punkt ${shape === 'circle' ? 'ihres Kreises (sein Radius' : 'ihrer Ellipse (ihre Höhe'} ${symbol} ist kleiner als h)`,
};
