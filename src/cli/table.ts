/**
 * Plain-text tables for the terminal: numbers with significant digits (never `-0`, never NaN),
 * columns sized to their widest cell so they stay apart for any magnitude. Pure.
 */
import { formatPercent, formatSignificant } from '../core/index';

/** Significant digits of every length in the table (issue: at least 6). */
export const TABLE_DIGITS = 7;

/** Shown in a cell that has no value (not applicable, not defined). */
export const NONE = '-';

/** Below this magnitude (mm) lengths switch to exponent notation: 1.234568e-5, not 0.00001234568. */
const EXPONENT_BELOW = 1e-4;

/** A length (mm) with {@link TABLE_DIGITS} significant digits. */
export function length(mm: number): string {
  return formatSignificant(mm, { digits: TABLE_DIGITS, exponentBelow: EXPONENT_BELOW });
}

/** A signed deviation (mm): `+` before positive values, never `-0`. */
export function deviation(mm: number): string {
  return formatSignificant(mm, { digits: TABLE_DIGITS, signed: true, exponentBelow: EXPONENT_BELOW });
}

/** A signed percentage with 2 decimals, never `-0.00`. */
export function percent(value: number | null): string {
  return value === null ? NONE : formatPercent(value, 2);
}

/** An input value as given (shortest text that reads back to the same number). */
export function echo(value: number): string {
  return Object.is(value, -0) ? '0' : String(value);
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
