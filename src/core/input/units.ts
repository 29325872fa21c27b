/**
 * Units and number formatting: the one place for degrees, inches and significant digits.
 * Pure (no DOM): used by the core's messages, the command line and the page alike.
 * Lengths are mm inside the program; other units exist only at its edges.
 */

/** Radians per degree. */
export const RAD_PER_DEG = Math.PI / 180;

/** Millimetres per inch (exact, by definition). */
export const MM_PER_INCH = 25.4;

/** A length unit a user can choose. */
export type LengthUnit = 'mm' | 'in';

/** The unit's symbol as printed after a number. */
export function unitSymbol(unit: LengthUnit): string {
  return unit === 'mm' ? 'mm' : 'in';
}

/** A length in mm expressed in `unit`. */
export function fromMm(lengthMm: number, unit: LengthUnit): number {
  return unit === 'mm' ? lengthMm : lengthMm / MM_PER_INCH;
}

/**
 * A length given in `unit` expressed in mm. A finite length stays finite (1e308 in is the largest
 * double in mm, not Infinity), so a range check says its limit rather than "not a finite number".
 */
export function toMm(length: number, unit: LengthUnit): number {
  if (unit === 'mm') return length;
  const mm = length * MM_PER_INCH;
  return Number.isFinite(mm) || !Number.isFinite(length) ? mm : Math.sign(mm) * Number.MAX_VALUE;
}

/** Degrees to radians. */
export function degToRad(angleDeg: number): number {
  return angleDeg * RAD_PER_DEG;
}

/** Radians to degrees. */
export function radToDeg(angleRad: number): number {
  return angleRad / RAD_PER_DEG;
}

/** Shown for a value that does not exist (never NaN, never a stale number). */
export const NO_VALUE = '\u2014';

export interface SignificantOptions {
  /** Significant digits (at least 1). */
  readonly digits: number;
  /** Put a `+` before positive values (deviations). */
  readonly signed?: boolean;
  /** Below this magnitude use exponent notation (default 1e-6); at or above `1e15` always. */
  readonly exponentBelow?: number;
  /** Drop trailing zeros after the decimal point (default false: the digits are kept). */
  readonly trimZeros?: boolean;
}

/**
 * A number with at least `digits` significant digits, in plain decimal notation for usual
 * magnitudes and exponent notation for tiny or huge ones. Never prints `-0`: a value that is
 * zero, or rounds to zero, prints unsigned. Non-finite values print {@link NO_VALUE}.
 */
export function formatSignificant(value: number, options: SignificantOptions): string {
  if (!Number.isFinite(value)) return NO_VALUE;
  const digits = Math.max(1, Math.min(21, Math.round(options.digits)));
  const magnitude = Math.abs(value);
  const exponentBelow = options.exponentBelow ?? 1e-6;
  let text: string;
  if (magnitude === 0) text = digits > 1 && !options.trimZeros ? `0.${'0'.repeat(digits - 1)}` : '0';
  else if (magnitude < exponentBelow || magnitude >= 1e15) {
    text = magnitude.toExponential(digits - 1);
    if (options.trimZeros) text = text.replace(/\.?0+e/, 'e');
  } else {
    const decimals = Math.max(0, digits - 1 - Math.floor(Math.log10(magnitude)));
    text = magnitude.toFixed(Math.min(100, decimals));
    // log10 can sit one below an exact power of ten: keep the digit count honest.
    const sig = text.replace('.', '').replace(/^0+/, '').length;
    if (sig > digits && decimals > 0) text = magnitude.toFixed(decimals - 1);
    if (options.trimZeros && text.includes('.')) text = text.replace(/\.?0+$/, '');
  }
  const roundsToZero = /^[0.]+$/.test(text) || /^0(\.0*)?e/.test(text);
  if (roundsToZero) return text;
  if (value < 0) return `-${text}`;
  return options.signed ? `+${text}` : text;
}

/** A length in `unit` with at least `digits` significant digits (default 5), no unit symbol. */
export function formatLength(lengthMm: number, unit: LengthUnit, digits = 5): string {
  return formatSignificant(fromMm(lengthMm, unit), { digits });
}

/** A signed length difference in `unit` (`+` before positive values). */
export function formatSignedLength(lengthMm: number, unit: LengthUnit, digits = 4): string {
  return formatSignificant(fromMm(lengthMm, unit), { digits, signed: true });
}

/** A signed percentage with `decimals` decimals, never `-0.00`. */
export function formatPercent(percent: number, decimals = 2): string {
  if (!Number.isFinite(percent)) return NO_VALUE;
  const text = Math.abs(percent).toFixed(decimals);
  if (/^[0.]+$/.test(text)) return text;
  return percent < 0 ? `-${text}` : `+${text}`;
}

/** An angle in degrees for messages: up to 6 significant digits, no trailing zeros. */
export function formatAngleDeg(angleDeg: number): string {
  return formatSignificant(angleDeg, { digits: 6, trimZeros: true, exponentBelow: 1e-4 });
}

/**
 * A number for a field or a message: up to 6 significant digits, trailing zeros dropped,
 * exponent notation only for very small or large magnitudes (so `0.762` not `0.7619999999999999`).
 */
export function formatInputNumber(value: number): string {
  return formatSignificant(value, { digits: 6, trimZeros: true, exponentBelow: 1e-5 });
}

/** How a length reads best: in the user's unit, or in its small sub-unit (um for mm, thou for inch). */
export interface ReadableLengthUnit {
  /** The symbol printed after the number: `mm`, `µm`, `in` or `thou`. */
  readonly symbol: string;
  /** Multiplies a value in the user's unit into this unit (1, or 1000 for the sub-unit). */
  readonly perUserUnit: number;
}

/**
 * Below this magnitude, in the user's unit, a length reads better in the sub-unit: 0.1 mm
 * (shown as 100 µm and less) and 0.01 in (10 thou and less, 1 thou = 0.001 in), so a scallop of
 * 0.05 mm reads `50.00 µm` and one of 0.0002 in `0.2000 thou`, while a step-over of 2.9 mm stays in mm.
 */
export const SUB_UNIT_BELOW: Readonly<Record<LengthUnit, number>> = { mm: 0.1, in: 0.01 };

/** The micrometre's symbol, with the micro sign (U+00B5) as everywhere on the page. */
export const MICROMETRE_SYMBOL = '\u00b5m';

/** The microinch's symbol, with the micro sign (U+00B5). */
export const MICROINCH_SYMBOL = '\u00b5in';

/**
 * The unit roughness (Rz, Ra, Rq) is given in, for a user working in `unit`: µm in mm, µin in
 * inch (the US shop convention: surface finish callouts are in microinches). Always that unit,
 * whatever the size, so that every roughness on a page compares at a glance.
 */
export function roughnessUnit(unit: LengthUnit): { readonly symbol: string; readonly perMm: number } {
  return unit === 'mm'
    ? { symbol: MICROMETRE_SYMBOL, perMm: 1000 }
    : { symbol: MICROINCH_SYMBOL, perMm: 1e6 / MM_PER_INCH };
}

/** The unit a length given in mm reads best in, for a user working in `unit` (zero stays in `unit`). */
export function readableLengthUnit(lengthMm: number, unit: LengthUnit): ReadableLengthUnit {
  const magnitude = Math.abs(fromMm(lengthMm, unit));
  if (magnitude > 0 && magnitude < SUB_UNIT_BELOW[unit])
    return { symbol: unit === 'mm' ? MICROMETRE_SYMBOL : 'thou', perUserUnit: 1000 };
  return { symbol: unitSymbol(unit), perUserUnit: 1 };
}
