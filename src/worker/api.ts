/**
 * The solver API that runs inside the Web Worker: one function per job, plain data in and out,
 * so it is tested in Node directly and exposed unchanged (rpc.ts) in solver.worker.ts.
 *  - `solve`: the exact answer, every procedure beside it, and the 3D scene's geometry;
 *  - `teach`: the teaching views' data (profiles, sweeps, the traced procedure, formulas' models).
 * Every reply echoes its request. Inputs are validated again here: a bad request gets a typed
 * error reply, never an exception.
 */
import {
  type Approximation,
  bediHalfInterval,
  bediModel,
  cornerBallHalfInterval,
  cornerBallModel,
  osculatingHalfInterval,
  osculatingModel,
  redonnetHalfInterval,
  redonnetModel,
  sekineHalfInterval,
  sekineModel,
} from '../core/approximations';
import {
  CORRECTED_KEYS,
  type CorrectedKey,
  type CurvatureComparison,
  compareForward,
  compareInverse,
  type ForwardEstimate,
  type InverseEstimate,
} from '../core/compare';
import { type CylinderSurface, revolvedProfile, type Surface } from '../core/cylinder';
import { exactForward } from '../core/exact';
import { cuspSection, intersectionLoops } from '../core/geometry';
import { placeTool, ringTangent, sectionCentre } from '../core/placement';
import { contactOffsetMm, type Flank, flankAtHeight, shapeOfTool } from '../core/posture';
import { APPROXIMATION_KEYS, type ApproximationKey, CURVATURE_ROWS, type CurvatureRowKey } from '../core/procedures';
import { forwardOfRaTarget, roughnessSummary, validateRaTarget } from '../core/raTarget';
import { exactRoughness, exactRoughnessAtInterval, type Roughness } from '../core/roughness';
import { surfacePoint, toSurfaceSection } from '../core/surfaceGeometry';
import { type PaperTableRow, paperTables, profileCurves, stepOverSweep } from '../core/teaching';
import { toolMesh } from '../core/toolMesh';
import { traceProcedure } from '../core/trace';
import {
  type ForwardInput,
  forwardInput,
  type InputError,
  type InverseInput,
  MIN_LENGTH_MM,
  maxIntervalMm,
  type ToolInput,
  validateForward,
  validateInverse,
} from '../core/validate';
import {
  type CurvatureRow,
  type Cusp,
  type CuspGeometry,
  type CylinderCurves,
  type ExactSummary,
  LOOP_SAMPLES,
  type Loops,
  type ProcedureNote,
  type ProcedureRow,
  type SceneGeometry,
  type SolveReply,
  type SolveRequest,
  type Sweep,
  type TeachData,
  type TeachReply,
  TOOL_RADIAL_SEGMENTS,
  type TraceFrame,
} from './protocol';
import { table } from './table';

/** The request's input validated again (the worker trusts no caller), or its errors. */
export function revalidate(request: SolveRequest): readonly InputError[] | null {
  const i = request.input;
  const tool = {
    R: i.toolRadiusMm,
    Rcr: i.cornerRadiusMm,
    rho: i.leadAngleDeg,
    tilt: i.tiltAngleDeg,
    pattern: i.pattern,
  };
  const surface = surfaceFields(i.surface);
  const v =
    request.mode === 'forward'
      ? validateForward({ ...tool, ...surface, h: request.input.scallopHeightMm })
      : request.mode === 'ra'
        ? validateRaTarget({ ...tool, ...surface, ra: request.input.targetRaMm })
        : validateInverse({ ...tool, ...surface, interval: request.input.intervalMm });
  return v.ok ? null : v.errors;
}

/** A surface as the validators' raw fields (a plane gives none). */
function surfaceFields(s: Surface): { surfaceRadius?: number; surfaceAxis?: string } {
  return s.kind === 'plane' ? {} : { surfaceRadius: s.radiusMm, surfaceAxis: s.axis };
}

