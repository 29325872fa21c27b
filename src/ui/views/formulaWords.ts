/**
 * The formulas view's words in English (issue 30): the view as written (what each procedure
 * assumes is the registry's), typed by the catalogues' FormulaWords so Japanese and German
 * (i18n/jaFormulas.ts, deFormulas.ts) give every one. Loaded with the teaching views.
 */
import { PROCEDURE_KEYS, PROCEDURES } from '../../core/procedures/procedures';
import type { FormulaWords } from '../i18n/teachWords';

export const EN_FORMULAS: FormulaWords = {
  assumes: Object.fromEntries(PROCEDURE_KEYS.map((k) => [k, PROCEDURES[k].assumes])) as FormulaWords['assumes'],
  leadOnly: 'Lead-only model: applied with the lead angle alone, the tilt ignored.',
  maths: (name) => `${name}: equations (a wide one scrolls sideways)`,
  cylinder: (radius, axis) =>
    `On a cylinder (Rs = ${radius}, axis ${axis === 'feed' ? 'along' : 'across'} the feed) the exact step-over is solved on the cylinder itself (the flanks' reach at the radial height h, ${axis === 'feed' ? 'as angles about its axis' : 'of the tool revolved about its axis'}), not by the plane's formulas, so they are left out. The approximations below are as on a plane; the table's corrected rows put 1/rho = 1/Reff + 1/Rs into L = 2 sqrt(2 rho h - h^2).`,
  notApplicable: (names) => `${names}: not applicable here (see the notes under the results table).`,
  units: (unit, small) =>
    `Lengths in ${unit} (small ones in ${small}), angles in degrees; each L/2 is at the h of the current state.`,
  postureTitle: 'Posture from the slope (three-axis)',
  postureIntro:
    "The upright tool on the sloped plane is the tool at this lead and tilt on a plane; the formulas below are the plane's at that posture.",
  postureLine: (label, formula, value) => `${label}: ${formula}, so ${value}`,
  postureLabels: {
    'Slope and raster angle': 'Slope and raster angle',
    D: 'D',
    Lead: 'Lead',
    Tilt: 'Tilt',
    'Programmed step': 'Programmed step',
  },
  anglesFormula: 'alpha, psi (waterline: psi = 90)',
};
