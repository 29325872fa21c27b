/**
 * The procedures' names in German (issue 30): the authors' names and the paper's equation numbers
 * kept, the words around them in the terms of the README's glossary (exakt, Schmiegkreis). Part of
 * de.ts.
 */
import type { CorrectedKey } from '../../core/procedures/procedures';
import type { ProcedureName, ProcedureNames } from './catalogue';

const NAMES: ProcedureNames['names'] = {
  exact: { label: 'Exakt (3D-Geometrie)', shortLabel: 'Exakt (3D)' },
  sekine: { label: 'Sekine et al. (Gl. 4-8)', shortLabel: 'Sekine et al.' },
  redonnet: { label: 'Redonnet et al. (Gl. 9, 8)', shortLabel: 'Redonnet et al.' },
  bedi: { label: 'Bedi et al. (Gl. 10-11)', shortLabel: 'Bedi et al.' },
  osculating: { label: 'Schmiegkreis am Kontaktpunkt', shortLabel: 'Schmiegkreis' },
  cornerBall: { label: 'Kugel mit dem Eckenradius', shortLabel: 'Eckenradius-Kugel' },
};

const corrected = (key: CorrectedKey): ProcedureName => ({
  label: `${NAMES[key].shortLabel}, korrigiert (1/rho = 1/Reff + 1/Rs)`,
  shortLabel: `${NAMES[key].shortLabel}, korrigiert`,
});

/** What a corrected row assumes (the registry's `assumes`, in the words of the glossary). */
const assumesCorrected = (key: CorrectedKey): string =>
  `Der Kreis mit Radius Reff von ${NAMES[key].shortLabel} mit der üblichen Krümmungskorrektur zweiter Ordnung: der kombinierte Radius 1/rho = 1/Reff + 1/Rs (Rs mit Vorzeichen; mit der Achse quer ist die Fläche quer zum Vorschub gerade, also rho = Reff) in L = 2 sqrt(2 rho h - h^2).`;

