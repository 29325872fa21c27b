/**
 * The formulas view in German (issue 30): what each procedure assumes, the notes around the
 * equations and the three-axis posture's box, in the terms of de.ts and the README's glossary
 * (Bahnabstand, Anstellwinkel, Kippwinkel, Ringellipse, Schmiegkreis, Torusfräser); the equations
 * are the paper's symbols. Part of de.ts.
 */
import type { FormulaWords } from './teachWords';

export const DE_FORMULAS: FormulaWords = {
  assumes: {
    exact:
      'Echte 3D-Geometrie: Das Werkzeug bewegt sich entlang X, also ist die Fläche, die es hinterlässt, seine Projektion entlang X: die um Rcr versetzte Ringellipse (um die Kippung gedreht). Gilt für jede Stellung, Kugel- und Schaftfräser eingeschlossen.',
    sekine:
      'Kreisnäherung: Eine Ellipse aus der Höhe des Werkzeugmittelpunkts wird durch einen Kreis mit dem Radius Reff ersetzt. Sie übergeht, wo sich die Krümmung des wahren Profils ändert, und liegt daher bei kleinem Anstellwinkel weit daneben.',
    redonnet:
      'Schmiegkreis im tiefsten Punkt ohne Kippung: exakt für h gegen 0, danach überschätzt er L, weil das wahre Profil schneller ansteigt.',
    bedi: 'Elliptische Projektion: Eine Ellipse mit den Halbachsen Rlong und Rlong sin(rho) steht für die versetzte Ellipse. Ohne Kippung nahe dran, aber eine versetzte Ellipse ist keine Ellipse; bei rho = 0 versagt sie.',
    osculating:
      'Redonnets Gedanke für jede Stellung: der Kreis, der sich im Kontaktpunkt dem exakten Profil anschmiegt. Exakt für h gegen 0; symmetrisch, daher entgeht ihm die Asymmetrie, die die Kippung bringt.',
    cornerBall:
      'Behandelt den Torusfräser als Kugelfräser mit dem Radius Rcr, wie manche Rechner im Netz: exakt nur für einen Kugelfräser, und ein viel zu kleiner Bahnabstand, sobald Anstell- oder Kippwinkel den flachen Boden ins Spiel bringen.',
  },
  leadOnly: 'Modell nur für die Anstellung: allein mit dem Anstellwinkel angewandt, die Kippung ignoriert.',
  maths: (name) => `${name}: Gleichungen (eine breite lässt sich seitlich scrollen)`,
  cylinder: (radius, axis) =>
    `Auf einem Zylinder (Rs = ${radius}, Achse ${axis === 'feed' ? 'in Vorschubrichtung' : 'quer zum Vorschub'}) wird der exakte Bahnabstand auf dem Zylinder selbst gelöst (die Reichweite der Flanken in der radialen Höhe h, ${axis === 'feed' ? 'als Winkel um seine Achse' : 'des um seine Achse gedrehten Werkzeugs'}), nicht mit den Formeln der Ebene; diese entfallen daher. Die Näherungen unten sind wie auf einer Ebene; die korrigierten Zeilen der Tabelle setzen 1/rho = 1/Reff + 1/Rs in L = 2 sqrt(2 rho h - h^2) ein.`,
  notApplicable: (names) => `${names}: hier nicht anwendbar (siehe die Hinweise unter der Ergebnistabelle).`,
  units: (unit, small) =>
    `Längen in ${unit} (kleine in ${small}), Winkel in Grad; jedes L/2 gilt bei der Rautiefe h der aktuellen Eingaben.`,
  postureTitle: 'Stellung aus der Neigung (3-Achs)',
  postureIntro:
    'Das senkrechte Werkzeug auf der geneigten Ebene ist das Werkzeug mit diesem Anstell- und Kippwinkel auf einer Ebene; die Formeln unten sind die der Ebene in dieser Stellung.',
  postureLine: (label, formula, value) => `${label}: ${formula}, also ${value}`,
  postureLabels: {
    'Slope and raster angle': 'Neigung und Zeilenwinkel',
    D: 'D',
    Lead: 'Anstellwinkel',
    Tilt: 'Kippwinkel',
    'Programmed step': 'Programmierter Abstand',
  },
  anglesFormula: 'alpha, psi (Z-Ebenen: psi = 90)',
};
