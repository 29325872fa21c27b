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
};