function exactOfForward(input: ForwardInput, c: ReturnType<typeof compareForward>): ExactSummary {
  const e = c.exact;
  const h = e.cuspHeightMm;
  const L = e.intervalMm;
  let right: Cusp;
  let left: Cusp;
  if (input.pattern === 'one-way') {
    right = { yMm: e.halfWidthRightMm, heightMm: h };
    left = { yMm: -e.halfWidthLeftMm, heightMm: h };
  } else {
    // Zigzag: the narrower flank meets its mirror at h, the wider one lower (both at L/2).
    const other = e.otherCuspHeightMm ?? h;
    const rightNarrower = e.halfWidthRightMm <= e.halfWidthLeftMm;
    right = { yMm: L / 2, heightMm: rightNarrower ? h : other };
    left = { yMm: -L / 2, heightMm: rightNarrower && e.halfWidthRightMm !== e.halfWidthLeftMm ? other : h };
  }
  return {
    pattern: input.pattern,
    intervalMm: L,
    halfIntervalMm: e.halfIntervalMm,
    widthRightMm: e.halfWidthRightMm,
    widthLeftMm: e.halfWidthLeftMm,
    contactOffsetMm: e.contactOffsetMm,
    cuspHeightMm: h,
    otherCuspHeightMm: e.otherCuspHeightMm,
    right,
    left,
    noScallop: e.noScallop,
    maxIntervalMm: c.maxIntervalMm,
  };
}

function exactOfInverse(input: InverseInput, c: ReturnType<typeof compareInverse>): ExactSummary {
  const e = c.exact;
  const L = e.intervalMm;
  const zigzag = input.pattern === 'zigzag';
  return {
    pattern: input.pattern,
    intervalMm: L,
    halfIntervalMm: L / 2,
    widthRightMm: e.halfWidthRightMm,
    widthLeftMm: e.halfWidthLeftMm,
    contactOffsetMm: e.contactOffsetMm,
    cuspHeightMm: e.cuspHeightMm,
    otherCuspHeightMm: e.otherCuspHeightMm,
    right: { yMm: zigzag ? L / 2 : e.halfWidthRightMm, heightMm: e.rightCuspHeightMm },
    left: { yMm: zigzag ? -L / 2 : -e.halfWidthLeftMm, heightMm: e.leftCuspHeightMm },
    noScallop: false,
    maxIntervalMm: maxIntervalMm(input, input.pattern, input.surface),
  };
}

/** Each approximation's model: its radius (circles) or ellipse, or why it has none. */
function modelOf(key: ApproximationKey, tool: ToolInput): Approximation<{ circle: number } | { ellipse: number[] }> {
  switch (key) {
    case 'bedi': {
      const m = bediModel(tool);
      return m.ok ? { ok: true, ellipse: [m.longRadiusMm, m.shortRadiusMm] } : m;
    }
    case 'sekine':
    case 'redonnet':
    case 'osculating':
    case 'cornerBall': {
      const models = {
        sekine: sekineModel,
        redonnet: redonnetModel,
        osculating: osculatingModel,
        cornerBall: cornerBallModel,
      };
      const m = models[key](tool);
      return m.ok ? { ok: true, circle: m.effectiveRadiusMm } : m;
    }
  }
}

/**
 * Why an approximation has no value at h (forward) or at L/2 (inverse): the model's own reason, or
 * the quantity beyond the model's widest point.
 */
function noValueNote(key: ApproximationKey, tool: ToolInput, quantity: 'h' | 'half', valueMm: number): ProcedureNote {
  const m = modelOf(key, tool);
  if (!m.ok) return { kind: 'reason', text: m.notApplicable };
  if ('circle' in m) return { kind: 'beyond-model', shape: 'circle', quantity, valueMm, limitMm: m.circle };
  const [long, short] = m.ellipse as [number, number];
  return { kind: 'beyond-model', shape: 'ellipse', quantity, valueMm, limitMm: quantity === 'h' ? short : long };
}

