/**
 * The page's three-axis question (issue 20): the tool, the slope, the pass strategy, the raster
 * angle (raster) or the surface's radii (waterline), and h forward or the programmed step inverse
 * (Lxy for raster, dz for waterline), validated as the command line does (core validateThreeAxis).
 * The page does not solve it: the worker does, once (jobs/threeAxis.ts), and the refusals only a
 * solver finds (ranges, the vertical wall, the flank and shank limits) come back in its reply, put
 * on their fields by threeAxisFieldErrors. Every message in the user's unit and the language in
 * force (i18n/words.ts describeThreeAxis; English: the core's message). Pure.
 */
import { FIELDS, fieldOfPageKey, pageKeyOf } from '../core/input/fields';
import { formatInputNumber, fromMm, unitSymbol } from '../core/input/units';
import {
  type RawThreeAxisInput,
  type ThreeAxisInputError,
  type ThreeAxisQuantity,
  validateThreeAxis,
} from '../core/threeAxis/validate';
import { radiusMm } from './curvedRequest';
import { catalogue, describeThreeAxis } from './i18n/words';
import { programmedStepKey } from './machineState';
import type { BuiltRequest, PageFieldError } from './requestTypes';
import { type CalculatorState, type FieldKey, fieldInMm } from './state';

/**
 * A core message (mm and degrees) in the user's unit: every `<number> mm` converted, and the value
 * quoted as typed (the core quotes it in mm). Angles stay in degrees.
 */
export function inUnit(message: string, state: CalculatorState, key: FieldKey | null): string {
  const typed = key === null ? null : state.fields[key].trim();
  const withTyped =
    typed === null || typed === ''
      ? message
      : message.replace(/\(got ("?)[^)]*\)/, (_m, q: string) => `(got ${q}${typed.slice(0, 24)}${q})`);
  if (state.unit === 'mm') return withTyped;
  const u = unitSymbol(state.unit);
  return withTyped.replace(
    /(-?\d+(?:\.\d+)?(?:e[+-]?\d+)?) mm\b/gi,
    (_m, n: string) => `${formatInputNumber(fromMm(Number(n), state.unit))} ${u}`,
  );
}

/** A three-axis error on its page field, in the user's unit (R in diameter mode is named D). */
function onField(e: ThreeAxisInputError, state: CalculatorState): PageFieldError | null {
  // The page field of the field it names (the field registry's; null: a switch, such as the passes).
  const key = pageKeyOf(e.field);
  if (key === null) return null;
  const words = describeThreeAxis(e, state.unit, state.fields[key].trim(), state.passes === 'waterline');
  return { key, message: words ?? inUnit(e.message, state, key) };
}

/** Three-axis errors (the validation's, or the worker's reply's) on their page fields, in the user's unit. */
export function threeAxisFieldErrors(errors: readonly ThreeAxisInputError[], state: CalculatorState): PageFieldError[] {
  return errors.flatMap((e) => onField(e, state) ?? []);
}

/**
 * A three-axis state's raw inputs (mm and degrees, by the core's field names): the tool, slope,
 * passes, the raster angle (raster) or the radii (waterline; straight: none). A radius field's own
 * error (missing, not a number, a sign) is pushed on `errors` and the radius left out.
 */
export function threeAxisRaw(state: CalculatorState, errors: PageFieldError[]): RawThreeAxisInput {
  const waterline = state.passes === 'waterline';
  const radius = (key: 'Rf' | 'Rc'): number | undefined => {
    if (!waterline) return undefined;
    const r = radiusMm(state, key);
    if (typeof r !== 'number') {
      errors.push(r);
      return undefined;
    }
    return Number.isFinite(r) ? r : undefined;
  };
  return {
    R: fieldInMm(state, 'R'),
    Rcr: fieldInMm(state, 'Rcr'),
    slope: fieldInMm(state, 'slope'),
    passes: state.passes,
    rasterAngle: waterline ? undefined : fieldInMm(state, 'psi'),
    feedRadius: radius('Rf'),
    crossRadius: radius('Rc'),
  };
}

/** The request of a three-axis state, or why it cannot be asked (each message on its field); not solved here. */
export function buildThreeAxisRequest(state: CalculatorState): BuiltRequest {
  const own: PageFieldError[] = [];
  const forward = state.mode === 'forward';
  // A target Ra or Sa: its field names it.
  if (forward && state.target !== 'h') {
    const symbol = FIELDS[fieldOfPageKey(state.target)].short;
    own.push({
      key: state.target,
      message:
        catalogue()?.said.targetNotOffered(symbol) ??
        `A target ${symbol} is not offered for three-axis machining: give the scallop height h.`,
    });
  }
  const raw = threeAxisRaw(state, own);
  const stepKey = programmedStepKey(state.passes);
  const quantity: ThreeAxisQuantity = forward ? 'h' : state.passes === 'waterline' ? 'stepDown' : 'horizontalStep';
  const value = fieldInMm(state, forward ? 'h' : stepKey);
  const v = validateThreeAxis(raw, quantity, value);
  // The page's own messages first (a field shows the first message that names it).
  const all = [...own, ...threeAxisFieldErrors(v.ok ? [] : v.errors, state)];
  if (!v.ok || all.length > 0) return { ok: false, errors: all };
  return { ok: true, request: { mode: 'three-axis', input: v.value } };
}
