/**
 * The doubly curved point (shared/notes/doubly-curved-and-3-axis.md, section 1) as a surface model
 * (surface.ts): the torus patch with signed principal radii Rf along the feed and Rc across it,
 * solved by doublyCurved/solve.ts (scallops measured radially from the equator's centre) through the
 * general forward and inverse, and its gouging check (doublyCurved/gouging.ts).
 *
 * Straight radii are the plane's and the cylinders' own surfaces, and are answered by their models,
 * to the last digit: Rf and Rc infinite the plane, Rf infinite the cylinder along the feed with
 * Rs = Rc, Rc infinite the cylinder across it with Rs = Rf (doublyCurved/solve.ts's module comment).
 * Lengths mm.
 */
import type { ForwardInput, InverseInput } from '../../domain/pass';
import type { CylinderSurface, DoublyCurvedSurface, PlaneSurface, Surface } from '../../domain/surface';
import type { PassPattern, ToolInput } from '../../domain/tool';
import {
  type Flank,
  type FlankPoint,
  flankAtHeight,
  flankLimits,
  type PostureShape,
  shapeOfTool,
} from '../../tool/posture';
import { doublyCurvedGouges } from '../doublyCurved/gouging';
import {
  type DoublyCurvedSolver,
  doublyCurvedMaxIntervalMm,
  doublyCurvedSolver,
  forwardWith,
  intervalWith,
  inverseWith,
} from '../doublyCurved/solve';
import type { ExactForward, ExactInverse, SurfaceFit, SurfaceModel } from '../surface';
import { cylinderModel } from './cylinder';
import { planeModel } from './plane';

/** A straight surface and its model. */
interface Straight {
  readonly model: SurfaceModel<Surface>;
  readonly surface: Surface;
}

const asModel = (m: SurfaceModel<PlaneSurface> | SurfaceModel<CylinderSurface>) => m as SurfaceModel<Surface>;

/** The plane or cylinder a doubly curved point with a straight radius is, with its model; null when both are curved. */
export function straightSurface(surface: DoublyCurvedSurface): Straight | null {
  const feedStraight = !Number.isFinite(surface.feedRadiusMm);
  const crossStraight = !Number.isFinite(surface.crossRadiusMm);
  if (feedStraight && crossStraight) return { model: asModel(planeModel), surface: { kind: 'plane' } };
  if (feedStraight)
    return {
      model: asModel(cylinderModel),
      surface: { kind: 'cylinder', radiusMm: surface.crossRadiusMm, axis: 'feed' },
    };
  if (crossStraight)
    return {
      model: asModel(cylinderModel),
      surface: { kind: 'cylinder', radiusMm: surface.feedRadiusMm, axis: 'cross' },
    };
  return null;
}

/** The plane profile's point at height h (clamped to the flank's top `topMm`), for drawing only (as on a cylinder). */
function drawnPoint(s: PostureShape, flank: Flank, topMm: number, heightMm: number): FlankPoint {
  return flankAtHeight(s, flank, Math.max(0, Math.min(heightMm, topMm)));
}

/** The plane profile's points drawn at the right and left cusps' heights. */
interface Drawn {
  readonly right: FlankPoint;
  readonly left: FlankPoint;
}

/**
 * The drawn points at the right and left cusps' heights, found when first read (the plane
 * profile's limits and two points cost about as much as the answer, and only a drawing reads them).
 */
function drawnPoints(input: ToolInput, rightMm: number, leftMm: number): () => Drawn {
  let drawn: Drawn | null = null;
  return () => {
    if (drawn === null) {
      const s = shapeOfTool(input);
      const tops = flankLimits(s);
      drawn = {
        right: drawnPoint(s, 'right', tops.topRightMm, rightMm),
        left: drawnPoint(s, 'left', tops.topLeftMm, leftMm),
      };
    }
    return drawn;
  };
}

/** The last point's prepared solver, and its tool, posture and radii (compared with Object.is). */
let lastSolver: DoublyCurvedSolver | null = null;
let lastKey: readonly number[] = [];