function forwardRow(
  key: ApproximationKey,
  input: ForwardInput,
  r: ForwardEstimate<unknown>,
  maxMm: number,
): ProcedureRow {
  if (!r.ok) {
    const note = noValueNote(key, input, 'h', input.scallopHeightMm);
    return { key, valueMm: null, deviationMm: null, deviationPercent: null, realScallopMm: null, note };
  }
  return {
    key,
    valueMm: r.halfIntervalMm,
    // The table shows L/2: its deviation is half the step-over's.
    deviationMm: r.deviationMm / 2,
    deviationPercent: r.deviationPercent,
    realScallopMm: r.realScallopMm,
    note: r.warning === null ? null : { kind: 'wall', intervalMm: r.intervalMm, maxIntervalMm: maxMm },
  };
}

function inverseRow(key: ApproximationKey, input: InverseInput, r: InverseEstimate): ProcedureRow {
  if (!r.ok) {
    const note = noValueNote(key, input, 'half', input.intervalMm / 2);
    return { key, valueMm: null, deviationMm: null, deviationPercent: null, realScallopMm: null, note };
  }
  return {
    key,
    valueMm: r.scallopHeightMm,
    deviationMm: r.deviationMm,
    deviationPercent: r.deviationPercent,
    realScallopMm: null,
    note: null,
  };
}

/** The row key of a corrected procedure. */
function correctedRowKey(key: CorrectedKey): CurvatureRowKey {
  return `${key}Corrected`;
}

/**
 * Why a corrected procedure has no value at h (forward) or L/2 (inverse): the model's own reason, a
 * combined radius that is not positive (a concave surface tighter than Reff), or the quantity beyond
 * the combined circle's widest point.
 */
function curvatureNote(
  key: CorrectedKey,
  tool: ToolInput,
  surface: CylinderSurface,
  quantity: 'h' | 'half',
  valueMm: number,
): ProcedureNote {
  const m = modelOf(key, tool);
  if (!m.ok) return { kind: 'reason', text: m.notApplicable };
  if (!('circle' in m)) return { kind: 'reason', text: 'not applicable' };
  const reff = m.circle;
  const across = surface.axis === 'feed' ? surface.radiusMm : Number.POSITIVE_INFINITY;
  const combined = Number.isFinite(across) ? (reff * across) / (reff + across) : reff;
  if (!(combined > 0) || !Number.isFinite(combined)) {
    return {
      kind: 'reason',
      text: `${CURVATURE_ROWS[correctedRowKey(key)].shortLabel}: its effective radius is not smaller than the concave surface's radius, so the combined radius 1/(1/Reff + 1/Rs) is not positive.`,
    };
  }
  return { kind: 'beyond-model', shape: 'circle', quantity, valueMm, limitMm: combined };
}

/** The rows a cylinder adds (forward): the plane's answer and each corrected procedure. */
function forwardCurvatureRows(input: ForwardInput, c: ReturnType<typeof compareForward>): CurvatureRow[] | null {
  const k = c.curvature;
  if (k === null) return null;
  const row = (key: CurvatureRowKey, r: ForwardEstimate<unknown>, missing: () => ProcedureNote): CurvatureRow => {
    if (!r.ok)
      return { key, valueMm: null, deviationMm: null, deviationPercent: null, realScallopMm: null, note: missing() };
    return {
      key,
      valueMm: r.halfIntervalMm,
      deviationMm: r.deviationMm / 2,
      deviationPercent: r.deviationPercent,
      realScallopMm: r.realScallopMm,
      note: r.warning === null ? null : { kind: 'wall', intervalMm: r.intervalMm, maxIntervalMm: c.maxIntervalMm },
    };
  };
  const rows = [row('plane', k.plane, () => ({ kind: 'reason', text: k.plane.ok ? '' : k.plane.notApplicable }))];
  for (const key of CORRECTED_KEYS)
    rows.push(
      row(correctedRowKey(key), k.corrected[key], () =>
        curvatureNote(key, input, k.surface, 'h', input.scallopHeightMm),
      ),
    );
  return rows;
}

