/**
 * Input validation for the path-interval solvers.
 *
 * Never throws and never yields NaN: every input is either accepted as finite
 * numbers inside the solvers' domain or rejected with one typed error per
 * offending field, whose message names the constraint in a machinist's terms.
 */

/** Names of the user-facing inputs, as the paper writes them. */
export type FieldName = 'R' | 'Rcr' | 'rho' | 'h' | 'halfInterval';

/** Why a field was rejected. */
export type InputErrorCode =
  | 'missing'
  | 'not-a-number'
  | 'not-finite'
  | 'not-positive'
  | 'negative'
  | 'too-large'
  | 'too-small'
  | 'out-of-range'
  | 'corner-exceeds-radius'
  | 'beyond-corner'
  | 'beyond-radius';

/** One rejected field. `message` is meant to be shown to the user as it is. */
export interface InputError {
  readonly field: FieldName;
  readonly code: InputErrorCode;
  readonly message: string;
}

/** Either the accepted value or the list of errors (at most one per field). */
export type Validation<T> =
  | { readonly ok: true; readonly value: T }
  | { readonly ok: false; readonly errors: readonly InputError[] };

/** A validated tool: lengths in mm, lead angle in degrees. */
export interface ToolInput {
  /** Tool radius `R` in mm, {@link MIN_TOOL_RADIUS_MM} <= R <= {@link MAX_TOOL_RADIUS_MM}. */
  readonly toolRadiusMm: number;
  /** Corner (tip) radius `Rcr` in mm, 0 <= Rcr <= R. */
  readonly cornerRadiusMm: number;
  /** Lead angle `rho` (inclination along the feed) in degrees, 0 <= rho < 90. */
  readonly leadAngleDeg: number;
}

/** Input of the forward problem: scallop height to path interval. */
export interface ForwardInput extends ToolInput {
  /** Scallop height `h` in mm, 0 < h < (R - Rcr) sin(rho) + Rcr. */
  readonly scallopHeightMm: number;
}

/** Input of the inverse problem: path interval to scallop height. */
export interface InverseInput extends ToolInput {
  /** Half path interval `L/2` in mm, 0 < L/2 < R. */
  readonly halfIntervalMm: number;
}

/** Raw values as they come from a form, a URL or a CSV cell. */
export interface RawToolInput {
  readonly R: unknown;
  readonly Rcr: unknown;
  readonly rho: unknown;
}
export interface RawForwardInput extends RawToolInput {
  readonly h: unknown;
}
export interface RawInverseInput extends RawToolInput {
  readonly halfInterval: unknown;
}

/**
 * Largest tool radius accepted, in mm. No end mill is this large; the bound keeps
 * every intermediate product far from overflow.
 */
export const MAX_TOOL_RADIUS_MM = 1000;

/** Smallest tool radius accepted, in mm (the smallest micro end mills are 0.005 mm across). */
export const MIN_TOOL_RADIUS_MM = 0.001;

/**
 * Smallest scallop height and half interval accepted, in mm: one nanometre, far below any
 * measurable scallop, so every result stays a normal floating-point number.
 */
export const MIN_LENGTH_MM = 1e-9;

const DEG = Math.PI / 180;

/** A strict decimal number: optional sign, digits with an optional point, optional exponent. */
const NUMBER_PATTERN = /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/;

type Parsed = { ok: true; value: number } | { ok: false; code: InputErrorCode; shown: string };

function parseNumber(raw: unknown): Parsed {
  if (raw === undefined || raw === null) return { ok: false, code: 'missing', shown: '' };
  if (typeof raw === 'number') {
    if (Number.isNaN(raw)) return { ok: false, code: 'not-a-number', shown: 'NaN' };
    if (!Number.isFinite(raw)) return { ok: false, code: 'not-finite', shown: String(raw) };
    return { ok: true, value: raw };
  }
  if (typeof raw !== 'string') return { ok: false, code: 'not-a-number', shown: typeof raw };
  const text = raw.trim();
  if (text === '') return { ok: false, code: 'missing', shown: '' };
  if (!NUMBER_PATTERN.test(text)) return { ok: false, code: 'not-a-number', shown: text };
  const value = Number(text);
  if (!Number.isFinite(value)) return { ok: false, code: 'not-finite', shown: text };
  return { ok: true, value };
}

