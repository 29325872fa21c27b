/**
 * The lookup table in the user's unit (issue 21): the table is computed in mm and degrees in the
 * batch's layout (lookupTable.ts, worker/data/curvedTable.ts); the page's download names the unit
 * of every dimensioned column in its header (`R_mm` or `R_in`, `rho_deg`) and, in inches, writes
 * its lengths in inches. Input lengths (R, Rcr, h, the surface radii) are rounded to 12
 * significant digits, so an inch value typed or taken from the inch grid reads as typed (0.0005,
 * not 0.0004999999999999999); results keep full precision. The `note` and `error` columns (text,
 * perhaps quoted) come last and are kept as they are. Pure.
 */

import { fromMm, type LengthUnit } from '../input/units';
import { csvNumber, RESULT_COLUMNS } from './csvWrite';

/** Input columns that hold a length (mm in the batch layout): rounded to 12 digits when converted. */
const INPUT_LENGTH_COLUMNS: ReadonlySet<string> = new Set([
  'R',
  'Rcr',
  'h',
  'surfaceRadius',
  'feedRadius',
  'crossRadius',
]);

/** Result columns that hold a length (full precision): every result column but the text ones. */
const RESULT_LENGTH_COLUMNS: ReadonlySet<string> = new Set([
  ...RESULT_COLUMNS.filter((column) => column !== 'note' && column !== 'error'),
  // Three-axis rows' programmed steps (threeAxisLookup.ts; their `interval` is the batch's too).
  'horizontalStep',
  'stepDown',
]);

/** Columns that hold an angle in degrees (three-axis rows: the slope, the raster angle, the equivalent lead and tilt). */
const ANGLE_COLUMNS: ReadonlySet<string> = new Set(['rho', 'tilt', 'slope', 'rasterAngle', 'lead']);

/** The unit suffix of a batch column (`_mm`, `_in`, `_deg`), or '' for a word or text column. */
export function columnUnitSuffix(column: string, unit: LengthUnit): string {
  if (INPUT_LENGTH_COLUMNS.has(column) || RESULT_LENGTH_COLUMNS.has(column)) return `_${unit}`;
  return ANGLE_COLUMNS.has(column) ? '_deg' : '';
}

/**
 * The batch column a unit-named column stands for, and its length unit: `R_in` is R in inches,
 * `rho_deg` is rho, `R` is R (no unit named). `unit` is null for an angle or a word column.
 */
export function unitNamedColumn(name: string): { readonly column: string; readonly unit: LengthUnit | null } {
  const m = /^(.+)_(mm|in|deg)$/.exec(name);
  if (m === null) return { column: name, unit: null };
  const [, column = '', suffix] = m;
  if (suffix === 'deg') return ANGLE_COLUMNS.has(column) ? { column, unit: null } : { column: name, unit: null };
  const isLength = INPUT_LENGTH_COLUMNS.has(column) || RESULT_LENGTH_COLUMNS.has(column);
  return isLength ? { column, unit: suffix as LengthUnit } : { column: name, unit: null };
}

/** A table's header line (batch column names) with the unit of every dimensioned column named. */
export function headerInUnit(header: string, unit: LengthUnit): string {
  return header
    .split(',')
    .map((c) => `${c}${columnUnitSuffix(c, unit)}`)
    .join(',');
}

/** A length field (mm text, or empty) in `unit`. */
function lengthIn(text: string, unit: LengthUnit, input: boolean): string {
  if (text === '' || unit === 'mm') return text;
  const v = fromMm(Number(text), unit);
  return csvNumber(input ? Number(v.toPrecision(12)) : v);
}

/**
 * A lookup table (batch layout, mm and degrees; header first) with its unit named in every
 * dimensioned column's header and its lengths in `unit`. The fields before `note` must be plain
 * (numbers or words, no comma or quote), as the table writers write them.
 */
export function lookupCsvInUnit(csvMm: string, unit: LengthUnit): string {
  const [head = '', ...rows] = csvMm.replace(/\n$/, '').split('\n');
  const columns = head.split(',');
  const plain = columns.indexOf('note');
  const count = plain < 0 ? columns.length : plain;
  const header = headerInUnit(head, unit);
  const lines = rows.map((row) => {
    const fields = row.split(',');
    const converted = fields.slice(0, count).map((text, i) => {
      const c = columns[i] ?? '';
      if (INPUT_LENGTH_COLUMNS.has(c)) return lengthIn(text, unit, true);
      if (RESULT_LENGTH_COLUMNS.has(c)) return lengthIn(text, unit, false);
      return text;
    });
    return [...converted, ...fields.slice(count)].join(',');
  });
  return `${[header, ...lines].join('\n')}\n`;
}
