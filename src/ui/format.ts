/**
 * Numbers as the page shows them, on top of the core's units module: lengths in the user's unit
 * to a fixed resolution (0.1 µm in mm, 10 µin in inch; heights one digit finer, the stepper's
 * convergence two finer) and never fewer than four significant digits. Never NaN, never -0: a
 * missing value is a dash.
 *
 * The page's one rule for a length it shows (issue 21, "Units everywhere"): every length carries
 * its unit ({@link formatLenUnit}: mm or in, µm below 0.1 mm, thou below 0.01 in, never exponent
 * notation), and every roughness Rz, Ra, Rq is in µm in mm and in µin in inch
 * ({@link formatRoughness}, at the heights' resolution); every computed angle has two decimals
 * ({@link formatAngle}); a field's number has the fewest digits that give it ({@link formatField},
 * which fieldText.ts's conversions use). The micro sign is U+00B5 (`µm`, `µin`) everywhere. The bare number
 * ({@link formatLen}) is for what is copied, where the unit is the page's (copy.ts), and for
 * cells under a header that names the unit.
 */
import {
  formatPercent,
  formatSignificant,
  fromMm,
  type LengthUnit,
  NO_VALUE,
  radToDeg,
  readableLengthUnit,
  roughnessUnit,
} from '../core/input/units';

export type Resolution = 'length' | 'height' | 'fine';

/**
 * Below this magnitude, in the unit a length or roughness is shown in, it reads as zero: a length
 * or a deviation of 1e-10 µm (1e-13 mm) is float noise of the solvers, and plain decimals of it
 * would run to dozens of zeros.
 */
const SHOWN_ZERO_BELOW = 1e-10;

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

/** {@link formatLen} at the fine resolution in plain decimals, never exponent notation (1 nm: 0.0000010000 mm). */
export function formatFineLen(mm: number | null, unit: LengthUnit): string {
  if (mm === null || !Number.isFinite(mm)) return NO_VALUE;
  const v = fromMm(mm, unit);
  return formatSignificant(v, { digits: digitsFor(v, DECIMALS.fine[unit]), exponentBelow: 0 });
}

/** A signed length difference (`+` before positive values). */
export function formatSignedLen(mm: number | null, unit: LengthUnit, resolution: Resolution = 'length'): string {
  if (mm === null || !Number.isFinite(mm)) return NO_VALUE;
  const v = fromMm(mm, unit);
  return formatSignificant(v, { digits: digitsFor(v, DECIMALS[resolution][unit]), signed: true });
}

/**
 * A length with its unit symbol, in the unit it reads best in (readableLengthUnit: below 0.1 mm in
 * µm, below 0.01 in in thou) at the same resolution and at least four significant digits, in plain
 * decimals (never exponent notation: 1.981e-7 mm reads `0.1981 µm`); zero reads in the user's unit,
 * never `-0`; a dash alone when there is no value. `signed` puts `+` before positive values.
 */
export function formatLenUnit(
  mm: number | null,
  unit: LengthUnit,
  resolution: Resolution = 'length',
  signed = false,
): string {
  if (mm === null || !Number.isFinite(mm)) return NO_VALUE;
  if (mm !== 0 && Math.abs(fromMm(mm, unit)) * 1000 < SHOWN_ZERO_BELOW)
    return formatLenUnit(0, unit, resolution, signed);
  const shown = readableLengthUnit(mm, unit);
  const v = fromMm(mm, unit) * shown.perUserUnit;
  const decimals = Math.max(0, DECIMALS[resolution][unit] - Math.round(Math.log10(shown.perUserUnit)));
  return `${formatSignificant(v, { digits: digitsFor(v, decimals), signed, exponentBelow: 0 })} ${shown.symbol}`;
}

/**
 * A roughness (Rz, Ra, Rq, or a height compared with them) given in mm, with its symbol: in µm
 * when the user works in mm and in µin in inch (roughnessUnit), whatever its size, at the
 * resolution of every height on the page (`height`: 0.01 µm, 1 µin), so Rz of a 0.05 mm scallop
 * reads `50.00 µm` as the scallop itself does in the table; at least four significant digits,
 * plain decimals, never `-0`; a dash for null or a non-finite value. Used by the results'
 * roughness rows and the Machined surface view alike.
 */
export function formatRoughness(mm: number | null, unit: LengthUnit): string {
  if (mm === null || !Number.isFinite(mm)) return NO_VALUE;
  const shown = roughnessUnit(unit);
  const v = Math.abs(mm * shown.perMm) < SHOWN_ZERO_BELOW ? 0 : mm * shown.perMm;
  const decimals = Math.max(0, DECIMALS.height[unit] - Math.round(Math.log10(shown.perMm / fromMm(1, unit))));
  return `${formatSignificant(v, { digits: digitsFor(v, decimals), exponentBelow: 0 })} ${shown.symbol}`;
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

/**
 * An angle the user gave, echoed in a caption or a title (`rho = 5`, a sheet's 30 column): as its
 * field writes it (up to 6 significant digits, no trailing zeros). A computed angle is
 * {@link formatAngle}'s.
 */
export function formatDeg(deg: number): string {
  return formatSignificant(deg, { digits: 6, trimZeros: true, exponentBelow: 1e-4 });
}

/** The decimals of every computed angle the page shows (0.01 deg). */
export const ANGLE_DECIMALS = 2;

/**
 * A computed angle (the equivalent lead and tilt, the step-through's gamma) with its symbol: always
 * {@link ANGLE_DECIMALS} decimals, so angles side by side read alike (`27.31 deg` beside
 * `12.92 deg`); never `-0.00`; a dash for null or a non-finite value.
 */
export function formatAngle(deg: number | null): string {
  if (deg === null || !Number.isFinite(deg)) return NO_VALUE;
  const text = Math.abs(deg).toFixed(ANGLE_DECIMALS);
  return `${deg < 0 && !/^[0.]+$/.test(text) ? '-' : ''}${text} deg`;
}

/** An angle given in radians, in degrees as {@link formatAngle} gives it (captions of the step-through). */
export function formatRadAsDeg(rad: number): string {
  return formatAngle(radToDeg(rad));
}

/**
 * Two numbers closer than this, relative to their size, are the same number written twice: the
 * float noise of a conversion or of a sum (1e-16 to 1e-14) lies far below it, and a typed value
 * (at most 11 significant digits) differs from every other value of as many digits by far more.
 */
const SAME_NUMBER = 1e-12;

/** A number with `digits` significant digits as a field writes it (no trailing zeros, no exponent for usual sizes). */
export function fieldDigits(value: number, digits: number): string {
  return formatSignificant(value, { digits, trimZeros: true, exponentBelow: 1e-5 });
}

/**
 * Formats a number for a field: the fewest significant digits that give the number itself (within
 * float noise, {@link SAME_NUMBER}), so `0.762` not `0.7619999999999999` and `0.5` not `0.500000`,
 * and nothing is lost (a tool's 0.1181102362205 in stays that); no exponent for usual sizes. Empty
 * for a non-finite value.
 */
export function formatField(value: number): string {
  if (!Number.isFinite(value)) return '';
  for (let digits = 1; digits < 17; digits++) {
    const text = fieldDigits(value, digits);
    if (Math.abs(Number(text) - value) <= SAME_NUMBER * Math.abs(value)) return text;
  }
  return fieldDigits(value, 17);
}

export { NO_VALUE };