/** The rows a cylinder adds (inverse): the scallop heights of the plane's answer and the corrected circles. */
function inverseCurvatureRows(input: InverseInput, c: ReturnType<typeof compareInverse>): CurvatureRow[] | null {
  const k = c.curvature;
  if (k === null) return null;
  const row = (key: CurvatureRowKey, r: InverseEstimate, missing: () => ProcedureNote): CurvatureRow =>
    r.ok
      ? {
          key,
          valueMm: r.scallopHeightMm,
          deviationMm: r.deviationMm,
          deviationPercent: r.deviationPercent,
          realScallopMm: null,
          note: null,
        }
      : { key, valueMm: null, deviationMm: null, deviationPercent: null, realScallopMm: null, note: missing() };
  const rows = [row('plane', k.plane, () => ({ kind: 'reason', text: k.plane.ok ? '' : k.plane.notApplicable }))];
  for (const key of CORRECTED_KEYS)
    rows.push(
      row(correctedRowKey(key), k.corrected[key], () =>
        curvatureNote(key, input, k.surface, 'half', input.intervalMm / 2),
      ),
    );
  return rows;
}

/** At most the two closed curves a torus leaves on a plane. */
function asLoops(curves: Float64Array[]): Loops {
  const [a, b] = curves;
  return a === undefined ? [] : b === undefined ? [a] : [a, b];
}

/** The scene's geometry: the tool in its posture, the cusp sections and curves (mm). */
export function sceneGeometry(
  input: ToolInput,
  exact: ExactSummary,
  surface: Surface = { kind: 'plane' },
): SceneGeometry {
  const p = placeTool(input);
  const mesh = toolMesh(input, 0.6 * input.toolRadiusMm, TOOL_RADIAL_SEGMENTS);
  // What the scene draws on any surface: the tool in its posture and the step-over it leaves.
  const common = {
    toolRadiusMm: input.toolRadiusMm,
    cornerRadiusMm: input.cornerRadiusMm,
    pattern: exact.pattern,
    intervalMm: exact.intervalMm,
    scallopHeightMm: exact.cuspHeightMm,
    toolCentre: p.centre,
    toolAxis: p.axis,
    toolPositions: mesh.positions,
    surface,
  };
  if (surface.kind === 'cylinder') {
    // The torus against the h pseudo plane is the plane's construction: on a cylinder the scene
    // marks the cusps themselves, on the offset cylinder, in the section through the contact.
    const cusp = (c: Cusp) => (c.heightMm < MIN_LENGTH_MM ? null : surfacePoint(surface, 0, c.yMm, c.heightMm));
    return { ...common, right: null, left: null, cuspPoints: { right: cusp(exact.right), left: cusp(exact.left) } };
  }
  const same = exact.right.heightMm === exact.left.heightMm;
  const sections = (['right', 'left'] as const).map((flank) => {
    const h = exact[flank].heightMm;
    return h < MIN_LENGTH_MM ? null : { flank, h, s: cuspSection(p, flank, flankAtHeight(p.shape, flank, h)) };
  });
  const [rs, ls] = sections;
  const cusp = (x: typeof rs, ringAngles: number[]): CuspGeometry | null =>
    x
      ? {
          flank: x.flank,
          heightMm: x.h,
          pHp: x.s.pHp,
          sectionCentre: x.s.sectionCentre,
          sectionNormal: x.s.sectionNormal,
          sectionRadiusMm: x.s.sectionRadiusMm,
          loops: ringAngles.length === 0 ? [] : asLoops(intersectionLoops(p, x.h, ringAngles, LOOP_SAMPLES)),
        }
      : null;
  // Equal heights: one set of curves through both cusps, carried by the right cusp.
  const both = [rs?.s.ringAngleRad, ls?.s.ringAngleRad].filter((t): t is number => t !== undefined);
  const right = cusp(rs ?? null, same ? both : rs ? [rs.s.ringAngleRad] : []);
  const left = cusp(ls ?? null, same && rs ? [] : ls ? [ls.s.ringAngleRad] : []);
  return { ...common, right, left, cuspPoints: null };
}

