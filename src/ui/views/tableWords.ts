/**
 * The paper's tables' words in English (issue 30): the view as written, typed by the catalogues'
 * TableWords so Japanese and German (i18n/jaTables.ts, deTables.ts) give every one. Loaded with the
 * teaching views.
 */
import type { TableWords } from '../i18n/teachWords';

export const EN_TABLES: TableWords = {
  note:
    'Each cell: printed / recomputed, in mm as the paper prints them (in either unit). Highlighted: the recomputed value does not round to the printed digits. ' +
    'Tables 4-5 evaluate Eqs. 12-13 at the printed 3D L/2, as the paper did. Click a condition to load it.',
  why:
    "Why the printed 3D column is 0.0005-0.013 mm low: the paper's Figure 1 leaves two things open, whether eta of Eq. 2 is normalised and how far the search of steps 15-16 runs, " +
    'and its search range can stop just before the true maximum. One plausible reading (Eq. 2 as printed, the range from the single-contact section to the angle of its P_hp) ' +
    'returns the printed 1.879 mm for R = 3, Rcr = 1, rho = 5, h = 0.10, where the true maximum is 1.892 mm. ' +
    "The exact values here agree with brute-force sampling of the torus surface and with the paper's own procedure run to convergence (the step-by-step view), so they are not tuned to the printed column.",
  halfCaption: 'Tables 2-3: L/2 [mm] for h',
  heightCaption: 'Tables 4-5: h [mm] at the printed 3D L/2',
  halfName: 'Tables 2-3',
  heightName: 'Tables 4-5',
  region: (name) => `${name} (scrolls sideways when wider than the screen)`,
  table: 'Table',
  printedHalf: 'L/2 (3D) [mm]',
  load: 'Load this condition into the calculator',
};