export const DE_PROCEDURES: ProcedureNames = {
  names: NAMES,
  rows: {
    plane: { label: 'Ebene, exakt (Krümmung ignoriert)', shortLabel: 'Ebene (Krümmung ignoriert)' },
    sekineCorrected: corrected('sekine'),
    redonnetCorrected: corrected('redonnet'),
    osculatingCorrected: corrected('osculating'),
    cornerBallCorrected: corrected('cornerBall'),
  },
  curved: {
    'Exact (this doubly curved point)': 'Exakt (dieser doppelt gekrümmte Punkt)',
    'Plane, exact (both curvatures ignored)': 'Ebene, exakt (beide Krümmungen ignoriert)',
    'Cylinder along the feed, exact (Rf ignored)': 'Zylinder in Vorschubrichtung, exakt (Rf ignoriert)',
    'Cylinder across the feed, exact (Rc ignored)': 'Zylinder quer zum Vorschub, exakt (Rc ignoriert)',
  },
  leadOnly: ', nur Anstellung',
  cylinderHead: 'Auf dem Zylinder: Krümmung ignoriert oder wie üblich korrigiert',
  table: 'Verfahren (eine Zeile wählen, um sie in allen Ansichten hervorzuheben)',
  region: 'Tabelle der Verfahren (seitlich scrollbar, wenn breiter als ihre Spalte)',
  select: 'Klicken, um dieses Verfahren in allen Ansichten auszuwählen',
  head: {
    Procedure: 'Verfahren',
    Model: 'Modell',
    Deviation: 'Abweichung',
    'Deviation [%]': 'Abweichung [%]',
    'Scallop it leaves': 'Verbleibende Rautiefe',
  },
  assumes: {
    plane:
      'Die exakte Lösung für eine Ebene beim selben h: was ein Rechner liefert, der die Krümmung der Fläche ignoriert.',
    sekineCorrected: assumesCorrected('sekine'),
    redonnetCorrected: assumesCorrected('redonnet'),
    osculatingCorrected: assumesCorrected('osculating'),
    cornerBallCorrected: assumesCorrected('cornerBall'),
  },
  curvedTitles: {
    'The exact step-over at this point.': 'Der exakte Bahnabstand in diesem Punkt.',
    'The exact answer on a plane at the same posture.': 'Die exakte Lösung auf einer Ebene bei derselben Werkzeuglage.',
    'The exact answer on the cylinder of radius Rc with its axis along the feed.':
      'Die exakte Lösung auf dem Zylinder mit Radius Rc und Achse in Vorschubrichtung.',
    'The exact answer on the cylinder of radius Rf with its axis across the feed.':
      'Die exakte Lösung auf dem Zylinder mit Radius Rf und Achse quer zum Vorschub.',
    'The usual correction: the effective radius combined with the radius across the feed.':
      'Die übliche Korrektur: der effektive Radius kombiniert mit dem Radius quer zum Vorschub.',
  },
  notes: {
    noScallop:
      'Kein Kamm: ein flach aufliegender Schaftfräser hinterlässt bei keinem Bahnabstand bis zu seinem Durchmesser einen Kamm, also L = 2R.',
    leadOnly: (names) =>
      `Mit Kippung sind ${names} reine Anstellmodelle: nur mit dem Anstellwinkel angewandt, die Kippung ignoriert.`,
    cylinder:
      'Auf einem Zylinder werden die Verfahren oben wie auf einer Ebene angewandt (sie ignorieren die Krümmung); die Zeilen darunter geben die exakte Lösung für eine Ebene bei derselben Eingabe (Krümmung ignoriert) und die übliche Korrektur 1/rho = 1/Reff + 1/Rs jedes Verfahrens mit effektivem Radius, jeweils neben der exakten Lösung auf dem Zylinder.',
    crossAxis:
      'Mit der Zylinderachse quer zum Vorschub ist der Schnitt quer zum Vorschub eine Gerade (dort 1/Rs = 0), daher lässt die Korrektur rho = Reff, und jede korrigierte Zeile gleicht der Zeile ihres Verfahrens oben.',
    curved:
      'Jede Zeile neben der exakten Lösung: die Ebene (beide Krümmungen ignoriert), jeder Zylinder (ein Radius ignoriert) und die übliche Korrektur 1/rho = 1/Reff + 1/Rc jedes Verfahrens mit effektivem Radius, mit ihrer Abweichung von der exakten Lösung und der Rautiefe, die ihr eigenes L in diesem Punkt tatsächlich hinterlässt.',
    curvedInverse: 'Die Vergleichszeilen gelten für die Vorwärtsaufgabe (von einer Rautiefe zum Bahnabstand).',
    beyond: (name, what, value, model, limit, limitValue) =>
      `${name}: ${what} = ${value} liegt ${what === 'h' ? 'über der breitesten Stelle' : 'über der Breite'} ${model === 'ellipse' ? 'seiner Ellipse' : model === 'combined' ? 'des kombinierten Kreises' : 'seines Kreises'} (${
        limit === 'Reff'
          ? 'Reff'
          : limit === 'height'
            ? 'ihre Höhe Rlong sin(rho)'
            : limit === 'halfWidth'
              ? 'ihre halbe Breite Rlong'
              : 'rho'
      } = ${limitValue}).`,
    wall: (name, interval, max, cylinder) =>
      `${name}: sein Bahnabstand L = ${interval} liegt nicht unter dem größten Bahnabstand, der ${cylinder ? 'auf diesem Zylinder ' : ''}einen Kamm hinterlässt (${max}): so weit auseinander liegende Bahnen hinterlassen eine Wand.`,
    reason: (name, reason) => `${name}: ${reason}.`,
    planeBeyond: 'Ebene: der Bahnabstand liegt bei oder über dem größten, den das Werkzeug auf einer Ebene zulässt.',
    notPositive: (name, reff) =>
      `${name}: sein effektiver Radius${reff === null ? '' : ` (${reff})`} ist nicht kleiner als der Radius der konkaven Fläche, daher ist der kombinierte Radius nicht positiv.`,
    flankLimit: (name) => `${name}: h liegt bei oder über der Grenze der Flanke auf dieser Fläche.`,
    combinedWidest: (name, radius) =>
      `${name}: h liegt über der breitesten Stelle des kombinierten Kreises (${radius}).`,
  },
};