/** Solves one request: exact, every procedure, the scene. Never throws for any numeric input. */
export function solve(request: SolveRequest): SolveReply {
  const t0 = performance.now();
  const errors = revalidate(request);
  if (errors !== null) return { ok: false, request, errors };
  let exact: ExactSummary;
  let rows: ProcedureRow[];
  let curvature: CurvatureRow[] | null;
  let roughness: Roughness;
  if (request.mode !== 'inverse') {
    const input = request.mode === 'ra' ? forwardOfRaTarget(request.input) : request.input;
    const c = compareForward(input);
    exact = exactOfForward(input, c);
    roughness = exactRoughness(input, c.exact);
    rows = [exactRow(exact.halfIntervalMm, exact.cuspHeightMm)];
    for (const key of APPROXIMATION_KEYS) rows.push(forwardRow(key, input, c.approximations[key], c.maxIntervalMm));
    curvature = forwardCurvatureRows(input, c);
  } else {
    const input = request.input;
    const c = compareInverse(input);
    exact = exactOfInverse(input, c);
    roughness = exactRoughnessAtInterval(input, input.pattern, c.exact, input.surface);
    rows = [exactRow(exact.cuspHeightMm, null)];
    for (const key of APPROXIMATION_KEYS) rows.push(inverseRow(key, input, c.approximations[key]));
    curvature = inverseCurvatureRows(input, c);
  }
  return {
    ok: true,
    request,
    exact,
    rows,
    curvature,
    scene: sceneGeometry(request.input, exact, request.input.surface),
    roughness: roughnessSummary(roughness, exact.cuspHeightMm),
    solveMs: performance.now() - t0,
  };
}

function exactRow(valueMm: number, realScallopMm: number | null): ProcedureRow {
  return { key: 'exact', valueMm, deviationMm: null, deviationPercent: null, realScallopMm, note: null };
}

/** The trace of the paper's procedure on both flanks as frames for the 3D step-through. */
export function traceFrames(input: ForwardInput): Pick<TeachData, 'frames' | 'traceResult'> {
  const trace = traceProcedure(input);
  const p = trace.placement;
  const section = (t: number) => ({ sectionCentre: sectionCentre(p, t), sectionNormal: ringTangent(p, t) });
  const frames: TraceFrame[] = [];
  const base = {
    dsMm: null,
    found: false,
    rangeRad: null,
    sectionCount: 0,
    candidates: [],
    point: null,
    outMm: null,
    approachIndex: 0,
  } as const;
  const approaches = { right: 0, left: 0 };
  const converge = (flank: Flank) => {
    const f = trace[flank];
    frames.push({
      ...base,
      phase: 'converged',
      flank,
      ringAngleRad: f.ringAngleRad,
      ...section(f.ringAngleRad),
      point: f.pHp,
      outMm: f.widthMm,
    });
  };
  let previous: Flank | null = null;
  for (const step of trace.steps) {
    if (previous !== null && step.flank !== previous) converge(previous);
    previous = step.flank;
    if (step.phase === 'approach') {
      frames.push({
        ...base,
        phase: 'approach',
        flank: step.flank,
        approachIndex: approaches[step.flank]++,
        ringAngleRad: step.ringAngleRad,
        dsMm: step.dsMm,
        ...section(step.ringAngleRad),
      });
    } else if (step.phase === 'single-contact') {
      frames.push({
        ...base,
        phase: 'single-contact',
        flank: step.flank,
        ringAngleRad: step.ringAngleRad,
        dsMm: step.dsMm,
        ...section(step.ringAngleRad),
        found: step.found,
        point: step.found ? step.pHp : null,
      });
    } else {
      const best = step.ringAnglesRad[step.bestIndex] ?? step.rangeRad[0];
      frames.push({
        ...base,
        phase: 'search',
        flank: step.flank,
        ringAngleRad: best,
        ...section(best),
        rangeRad: step.rangeRad,
        sectionCount: step.ringAnglesRad.length,
        candidates: [...step.candidates],
        point: step.pHp,
        outMm: step.crossingOutMm[step.bestIndex] ?? null,
      });
    }
  }
  if (previous !== null) converge(previous);
  // The closing frame: both flanks' points.
  frames.push({
    ...base,
    phase: 'converged',
    flank: null,
    ringAngleRad: trace.right.ringAngleRad,
    ...section(trace.right.ringAngleRad),
    candidates: [...trace.right.pHp, ...trace.left.pHp],
    point: trace.right.pHp,
    outMm: trace.right.widthMm,
  });
  const exact = exactForward(input);
  return {
    frames,
    traceResult: {
      widthRightMm: trace.right.widthMm,
      widthLeftMm: trace.left.widthMm,
      exactWidthRightMm: exact.halfWidthRightMm,
      exactWidthLeftMm: exact.halfWidthLeftMm,
    },
  };
}

