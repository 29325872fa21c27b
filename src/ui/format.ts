/**
 * Numbers as the page shows them, on top of the core's units module: lengths in the user's unit
 * to a fixed resolution (0.1 um in mm, 10 uin in inch; heights one digit finer, the stepper's
 * convergence two finer) and never fewer than four significant digits, so a micro tool reads
 * 4.472e-5 rather than 0.0000. Never NaN, never -0: a missing value is a dash.
 */
import {
  formatPercent,
  formatSignificant,
  fromMm,
  type LengthUnit,
  NO_VALUE,
  radToDeg,
  readableLengthUnit,
} from '../core/input/units';

export type Resolution = 'length' | 'height' | 'fine';

const DECIMALS: Readonly<Record<Resolution, Readonly<Record<LengthUnit, number>>>> = {
  length: { mm: 4, in: 5 },
  height: { mm: 5, in: 6 },
  fine: { mm: 6, in: 7 },
};

/**
 * Significant digits that give `decimals` decimals for `value`, at least four. The magnitude is
 * taken after rounding to those decimals, so a value just below a power of ten that rounds up to it
 * (9.99999999 at 3 decimals: 10.000) keeps the same decimals as one just above it.
 */
function digitsFor(value: number, decimals: number): number {
  const magnitude = Math.abs(value);
  if (magnitude === 0) return decimals + 1;
  const rounded = decimals <= 100 ? Number(magnitude.toFixed(decimals)) : magnitude;
  return Math.max(4, decimals + Math.floor(Math.log10(rounded > 0 ? rounded : magnitude)) + 1);
}

/** A length given in mm, in `unit` (no symbol); a dash for null or a non-finite value. */
export function formatLen(mm: number | null, unit: LengthUnit, resolution: Resolution = 'length'): string {
  if (mm === null || !Number.isFinite(mm)) return NO_VALUE;
  const v = fromMm(mm, unit);
  return formatSignificant(v, { digits: digitsFor(v, DECIMALS[resolution][unit]) });
}

/** A signed length difference (`+` before positive values). */
export function formatSignedLen(mm: number | null, unit: LengthUnit, resolution: Resolution = 'length'): string {
  if (mm === null || !Number.isFinite(mm)) return NO_VALUE;
  const v = fromMm(mm, unit);
  return formatSignificant(v, { digits: digitsFor(v, DECIMALS[resolution][unit]), signed: true });
}

/**
 * A length with its unit symbol, in the unit it reads best in (readableLengthUnit: below 0.1 mm in
 * µm, below 0.01 in in thou) at the same resolution and at least four significant digits; a dash
 * alone when there is no value. `signed` puts `+` before positive values.
 */
export function formatLenUnit(
  mm: number | null,
  unit: LengthUnit,
  resolution: Resolution = 'length',
  signed = false,
): string {
  if (mm === null || !Number.isFinite(mm)) return NO_VALUE;
  const shown = readableLengthUnit(mm, unit);
  const v = fromMm(mm, unit) * shown.perUserUnit;
  const decimals = Math.max(0, DECIMALS[resolution][unit] - Math.round(Math.log10(shown.perUserUnit)));
  return `${formatSignificant(v, { digits: digitsFor(v, decimals), signed })} ${shown.symbol}`;
}

/** A signed length with its unit symbol (formatLenUnit with `+` before positive values). */
export function formatSignedLenUnit(mm: number | null, unit: LengthUnit, resolution: Resolution = 'length'): string {
  return formatLenUnit(mm, unit, resolution, true);
}

/**
 * A signed percentage (a deviation against exact) with two decimals: `+` before positive values,
 * `-` before negative ones, and a value that rounds to zero reads `0.00` (never `-0.00` or
 * `+0.00`); a dash for null or a non-finite value. No `%` sign (the caption or title carries it).
 */
export function formatSignedPercent(percent: number | null): string {
  return percent === null ? NO_VALUE : formatPercent(percent, 2);
}

/** An angle in degrees for captions: up to 6 significant digits, no trailing zeros. */
export function formatDeg(deg: number): string {
  return formatSignificant(deg, { digits: 6, trimZeros: true, exponentBelow: 1e-4 });
}

/** An angle given in radians, in degrees with two decimals (captions of the step-through). */
export function formatRadAsDeg(rad: number): string {
  const deg = radToDeg(rad);
  return `${formatSignificant(deg, { digits: Math.max(3, digitsFor(deg, 2)) })} deg`;
}

export { NO_VALUE };
