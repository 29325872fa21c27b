/**
 * JSON in the user's unit (issue 26 point 9): the answers are computed in mm, once, and every
 * length of the JSON is converted once from its double (`fromMm`), so an answer in inches is the mm
 * answer / 25.4 to the last digit. Which members are lengths is named here, member by member
 * (tests/cli/units.test.ts checks that every number the command line writes is named in one list);
 * an error's `limit` is a length or an angle by its field (the field registry's kind). The input
 * echoed (`input`) reads back as typed: rounded to 12 significant digits (table.ts's inputIn). Pure.
 */
import { FIELDS, type FieldId, isLengthField } from '../core/input/fields';
import { fromMm, type LengthUnit } from '../core/input/units';
import { AREAL_HEIGHTS } from './batchHeader';
import { unitWord } from './lengthInput';
import type { JsonValue } from './reportJson';
import { inputIn } from './table';

/** Members that hold a length (mm in the solvers). */
export const LENGTH_MEMBERS: ReadonlySet<string> = new Set([
  'R',
  'D',
  'Rcr',
  'h',
  'Ra',
  'Rz',
  'Rq',
  'surfaceRadius',
  'feedRadius',
  'crossRadius',
  'interval',
  'halfInterval',
  'maxInterval',
  'halfWidthRight',
  'halfWidthLeft',
  'contactOffset',
  'scallopHeight',
  'otherCuspHeight',
  'rightCuspHeight',
  'leftCuspHeight',
  'deviation',
  'intervalDeviation',
  'realScallopHeight',
  'toolCentreHeight',
  'shortRadius',
  'longRadius',
  'effectiveRadius',
  'combinedRadius',
  'cuspHeight',
  'cuspHeightBound',
  'roughnessBound',
  'cellSize',
  'horizontalStep',
  'stepDown',
  'flatFloorStep',
  'programmedStep',
  'heightLimit',
  'cuspAtProgrammedStep',
  'heldMm',
  'radiusMm',
  // The surface the teeth leave (feedMarks, areal).
  'height',
  'period',
  'balancedFz',
  ...AREAL_HEIGHTS,
  'dx',
  'dy',
  // The finish asked backwards (targetFinish.ts).
  'feedPerTooth',
  'feedMarkHeight',
  'zeroFeedInterval',
]);

/** Members that hold a number that is no length (angles in degrees, percentages, counts, times). */
export const OTHER_NUMBER_MEMBERS: ReadonlySet<string> = new Set([
  'rho',
  'tilt',
  'slope',
  'rasterAngle',
  'lead',
  'largestSlope',
  'leanDeg',
  'deviationPercent',
  'cells',
  'placements',
  'ms',
  'cellsAcross',
  'cellsAlong',
  'Ssk',
  'Sku',
  'nx',
  'ny',
  'cellsX',
  'cellsY',
]);

function convert(value: JsonValue, unit: LengthUnit, isLength: boolean, input = false): JsonValue {
  if (typeof value === 'number') return isLength ? (input ? inputIn(value, unit) : fromMm(value, unit)) : value;
  if (Array.isArray(value)) return value.map((v) => convert(v, unit, isLength, input));
  if (typeof value !== 'object') return value;
  const out: { [key: string]: JsonValue } = {};
  const field = typeof value.field === 'string' ? value.field : null;
  for (const [key, v] of Object.entries(value)) {
    // An error's limit: a length or an angle by its field.
    const length =
      key === 'limit' && field !== null ? field in FIELDS && isLengthField(field as FieldId) : LENGTH_MEMBERS.has(key);
    out[key] = convert(v, unit, length, input || key === 'input');
  }
  return out;
}

/**
 * A JSON answer (or errors) of the command line in `unit`: every length converted once from mm,
 * and `unit` (where the answer names one) set to the unit's word (`mm` or `inch`).
 */
export function jsonInUnit(value: { [key: string]: JsonValue }, unit: LengthUnit): { [key: string]: JsonValue } {
  if (unit === 'mm') return value;
  const out = convert(value, unit, false) as { [key: string]: JsonValue };
  return 'unit' in out ? { ...out, unit: unitWord(unit) } : out;
}
