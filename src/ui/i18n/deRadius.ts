/**
 * A doubly curved point's charts in German (issue 30): L against each principal radius, in the
 * terms of de.ts (konvex, konkav, gerade, verletzen); symbols kept. Part of de.ts.
 */
import type { RadiusWords } from './catalogue';

const KIND = { convex: 'konvex', concave: 'konkav', straight: 'gerade' } as const;

export const DE_RADIUS: RadiusWords = {
  radius: (kind, size) => (kind === 'straight' ? 'gerade' : `${KIND[kind]} ${size}`),
  title: (u, self, other, held, current) =>
    `L [${u}] über |${self}| [${u}], logarithmische Achse (${other} fest ${held}; R, Rcr, Anstellung, h fest; gestrichelt: aktueller ${self} = ${current})`,
  xLabel: (self, u) => `|${self}| [${u}] (logarithmisch)`,
  description: (title) => `${title}. Die Werte beim aktuellen Radius stehen neben dem Diagramm.`,
  band: { gouging: 'Verletzung', limit: 'h auf oder über der Grenze' },
  legendHead: (self, current) => `bei ${self} ${current}:`,
  branch: (self, kind) => `${self} ${KIND[kind]}`,
  seeBelow: 'keine Antwort (siehe unten)',
  summary: (rf, rc, L, rfStraight, rcStraight) =>
    `Bei Rf ${rf}, Rc ${rc}: L = ${L}; mit Rf gerade ${rfStraight}, mit Rc gerade ${rcStraight}.`,
  gap: (side, self, from, to, other, held, reason) =>
    `Kein ${side === 'concave' ? 'konkaves' : 'konvexes'} L ${to === null ? `bei etwa |${self}| = ${from}` : `für |${self}| von etwa ${from} bis ${to}`} (${other} fest ${held}): ${reason === 'gouging' ? 'das Werkzeug verletzt die Fläche in dieser Anstellung' : 'h liegt dort auf oder über der Grenze der Flanke oder des Schafts'}.`,
};
