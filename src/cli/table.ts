/**
 * Plain-text tables for the terminal: numbers with significant digits (never `-0`, never NaN),
 * columns sized to their widest cell so they stay apart for any magnitude. Pure.
 */
import { formatPercent, formatSignificant } from '../core/index';
import { fromMm, type LengthUnit, unitSymbol } from '../core/input/units';

/** Significant digits of every length in the table (issue: at least 6). */
export const TABLE_DIGITS = 7;

/** Shown in a cell that has no value (not applicable, not defined). */
export const NONE = '-';

/** Tables never write exponent notation (issue 26 point 10): 0.00006713918, not 6.713918e-5. */
const EXPONENT_BELOW = 0;

/** A length (mm) with {@link TABLE_DIGITS} significant digits. */
export function length(mm: number): string {
  return formatSignificant(mm, { digits: TABLE_DIGITS, exponentBelow: EXPONENT_BELOW });
}

/** A signed deviation (mm): `+` before positive values, never `-0`. */
export function deviation(mm: number): string {
  return formatSignificant(mm, { digits: TABLE_DIGITS, signed: true, exponentBelow: EXPONENT_BELOW });
}

/**
 * Lengths in the user's unit for a table: each converted once from its mm double, and the unit's
 * symbol for the labels (`mm` or `in`).
 */
export interface Lengths {
  /** The unit's symbol. */
  readonly u: string;
  /** A length with {@link TABLE_DIGITS} significant digits. */
  length(mm: number): string;
  /** A signed length difference. */
  deviation(mm: number): string;
  /** An input length as given (the shortest text that reads back to the same number, in the unit). */
  echo(mm: number): string;
}

/**
 * An input length given in `unit` and held in mm, back in `unit` as typed: rounded to 12
 * significant digits (0.5 in is 12.7 mm and reads back 0.5, not 0.49999999999999994), as the
 * page's lookup table writes its inputs in inches.
 */
export function inputIn(lengthMm: number, unit: LengthUnit): number {
  return Number(fromMm(lengthMm, unit).toPrecision(12));
}

/** The table's lengths in `unit` (see {@link Lengths}). */
export function lengthsIn(unit: LengthUnit): Lengths {
  return {
    u: unitSymbol(unit),
    length: (mm) => length(fromMm(mm, unit)),
    deviation: (mm) => deviation(fromMm(mm, unit)),
    echo: (mm) => echo(unit === 'mm' ? mm : inputIn(mm, unit)),
  };
}

/** A signed percentage with 2 decimals, never `-0.00`. */
export function percent(value: number | null): string {
  return value === null ? NONE : formatPercent(value, 2);
}

/**
 * An input value as given: the shortest text that reads back to the same number, written as a
 * plain decimal (1e-9 as 0.000000001: tables never use exponent notation).
 */
export function echo(value: number): string {
  const text = Object.is(value, -0) ? '0' : String(value);
  const m = /^(-?)(\d+)(?:\.(\d+))?e([+-]\d+)$/.exec(text);
  if (m === null) return text;
  const [, sign = '', whole = '', fraction = '', exponent = '0'] = m;
  const digits = whole + fraction;
  const point = whole.length + Number(exponent);
  if (point <= 0) return `${sign}0.${'0'.repeat(-point)}${digits}`;
  if (point >= digits.length) return `${sign}${digits}${'0'.repeat(point - digits.length)}`;
  return `${sign}${digits.slice(0, point)}.${digits.slice(point)}`;
}

export interface Column {
  readonly header: string;
  /** Numbers align right, text left. */
  readonly align: 'left' | 'right';
}

/** Spaces between columns. */
export const GAP = 2;

/**
 * Lines of a table: each column as wide as its widest cell (header included), separated by
 * {@link GAP} spaces; no trailing spaces. A row may be shorter than the columns (empty cells).
 */
export function renderTable(columns: readonly Column[], rows: readonly (readonly string[])[], header = true): string[] {
  const all = header ? [columns.map((c) => c.header), ...rows] : rows;
  const widths = columns.map((_, j) => Math.max(0, ...all.map((r) => (r[j] ?? '').length)));
  return all.map((row) => {
    const cells = columns.map((c, j) => {
      const text = row[j] ?? '';
      const width = widths[j] as number;
      return c.align === 'right' ? text.padStart(width) : text.padEnd(width);
    });
    return cells.join(' '.repeat(GAP)).trimEnd();
  });
}