/**
 * The point's solver, prepared once for a run of calls at one point: a reply asks the same point's
 * limits (the shank's search, cached in the solver), widest step-over, answer and flank widths in
 * turn, each through the model.
 */
function solverOf(tool: ToolInput, surface: DoublyCurvedSurface): DoublyCurvedSolver {
  const key = [
    tool.toolRadiusMm,
    tool.cornerRadiusMm,
    tool.leadAngleDeg,
    tool.tiltAngleDeg,
    surface.feedRadiusMm,
    surface.crossRadiusMm,
  ];
  if (lastSolver === null || key.some((v, i) => !Object.is(v, lastKey[i]))) {
    lastSolver = doublyCurvedSolver(tool, surface);
    lastKey = key;
  }
  return lastSolver;
}

function forward(input: ForwardInput<DoublyCurvedSurface>): ExactForward {
  const straight = straightSurface(input.surface);
  if (straight !== null) return straight.model.forward({ ...input, surface: straight.surface });
  const a = forwardWith(solverOf(input, input.surface), input.pattern, input.scallopHeightMm);
  const drawn = drawnPoints(input, a.cuspHeightMm, a.cuspHeightMm);
  return {
    intervalMm: a.intervalMm,
    halfIntervalMm: a.intervalMm / 2,
    halfWidthRightMm: a.halfWidthRightMm,
    halfWidthLeftMm: a.halfWidthLeftMm,
    contactOffsetMm: a.contactOffsetMm,
    cuspHeightMm: a.cuspHeightMm,
    otherCuspHeightMm: a.otherCuspHeightMm,
    noScallop: false,
    get right() {
      return drawn().right;
    },
    get left() {
      return drawn().left;
    },
  };
}

function inverse(input: InverseInput<DoublyCurvedSurface>): ExactInverse {
  const straight = straightSurface(input.surface);
  if (straight !== null) return straight.model.inverse({ ...input, surface: straight.surface });
  const a = inverseWith(solverOf(input, input.surface), input.pattern, input.intervalMm);
  const drawn = drawnPoints(input, a.rightCuspHeightMm, a.leftCuspHeightMm);
  return {
    ...a,
    get right() {
      return drawn().right;
    },
    get left() {
      return drawn().left;
    },
  };
}

/** Gouging: the doubly curved predicate (no single radius to name: each radius's limit depends on the other). */
function fit(tool: ToolInput, surface: DoublyCurvedSurface): SurfaceFit {
  const straight = straightSurface(surface);
  if (straight !== null) return straight.model.fit(tool, straight.surface);
  return doublyCurvedGouges(tool, surface) ? { gouges: true, by: 'head', limitRadiusMm: null } : { gouges: false };
}

/** The doubly curved point's model. */
export const doublyCurvedModel: SurfaceModel<DoublyCurvedSurface> = {
  kind: 'doublyCurved',
  intervalMm: (input) => {
    const straight = straightSurface(input.surface);
    if (straight !== null) return straight.model.intervalMm({ ...input, surface: straight.surface });
    return intervalWith(solverOf(input, input.surface), input.pattern, input.scallopHeightMm);
  },
  forward,
  inverse,
  limits: (tool, surface) => {
    const straight = straightSurface(surface);
    return straight !== null ? straight.model.limits(tool, straight.surface) : solverOf(tool, surface).limits();
  },
  maxIntervalMm: (tool: ToolInput, pattern: PassPattern, surface) => {
    const straight = straightSurface(surface);
    if (straight !== null) return straight.model.maxIntervalMm(tool, pattern, straight.surface);
    return doublyCurvedMaxIntervalMm(solverOf(tool, surface), pattern);
  },
  flankWidths: (tool, surface) => {
    const straight = straightSurface(surface);
    if (straight !== null) return straight.model.flankWidths(tool, straight.surface);
    const solver = solverOf(tool, surface);
    return (flank, h) => (flank === 'right' ? solver.right : solver.left).reachMm(h);
  },
  fit,
  leavesNoScallop: (tool, surface) => {
    const straight = straightSurface(surface);
    if (straight === null) return false;
    return straight.model.leavesNoScallop(tool, straight.surface);
  },
};