const LABEL: Record<FieldName, string> = {
  R: 'Tool radius R',
  Rcr: 'Corner radius Rcr',
  rho: 'Lead angle rho',
  h: 'Scallop height h',
  halfInterval: 'Half path interval L/2',
};

function shorten(text: string): string {
  return text.length > 24 ? `${text.slice(0, 21)}...` : text;
}

function parseError(field: FieldName, parsed: Extract<Parsed, { ok: false }>): InputError {
  const label = LABEL[field];
  switch (parsed.code) {
    case 'missing':
      return { field, code: 'missing', message: `${label} is missing: enter a number.` };
    case 'not-finite':
      return {
        field,
        code: 'not-finite',
        message: `${label} must be a finite number (got "${shorten(parsed.shown)}").`,
      };
    default:
      return { field, code: 'not-a-number', message: `${label} must be a number (got "${shorten(parsed.shown)}").` };
  }
}

/** Formats a length for a message: up to 6 significant digits, no trailing zeros. */
function mm(value: number): string {
  return `${Number(value.toPrecision(6))} mm`;
}

type Collected = { values: Partial<Record<FieldName, number>>; errors: InputError[] };

function collect(raw: Partial<Record<FieldName, unknown>>, fields: readonly FieldName[]): Collected {
  const out: Collected = { values: {}, errors: [] };
  for (const field of fields) {
    const parsed = parseNumber(raw[field]);
    if (parsed.ok) out.values[field] = parsed.value;
    else out.errors.push(parseError(field, parsed));
  }
  return out;
}

function checkTool(c: Collected): void {
  const { R, Rcr, rho } = c.values;
  const reject = (field: FieldName, code: InputErrorCode, message: string) => {
    c.errors.push({ field, code, message });
    delete c.values[field];
  };
  if (R !== undefined) {
    if (R <= 0) reject('R', 'not-positive', `Tool radius R must be greater than 0 mm (got ${R}).`);
    else if (R < MIN_TOOL_RADIUS_MM)
      reject('R', 'too-small', `Tool radius R must be at least ${MIN_TOOL_RADIUS_MM} mm (got ${R}).`);
    else if (R > MAX_TOOL_RADIUS_MM)
      reject('R', 'too-large', `Tool radius R must be at most ${MAX_TOOL_RADIUS_MM} mm (got ${R}).`);
  }
  if (Rcr !== undefined) {
    if (Rcr < 0) reject('Rcr', 'negative', `Corner radius Rcr must be 0 mm or more (got ${Rcr}).`);
    else if (c.values.R !== undefined && Rcr > c.values.R)
      reject(
        'Rcr',
        'corner-exceeds-radius',
        `Corner radius Rcr must not exceed the tool radius R = ${mm(c.values.R)} (got ${Rcr}); Rcr = R is a ball end mill.`,
      );
  }
  if (rho !== undefined && !(rho >= 0 && rho < 90)) {
    reject('rho', 'out-of-range', `Lead angle rho must be at least 0 and below 90 degrees (got ${rho}).`);
  }
}

/**
 * Height of the widest point of the tool's cross-feed profile above its lowest
 * point, in mm: `(R - Rcr) sin(rho) + Rcr` (geometry notes, "Limits"). A scallop
 * exists only below it.
 *
 * @param toolRadiusMm R in mm; @param cornerRadiusMm Rcr in mm; @param leadAngleDeg rho in degrees.
 */