/** Fixed conditions: computed once per worker. */
let tables: readonly PaperTableRow[] | null = null;

function sweep(input: ForwardInput, axis: 'lead' | 'tilt'): Sweep {
  const h = input.scallopHeightMm;
  if (axis === 'lead') {
    const s = stepOverSweep(input, input.pattern, h, 'lead', 0.5, 89, 120, input.leadAngleDeg, input.surface);
    return { angleDeg: s.angleDeg, values: s.values, gaps: s.gaps };
  }
  const beta = input.tiltAngleDeg;
  const s = stepOverSweep(
    input,
    input.pattern,
    h,
    'tilt',
    Math.min(-60, beta),
    Math.max(60, beta),
    120,
    beta,
    input.surface,
  );
  return { angleDeg: s.angleDeg, values: s.values, gaps: s.gaps };
}

const half = (r: { ok: true; halfIntervalMm: number } | { ok: false }) => (r.ok ? r.halfIntervalMm : null);

function models(input: ForwardInput): TeachData['models'] {
  const s = shapeOfTool(input);
  const h = input.scallopHeightMm;
  const sek = sekineModel(input);
  const red = redonnetModel(input);
  const bedi = bediModel(input);
  const osc = osculatingModel(input);
  const ball = cornerBallModel(input);
  return {
    shape: {
      a: s.a,
      b: s.b,
      phiRad: s.phi,
      d0: s.d0,
      t0Rad: Math.atan2(s.sinT0, s.cosT0),
      contactOffsetMm: contactOffsetMm(s),
    },
    rightOffsetRad: flankAtHeight(s, 'right', h).ringOffsetRad,
    leftOffsetRad: flankAtHeight(s, 'left', h).ringOffsetRad,
    sekine: sek.ok
      ? {
          toolCentreHeightMm: sek.toolCentreHeightMm,
          shortRadiusMm: sek.shortRadiusMm,
          longRadiusMm: sek.longRadiusMm,
          effectiveRadiusMm: sek.effectiveRadiusMm,
          halfIntervalMm: half(sekineHalfInterval(input)),
        }
      : null,
    redonnet: red.ok
      ? { effectiveRadiusMm: red.effectiveRadiusMm, halfIntervalMm: half(redonnetHalfInterval(input)) }
      : null,
    bedi: bedi.ok
      ? {
          longRadiusMm: bedi.longRadiusMm,
          shortRadiusMm: bedi.shortRadiusMm,
          halfIntervalMm: half(bediHalfInterval(input)),
        }
      : null,
    osculating: osc.ok
      ? { effectiveRadiusMm: osc.effectiveRadiusMm, halfIntervalMm: half(osculatingHalfInterval(input)) }
      : null,
    cornerBall: ball.ok
      ? { effectiveRadiusMm: ball.effectiveRadiusMm, halfIntervalMm: half(cornerBallHalfInterval(input)) }
      : null,
  };
}

