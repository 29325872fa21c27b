/**
 * The worker's `solve` job for a doubly curved point (issue 19): every number of the exact answer
 * from the surface registry's doubly curved model at the five-axis mode's posture (core
 * surfaces/doublyCurvedPoint.ts over question.ts posturedModel: issue 27 point 3, every surface
 * through its SurfaceModel, a machine mode a posture supplier): the step-over and cusps, the
 * limits, the widest step-over, the sliders' limits, the roughness along the normal (a target Ra
 * first comes to the scallop height that leaves it, doublyCurvedHeightForRaMm) and, forward, the
 * comparison rows (the plane, each cylinder, the usual correction). A straight radius is the
 * cylinder's or the plane's answer (models/doublyCurved.ts). The model loads on first use with this
 * job (jobs/page.ts `ready`, which the worker awaits before its first answer). The request is
 * validated again (the tool and posture as validate.ts does, then this point's own checks): a bad
 * request gets a typed error reply, never an exception.
 */

import { TOOL_FIELDS } from '../../core/input/fields';
import { rawOf } from '../../core/input/raw';
import { type InputError, inputError, MIN_LENGTH_MM } from '../../core/input/validate';
import { compareAtPoint } from '../../core/procedures/compareDoublyCurved';
import {
  doublyCurvedHeightForRaMm,
  doublyCurvedRoughness,
  doublyCurvedRoughnessAtInterval,
} from '../../core/roughness/doublyCurved';
import { roughnessSummary } from '../../core/roughness/raTarget';
import { curvedInverse, curvedLimits, curvedPointOf } from '../../core/surfaces/doublyCurvedPoint';
import type { ExactForward, ExactInverse } from '../../core/surfaces/surface';
import { validatePassAnd } from '../../core/surfaces/validate';
import { curvedErrors, curvedSliderLimits } from '../data/curvedCheck';
import { curvedSceneGeometry } from '../data/curvedScene';
import { finiteLimits } from '../data/sliderLimits';
import type { CurvedError, CurvedReply, CurvedRequest, CurvedSummary } from '../pageProtocol';

/** The request's errors (the tool's, then the point's), or null when it is valid. */
export function revalidateCurved(request: CurvedRequest): readonly (InputError | CurvedError)[] | null {
  const i = request.input;
  const [field, value] =
    request.mode === 'curved-forward'
      ? (['h', request.input.scallopHeightMm] as const)
      : request.mode === 'curved-ra'
        ? (['ra', request.input.targetRaMm] as const)
        : (['interval', request.input.intervalMm] as const);
  const v = validatePassAnd({ ...rawOf(i, TOOL_FIELDS), pattern: i.pattern, [field]: value }, field);
  if (v.errors.length > 0) return v.errors as InputError[];
  const min = field === 'interval' ? 2 * MIN_LENGTH_MM : MIN_LENGTH_MM;
  if (!(value >= min)) return [inputError(field, value > 0 ? 'too-small' : 'not-positive', String(value), min)];
  const question = field === 'h' ? { h: value } : field === 'ra' ? { ra: value } : { interval: value };
  const errors = curvedErrors(i, i, i.pattern, question);
  return errors.length > 0 ? errors : null;
}

/**
 * True for an error after which a point has no sliders' limits: a validation error (the radii are
 * checked only after it), a radius out of range or gouging.
 */
function noLimits(e: InputError | CurvedError): boolean {
  return 'got' in e || e.field === 'feedRadius' || e.field === 'crossRadius';
}

/** The exact answer's numbers a reply carries, forward or inverse (mm). */
function exactNumbers(e: ExactForward | ExactInverse) {
  return {
    intervalMm: e.intervalMm,
    halfWidthRightMm: e.halfWidthRightMm,
    halfWidthLeftMm: e.halfWidthLeftMm,
    contactOffsetMm: e.contactOffsetMm,
    cuspHeightMm: e.cuspHeightMm,
    otherCuspHeightMm: e.otherCuspHeightMm,
  };
}

/** Solves a doubly curved request. Never throws for any numeric input. */
export function solveCurved(request: CurvedRequest): CurvedReply {
  const t0 = performance.now();
  const errors = revalidateCurved(request);
  const i = request.input;
  // The point through the registries, for the sliders' limits (beside a refusal of h, L or Ra too),
  // the answer and the roughness: unless the tool or the radii were refused (checked once, above).
  const point = (errors ?? []).some(noLimits) ? null : curvedPointOf(i);
  const sliderLimits =
    point === null ? null : finiteLimits(() => curvedSliderLimits(point, request.mode === 'curved-ra'));
  if (errors !== null || point === null) return { ok: false, request, errors: errors ?? [], limits: sliderLimits };
  const { model, tool, surface, pattern } = point;
  const limits = curvedLimits(point);
  const maxIntervalMm = sliderLimits?.intervalMm ?? model.maxIntervalMm(tool, pattern, surface);
  if (request.mode !== 'curved-inverse') {
    const hMm =
      request.mode === 'curved-forward'
        ? request.input.scallopHeightMm
        : doublyCurvedHeightForRaMm(point, request.input.targetRaMm);
    const f = model.forward({ ...tool, pattern, surface, scallopHeightMm: hMm });
    const exact = exactNumbers(f);
    // The rows beside it, from the answer and widest step-over just found (not solved again).
    const {
      exact: _exact,
      maxIntervalMm: _max,
      ...comparison
    } = compareAtPoint({ ...i, scallopHeightMm: hMm }, point, f, maxIntervalMm);
    const summary = { ...exact, pattern: i.pattern, maxIntervalMm, limits };
    return {
      ok: true,
      request,
      limits: sliderLimits,
      exact: summary,
      comparison,
      roughness: roughnessSummary(doublyCurvedRoughness(point, f), exact.cuspHeightMm),
      scene: curvedSceneGeometry(i, summary),
      solveMs: performance.now() - t0,
    };
  }
  const e = curvedInverse(point, request.input.intervalMm);
  const exact: CurvedSummary = { pattern: i.pattern, ...exactNumbers(e), maxIntervalMm, limits };
  return {
    ok: true,
    request,
    limits: sliderLimits,
    exact,
    comparison: null,
    roughness: roughnessSummary(doublyCurvedRoughnessAtInterval(point, e), e.cuspHeightMm),
    scene: curvedSceneGeometry(i, exact),
    solveMs: performance.now() - t0,
  };
}
