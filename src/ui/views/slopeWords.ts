/**
 * The three-axis chart's words in English (issue 30): the chart as written, typed by the
 * catalogues' SlopeWords so Japanese and German (i18n/jaSlope.ts, deSlope.ts) give every one.
 * Loaded with the teaching views.
 */
import type { SlopeWords } from '../i18n/catalogue';

/** Why a constant step leaves no cusp, by the core's code (core/threeAxis/errors.ts). */
const REFUSAL_WORDS: Readonly<Record<string, string>> = {
  'beyond-step': 'passes that far apart leave a wall, not a scallop',
  'shank-cuts': "the tool's shank, not its corner, would form the cusp",
  'flank-wall': 'the flank rises to a wall before the passes meet',
  'wall-only': 'the side rises straight from the contact: no scallop at any step',
  'past-surface': 'the next pass would lie past the usable surface',
  'needs-slope': 'on a flat floor a step-down means nothing',
  gouging: 'the tool would gouge the surface',
};

export const EN_SLOPE: SlopeWords = {
  stepTitle: (u, h, slope) =>
    `Programmed step [${u}] against slope [deg] for h = ${h} (R, Rcr fixed; dashed: current slope = ${slope})`,
  cuspTitle: (u, constant, h) => `Scallop [${u}] a constant ${constant} leaves, against slope [deg] (dotted: h = ${h})`,
  slopeAxis: 'slope alpha [deg]',
  stepAxis: (u) => `step [${u}]`,
  scallopAxis: (u) => `scallop [${u}]`,
  description: (title, sentence) => `${title}. ${sentence}`,
  legendHead: (slope) => `at slope = ${slope}:`,
  strategy: (passes, psi) => (passes === 'raster' ? `Lxy (raster, psi = ${psi})` : 'dz (waterline)'),
  floor: "flat floor's step Lxy0",
  scallopOf: (constant) => `scallop of ${constant}`,
  none: 'n/a',
  gap: 'h at or above the limit',
  noStepAbove: (slope, h, revolution) =>
    `No step above ${slope}: there h = ${h} reaches the largest scallop the tool can leave (its flank or shank${revolution ? ', or the end of the surface' : ''}); 90° is a vertical wall.`,
  crossing: (crossing, psi, h, both, revolution) => {
    const raster = `raster at psi = ${psi}`;
    const where = revolution ? ' (on a plane of that slope)' : '';
    if (crossing === null)
      return `Waterline and ${raster} do not cross for a scallop of ${h}${where}: ${raster} programs the larger step at every slope where both are valid.`;
    return `Above ${crossing} waterline programs a larger step than ${raster} for the same scallop of ${h}, below it ${raster} does${both === null ? '' : ` (both ${both} at ${crossing})`}${where}.`;
  },
  refusal: (step, from, to, code) =>
    `No scallop for the constant ${step} ${to === null ? `at about ${from}` : `from about ${from} to ${to}`}: ${REFUSAL_WORDS[code] ?? 'the solver refuses it'}.`,
};
