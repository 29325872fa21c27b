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
};