export function cornerProfileHeightMm(toolRadiusMm: number, cornerRadiusMm: number, leadAngleDeg: number): number {
  return (toolRadiusMm - cornerRadiusMm) * Math.sin(leadAngleDeg * DEG) + cornerRadiusMm;
}

function toolOf(values: Collected['values']): ToolInput {
  return {
    toolRadiusMm: values.R as number,
    cornerRadiusMm: values.Rcr as number,
    leadAngleDeg: values.rho as number,
  };
}

/**
 * Validates the inputs of the forward problem (scallop height `h` to path interval).
 *
 * Rules: `R > 0` (from {@link MIN_TOOL_RADIUS_MM} to {@link MAX_TOOL_RADIUS_MM}), `0 <= Rcr <= R`,
 * `0 <= rho < 90` degrees, `h > 0` (at least {@link MIN_LENGTH_MM}) and `h < (R - Rcr) sin(rho) + Rcr`. Accepts numbers and numeric
 * strings; NaN, Infinity, empty and non-numeric values are rejected.
 */
export function validateForward(raw: RawForwardInput): Validation<ForwardInput> {
  const c = collect(raw, ['R', 'Rcr', 'rho', 'h']);
  checkTool(c);
  const { R, Rcr, rho, h } = c.values;
  if (h !== undefined) {
    if (h <= 0) {
      c.errors.push({
        field: 'h',
        code: 'not-positive',
        message: `Scallop height h must be greater than 0 mm (got ${h}).`,
      });
    } else if (h < MIN_LENGTH_MM) {
      c.errors.push({
        field: 'h',
        code: 'too-small',
        message: `Scallop height h must be at least ${MIN_LENGTH_MM} mm (got ${h}).`,
      });
    } else if (R !== undefined && Rcr !== undefined && rho !== undefined) {
      const limitMm = cornerProfileHeightMm(R, Rcr, rho);
      if (h >= limitMm) {
        c.errors.push({
          field: 'h',
          code: 'beyond-corner',
          message:
            `Scallop height h must be below the corner profile's full height (R - Rcr)*sin(rho) + Rcr = ${mm(limitMm)} (got ${h}); ` +
            'at or above it the tool flank leaves a wall, not a scallop.',
        });
      }
    }
  }
  if (c.errors.length > 0) return { ok: false, errors: c.errors };
  return { ok: true, value: { ...toolOf(c.values), scallopHeightMm: h as number } };
}

/**
 * Validates the inputs of the inverse problem (half path interval `L/2` to scallop height).
 *
 * Rules: the tool rules of {@link validateForward}, and `0 < L/2 < R` (at `L/2 >= R`
 * adjacent passes no longer overlap and leave a wall).
 */
export function validateInverse(raw: RawInverseInput): Validation<InverseInput> {
  const c = collect(raw, ['R', 'Rcr', 'rho', 'halfInterval']);
  checkTool(c);
  const { R, halfInterval } = c.values;
  if (halfInterval !== undefined) {
    if (halfInterval <= 0) {
      c.errors.push({
        field: 'halfInterval',
        code: 'not-positive',
        message: `Half path interval L/2 must be greater than 0 mm (got ${halfInterval}).`,
      });
    } else if (halfInterval < MIN_LENGTH_MM) {
      c.errors.push({
        field: 'halfInterval',
        code: 'too-small',
        message: `Half path interval L/2 must be at least ${MIN_LENGTH_MM} mm (got ${halfInterval}).`,
      });
    } else if (R !== undefined && halfInterval >= R) {
      c.errors.push({
        field: 'halfInterval',
        code: 'beyond-radius',
        message: `Half path interval L/2 must be below the tool radius R = ${mm(R)} (got ${halfInterval}); at or beyond it adjacent passes leave a wall.`,
      });
    }
  }
  if (c.errors.length > 0) return { ok: false, errors: c.errors };
  return { ok: true, value: { ...toolOf(c.values), halfIntervalMm: halfInterval as number } };
}
