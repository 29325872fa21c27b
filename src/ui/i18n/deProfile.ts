/**
 * The cross-feed profile in German (issue 30): the plot's name, the notes over a curved surface's
 * section, the scale line, the exaggeration's choice, the buttons, the legend's words (the
 * procedures' names kept), the arc and the height bar. Part of de.ts.
 */
import type { Catalogue } from './catalogue';

const side = (s: 'convex' | 'concave') => (s === 'convex' ? 'konvex' : 'konkav');

export const DE_PROFILE: Catalogue['profile'] = {
  plotPlane: 'Profil quer zum Vorschub mit drei benachbarten Bahnen',
  plotCylinder: (s, axis) =>
    `Profil quer zum Vorschub mit drei benachbarten Bahnen auf einem ${s === 'convex' ? 'konvexen' : 'konkaven'} Zylinder, Achse ${axis === 'feed' ? 'in' : 'quer zur'} Vorschubrichtung`,
  plotCurved: (rf, rc) =>
    `Profil quer zum Vorschub mit drei benachbarten Bahnen an einem doppelt gekrümmten Punkt (Rf ${side(rf)}, Rc ${side(rc)})`,
  noteCylinder: (s, radius, axis) => {
    const on = `Auf einem ${s === 'convex' ? 'konvexen' : 'konkaven'} Zylinder mit Radius ${radius}`;
    return axis === 'feed'
      ? `${on}, Achse in Vorschubrichtung: jede Bahn hinterlässt das Profil der Ebene, die nächste um L/|Rs| um die Zylinderachse gedreht; L wird entlang des Bogens gemessen. Höhen radial, von der Fläche aus.`
      : `${on}, Achse quer zum Vorschub: dieser Schnitt durch die Zylinderachse zeigt die Fläche gerade; jede Bahn ist das um die Achse gedrehte Werkzeug (sein Profil ist nicht das der Ebene), die nächste um L entlang der Achse versetzt. Höhen radial, von der Fläche aus.`;
  },
  noteCurved: (rf, rc) =>
    `An einem doppelt gekrümmten Punkt (Rf ${rf} in Vorschubrichtung, Rc ${rc} quer dazu): der Schnitt quer zum Vorschub ist der Kreis mit Radius |Rc|; jede Bahn hinterlässt den Schnitt, den ihre beiden Flanken von der Hauptachse aus gesehen bilden, die nächste um L/|Rc| darum gedreht; L wird entlang des Bogens gemessen. Die Marken zeigen, wohin die Antwort der Ebene, die jedes Zylinders und die korrigierten Verfahren die nächste Bahn legen. Höhen radial, von der Fläche aus.`,
  heightsPlane: 'Höhen',
  heightsSurface: 'Höhen über der Fläche',
  curvatureTrue: '; die Krümmung der Fläche maßstäblich',
  scale: (k, heights, auto, capped, curvature) => {
    const a = auto ? ' (automatisch)' : '';
    const c = capped === null ? '' : ` (${capped}-fach würde das Tal überschlagen)`;
    return k === 1 ? `maßstäblich${a}${c}` : `${heights} ${k}-fach überhöht${a}${c}${curvature}`;
  },
  exaggeration: 'Überhöhung',
  auto: 'Überhöhung: automatisch',
  trueScale: 'maßstäblich',
  vertical: (k) => `${k}-fach überhöht`,
  zoomIn: 'Vergrößern',
  zoomOut: 'Verkleinern',
  reset: 'Ansicht zurücksetzen',
  cusp: 'Zum Kamm zoomen',
  approximations:
    'Die Profile der Näherungen sind beim exakten Bahnabstand L gezeichnet (an jeder Bahn, die die exakte Lösung legt), um ihre Form mit dem exakten Profil zu vergleichen; den Bahnabstand, den jede von ihnen ergibt, nennt die Ergebnistabelle.',
  ring: 'Ringellipse (a = Rb, b)',
  nextPass: ': nächste Bahn',
  cylinderAlong: 'Zylinder in Vorschubrichtung (Rf nicht berücksichtigt)',
  cylinderAcross: 'Zylinder quer zum Vorschub (Rc nicht berücksichtigt)',
  arc: ' (Bogenlänge)',
  high: (length, k) => `${length} hoch (${k}-fach überhöht gezeichnet)`,
};
