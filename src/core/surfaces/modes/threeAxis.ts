/**
 * Three-axis machining as a machine mode (mode.ts; shared/notes/doubly-curved-and-3-axis.md,
 * section 2a): the tool stays upright, and the slope `alpha` and the raster angle `psi` (90 for
 * waterline passes) give its lead and tilt at the CC point in closed form (threeAxis/slopePosture.ts),
 * over the plane's model: the sloped plane is the plane at that posture, not a surface of its own.
 * Feeding down the slope is the same upright tool on the same line, so zigzag passes leave what
 * one-way passes leave: the pattern is one-way. Waterline passes on a surface of revolution (a
 * doubly curved point: Rf the horizontal circle's normal radius, Rc the meridian's) are not
 * congruent (surface.ts): the mode answers them itself (mode.ts OwnAnswer) by
 * threeAxis/waterlineRevolution.ts, without per-flank parts. The programmed steps (Lxy, dz) stay
 * threeAxis/slopedPlane.ts's and waterlineRevolution.ts's. Angles degrees.
 */
import type { DoublyCurvedSurface, SurfaceDescriptorBase } from '../../domain/surface';
import { slopeErrors, type ThreeAxisPasses } from '../../threeAxis/slopedPlane';
import { slopePosture } from '../../threeAxis/slopePosture';
import { waterlineForward, waterlineHeightLimitMm, waterlineInverse } from '../../threeAxis/waterlineRevolution';
import { type MachineMode, type ModeError, type OwnAnswer, shownNumber } from '../mode';

/** The upright tool over a slope `slopeDeg` (0 <= alpha < 90), with raster or waterline passes. */
export interface ThreeAxisMode {
  readonly kind: 'threeAxis';
  readonly slopeDeg: number;
  readonly passes: ThreeAxisPasses;
  /** Raster angle psi in plan from the fall line, degrees, 0 to 90; ignored for waterline (90). */
  readonly rasterAngleDeg: number;
}

/**
 * The slope's and raster angle's errors on the sloped plane, in the plane solver's own words
 * (threeAxis/slopedPlane.ts slopeErrors); on a surface of revolution the waterline solver checks
 * them itself (its own answer).
 */
function check(mode: ThreeAxisMode, surface: SurfaceDescriptorBase): ModeError[] {
  if (mode.passes === 'waterline' && surface.kind === 'doublyCurved') return [];
  const finite = (['slopeDeg', 'rasterAngleDeg'] as const).filter((k) => !Number.isFinite(mode[k]));
  if (finite.length > 0)
    return finite.map((k) => ({
      parameter: k === 'slopeDeg' ? 'slope' : 'rasterAngle',
      message: `${k === 'slopeDeg' ? 'Slope' : 'Raster angle'} must be a number of degrees (got ${shownNumber(mode[k])}).`,
    }));
  return slopeErrors(mode).map((e) => ({ parameter: e.field, message: e.message }));
}

/** The upright tool's lead and tilt (degrees) over the slope, one-way. */
function posture(mode: ThreeAxisMode) {
  const p = slopePosture(mode.slopeDeg, mode.passes === 'waterline' ? 90 : mode.rasterAngleDeg);
  return { leadAngleDeg: p.leadDeg, tiltAngleDeg: p.tiltDeg, pattern: 'one-way' as const };
}

/** A straight principal radius (infinite) as the revolution solver takes it (null). */
const radius = (r: number): number | null => (Number.isFinite(r) ? r : null);

/** Waterline passes on a surface of revolution: not congruent, answered by their own solver. */
const waterlineOnRevolution: OwnAnswer<ThreeAxisMode> = {
  surfaceKind: 'doublyCurved',
  applies: (mode) => mode.passes === 'waterline',
  answer: (tool, mode, surface, target) => {
    const s = surface as DoublyCurvedSurface;
    const c = {
      ...tool,
      slopeDeg: mode.slopeDeg,
      feedRadiusMm: radius(s.feedRadiusMm),
      crossRadiusMm: radius(s.crossRadiusMm),
    };
    const r =
      target.quantity === 'h'
        ? waterlineForward(c, target.mm)
        : waterlineInverse(c, { field: 'interval', mm: target.mm });
    if (!r.ok) return { ok: false, errors: r.errors.map((e) => ({ field: e.field, message: e.message })) };
    const a = r.value;
    return {
      ok: true,
      value: {
        intervalMm: a.intervalMm,
        cuspHeightMm: a.cuspHeightMm,
        otherCuspHeightMm: null,
        halfWidthRightMm: null,
        halfWidthLeftMm: null,
        contactOffsetMm: null,
        posture: { leadAngleDeg: a.leadDeg, tiltAngleDeg: a.tiltDeg, pattern: 'one-way' },
        maxIntervalMm: null,
        heightLimitMm: waterlineHeightLimitMm(c),
      },
    };
  },
};

/** The three-axis mode: a posture on the plane (the sloped plane); its own answer for waterline passes on a surface of revolution. */
export const threeAxisMode: MachineMode<ThreeAxisMode> = {
  kind: 'threeAxis',
  surfaceKinds: ['plane'],
  check,
  posture,
  ownAnswers: [waterlineOnRevolution],
  refusal: (kind) =>
    `Three-axis machining is answered on a sloped plane, or with waterline passes on a surface of revolution, not here (a surface of kind "${kind}"): the upright tool's posture is known there only.`,
};