/** The profile view's curves on a cylinder (surface coordinates) and where each comparison row puts the next pass. */
function cylinderCurves(
  forward: ForwardInput,
  surface: CylinderSurface,
  c: { profile: Float64Array; ringEllipse: Float64Array },
  k: CurvatureComparison | null,
): CylinderCurves {
  const passProfile =
    surface.axis === 'feed' ? toSurfaceSection(surface, c.profile) : revolvedProfile(forward, surface);
  const comparison: Array<{ key: CurvatureRowKey; intervalMm: number | null }> = [
    { key: 'plane', intervalMm: k?.plane.ok ? k.plane.intervalMm : null },
  ];
  for (const key of CORRECTED_KEYS) {
    const r = k?.corrected[key];
    comparison.push({ key: correctedRowKey(key), intervalMm: r?.ok ? r.intervalMm : null });
  }
  return { surface, passProfile, ringEllipse: toSurfaceSection(surface, c.ringEllipse), comparison };
}

/** The teaching views' data for one request (in inverse mode: the forward state at the solved h). */
export function teach(request: SolveRequest): TeachReply {
  const errors = revalidate(request);
  if (errors !== null) return { ok: false, request, errors, reason: null };
  let forward: ForwardInput;
  let exact: ExactSummary;
  /** The forward comparison, when it is at hand (its curvature rows feed the profile on a cylinder). */
  let compared: ReturnType<typeof compareForward> | null = null;
  if (request.mode !== 'inverse') {
    forward = request.mode === 'ra' ? forwardOfRaTarget(request.input) : request.input;
    compared = compareForward(forward);
    exact = exactOfForward(forward, compared);
  } else {
    const input = request.input;
    exact = exactOfInverse(input, compareInverse(input));
    if (exact.cuspHeightMm < MIN_LENGTH_MM) {
      return {
        ok: false,
        request,
        errors: [],
        reason:
          'No scallop: the flat bottom lying on the plane covers this step-over, so there is no profile to compare.',
      };
    }
    forward = forwardInput(input, input.pattern, exact.cuspHeightMm, input.surface);
  }
  const c = profileCurves(forward);
  const approximations = {
    sekine: c.sekine,
    redonnet: c.redonnet,
    bedi: c.bedi,
    osculating: c.osculating,
    cornerBall: c.cornerBall,
  };
  tables ??= paperTables();
  const cylinder =
    forward.surface.kind === 'cylinder'
      ? cylinderCurves(forward, forward.surface, c, (compared ?? compareForward(forward)).curvature)
      : null;
  const trace = traceFrames(forward);
  return {
    ok: true,
    request,
    forward,
    exact,
    curves: { profile: c.profile, ringEllipse: c.ringEllipse, approximations },
    sweeps: { lead: sweep(forward, 'lead'), tilt: sweep(forward, 'tilt') },
    // The paper's procedure works against the h pseudo plane: it has no frames on a cylinder.
    frames: cylinder === null ? trace.frames : [],
    traceResult: trace.traceResult,
    models: models(forward),
    tables,
    cylinder,
  };
}

/** Buffers of a reply that can be transferred instead of copied (each listed once). */
export function transferables(reply: SolveReply | TeachReply): ArrayBuffer[] {
  if (!reply.ok) return [];
  const out = new Set<ArrayBuffer>();
  if ('scene' in reply) {
    const g = reply.scene;
    out.add(g.toolPositions.buffer as ArrayBuffer);
    for (const cusp of [g.right, g.left]) for (const l of cusp?.loops ?? []) out.add(l.buffer as ArrayBuffer);
  } else {
    const c = reply.curves;
    for (const curve of [c.profile, c.ringEllipse, ...Object.values(c.approximations)])
      if (curve) out.add(curve.buffer as ArrayBuffer);
    if (reply.cylinder !== null) {
      out.add(reply.cylinder.passProfile.buffer as ArrayBuffer);
      out.add(reply.cylinder.ringEllipse.buffer as ArrayBuffer);
    }
  }
  return [...out];
}

/** The worker's API object; its type is what the page sees through rpc.ts. */
export const solverApi = { solve, teach, table };

export type SolverApi = typeof solverApi;
