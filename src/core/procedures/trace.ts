/**
 * The paper's "3D geometrical computation" (Figure 1, Eqs. 1-3) as a recorded trace, extended to
 * any posture: on each flank (right, +Y, and left, -Y) it searches the torus sections for the
 * crossing with the h pseudo plane that lies farthest out.
 *
 * It works only with torus sections (placement.ts) and the plane, never with the profile's
 * normal condition of posture.ts, so its result checks the exact solver:
 *  1. Eq. 1: start at the section whose ring point is h/2 above the ring's lowest point. The ring
 *     height above its lowest point is `D0 (1 - cos delta)` (Eq. 1 is the case beta = 0, where
 *     `D0 = Rb sin rho`), written `2 D0 sin^2(delta/2)` so that tiny h keeps its digits;
 *  2. Eqs. 2-3: move along the ring until the section touches the plane at a single point
 *     (`d_s = Rcr`): the section circle's lowest point, `Rcr (1 - m)` below its centre with
 *     `m = sqrt(1 - T_z^2)` (T the ring tangent), reaches the plane;
 *  3. steps 15-25: search the sections between the contact (or, for h > 2 Rcr, the first one that
 *     reaches the plane) and the single-contact one for the farthest crossing, refining a grid of
 *     n sections around the best until the range is exhausted.
 * Lengths mm (relative to the contact), angles radians.
 */

import type { ForwardInput } from '../domain/pass';
import type { Vec3 } from '../math/vec';
import { type Placement, placeTool } from '../tool/placement';
import type { Flank } from '../tool/posture';

/** One step of the procedure on one flank, in the paper's terms. */
export type TraceStep =
  | {
      /** Steps 2-11: a section visited on the way to the single-contact section. */
      readonly phase: 'approach';
      readonly flank: Flank;
      readonly ringAngleRad: number;
      /** In-plane distance from the section centre to the h pseudo plane, mm (Eq. 3). */
      readonly dsMm: number;
    }
  | {
      /** Steps 12-14: the single-contact section and its touching point on the plane. */
      readonly phase: 'single-contact';
      readonly flank: Flank;
      readonly ringAngleRad: number;
      readonly dsMm: number;
      readonly pHp: Vec3;
      /** False when every section on this side meets the plane (no single contact). */
      readonly found: boolean;
    }
  | {
      /** Steps 16-25: one pass over the search grid; `best` is the farthest crossing. */
      readonly phase: 'search';
      readonly flank: Flank;
      readonly rangeRad: readonly [number, number];
      readonly ringAnglesRad: readonly number[];
      /** Distance out from the contact of each section's farthest crossing (null where none), mm. */
      readonly crossingOutMm: ReadonlyArray<number | null>;
      /** The crossing points (flat xyz, mm); sections that miss the plane are left out. */
      readonly candidates: readonly number[];
      readonly bestIndex: number;
      readonly pHp: Vec3;
    };

/** The procedure's answer on one flank. */
export interface FlankTrace {
  readonly flank: Flank;
  /** How far out from the contact the farthest crossing lies (the flank's width at h), mm. */
  readonly widthMm: number;
  readonly pHp: Vec3;
  readonly ringAngleRad: number;
}

export interface Trace {
  readonly steps: readonly TraceStep[];
  readonly right: FlankTrace;
  readonly left: FlankTrace;
  /** The placement the trace worked in (contact at the origin). */
  readonly placement: Placement;
}

/** A section relative to the contact: its ring point and the cut with the plane h above the contact. */
interface Cut {
  /** Vertical gap from the section circle's lowest point up to the plane (>= 0: it reaches), mm. */
  readonly gapMm: number;
  /** In-plane distance from the section centre down to the plane (Eq. 3), mm. */
  readonly dsMm: number;
  /** The crossing farthest towards the flank, or null. */
  readonly point: Vec3 | null;
  /** Its distance out from the contact (signed towards the flank), mm. */
  readonly outMm: number | null;
}

function cutAt(p: Placement, side: 1 | -1, delta: number, h: number): Cut {
  const s = p.shape;
  const rb = p.ringRadiusMm;
  const rcr = p.cornerRadiusMm;
  const t = p.contactRingAngleRad + side * delta;
  const st = Math.sin(t);
  const ct = Math.cos(t);
  const r: Vec3 = [st * p.v1[0] + ct * p.v2[0], st * p.v1[1] + ct * p.v2[1], st * p.v1[2] + ct * p.v2[2]];
  const tz = ct * p.v1[2] - st * p.v2[2];
  // Ring point relative to the contact's ring point: the chord Rb (r(t) - r(t0)), with its height
  // from Eq. 1, D0 (1 - cos delta) = 2 D0 sin^2(delta/2).
  const half = Math.sin(delta / 2);
  const rise = 2 * s.d0 * half * half;
  const tm = p.contactRingAngleRad + (side * delta) / 2;
  const chordY = 2 * side * half * (Math.cos(tm) * p.v1[1] - Math.sin(tm) * p.v2[1]);
  const chordX = 2 * side * half * (Math.cos(tm) * p.v1[0] - Math.sin(tm) * p.v2[0]);
  // Centre of the section relative to the contact point, which lies Rcr below the contact's ring
  // point; a flat bottom lying flat touches with its whole face, under O (placement.ts).
  const flat = p.shape.flatOnPlane;
  const cx = rb * chordX + (flat ? rb * (p.shape.sinT0 * p.v1[0] + p.shape.cosT0 * p.v2[0]) : 0);
  const cy = rb * chordY + (flat ? rb * (p.shape.sinT0 * p.v1[1] + p.shape.cosT0 * p.v2[1]) : 0);
  const cz = rcr + rise;
  // Inside the section plane the circle's height is cz + Rcr (r_z cos psi + a_z sin psi).
  const A = r[2];
  const B = p.axis[2];
  const m = Math.sqrt(A * A + B * B);
  const dsMm = (cz - h) / m;
  // Lowest point of the circle: Rcr m below the centre; Rcr - Rcr m = Rcr T_z^2 / (1 + m).
  const gapMm = h - rise - (rcr * tz * tz) / (1 + m);
  if (rcr === 0) return { gapMm, dsMm, point: gapMm === 0 ? [cx, cy, h] : null, outMm: gapMm === 0 ? side * cy : null };
  if (gapMm < 0 || !(gapMm <= 2 * rcr * m)) return { gapMm, dsMm, point: null, outMm: null };
  // Crossing angles around the lowest point psi_low: 1 - cos(spread) = gap / (Rcr m).
  const phase = Math.atan2(B, A) + Math.PI;
  const spread = 2 * Math.asin(Math.min(1, Math.sqrt(gapMm / (2 * rcr * m))));
  let best: Vec3 | null = null;
  let bestOut = Number.NEGATIVE_INFINITY;
  for (const psi of [phase - spread, phase + spread]) {
    const c = rcr * Math.cos(psi);
    const sn = rcr * Math.sin(psi);
    const y = cy + c * r[1] + sn * p.axis[1];
    const out = side * y;
    if (out > bestOut) {
      bestOut = out;
      best = [cx + c * r[0] + sn * p.axis[0], y, h];
    }
  }
  return { gapMm, dsMm, point: best, outMm: bestOut };
}

/** Ring-angle offset where the ring is `z` above its lowest point (Eq. 1 generalised), capped at pi. */
function offsetAtRise(p: Placement, z: number): number {
  const d0 = p.shape.d0;
  if (!(d0 > 0)) return 0;
  return 2 * Math.asin(Math.min(1, Math.sqrt(Math.max(0, z) / (2 * d0))));
}

/**
 * Runs the procedure on both flanks.
 * @param input validated forward input; @param gridSize sections per search pass (odd, >= 5).
 */
export function traceProcedure(input: ForwardInput, gridSize = 9): Trace {
  const p = placeTool(input);
  const h = input.scallopHeightMm;
  const steps: TraceStep[] = [];
  const right = traceFlank(p, 1, h, gridSize, steps);
  const left = traceFlank(p, -1, h, gridSize, steps);
  return { steps, right, left, placement: p };
}

function traceFlank(p: Placement, side: 1 | -1, h: number, gridSize: number, steps: TraceStep[]): FlankTrace {
  const flank: Flank = side === 1 ? 'right' : 'left';
  const rcr = p.cornerRadiusMm;
  const s = p.shape;
  // The side's sections run from the contact to the opposite point of the ring (delta in [0, pi]).
  if (s.flatOnPlane || p.ringRadiusMm === 0) {
    // A flat bottom lying on the plane, or a ball: the farthest section is known (the edge of the
    // face, or any meridian of the ball); the procedure reduces to one section.
    const delta = s.flatOnPlane ? Math.PI / 2 : 0;
    const cut = p.ringRadiusMm === 0 ? ballCut(p, side, h) : cutAt(p, side, delta, h);
    const pHp = cut.point ?? [0, 0, h];
    steps.push({
      phase: 'single-contact',
      flank,
      ringAngleRad: p.contactRingAngleRad + side * delta,
      dsMm: cut.dsMm,
      pHp,
      found: false,
    });
    return { flank, widthMm: cut.outMm ?? 0, pHp, ringAngleRad: p.contactRingAngleRad + side * delta };
  }
  const ringAngle = (d: number) => p.contactRingAngleRad + side * d;
  if (rcr === 0) {
    // A flat end: the sections are the ring's points; the one at height h is the crossing (Eq. 1).
    const d = offsetAtRise(p, h);
    const cut = cutAt(p, side, d, h);
    const half = Math.sin(d / 2);
    const tm = p.contactRingAngleRad + (side * d) / 2;
    const y = 2 * side * half * (Math.cos(tm) * p.v1[1] - Math.sin(tm) * p.v2[1]) * p.ringRadiusMm;
    const x = 2 * side * half * (Math.cos(tm) * p.v1[0] - Math.sin(tm) * p.v2[0]) * p.ringRadiusMm;
    const pHp: Vec3 = [x, y, h];
    steps.push({ phase: 'single-contact', flank, ringAngleRad: ringAngle(d), dsMm: cut.dsMm, pHp, found: true });
    return { flank, widthMm: side * y, pHp, ringAngleRad: ringAngle(d) };
  }
  // Step 2 (Eq. 1): the section whose ring point is h/2 above the lowest.
  const start = offsetAtRise(p, h / 2);
  steps.push({ phase: 'approach', flank, ringAngleRad: ringAngle(start), dsMm: cutAt(p, side, start, h).dsMm });
  // For h > 2 Rcr the first sections lie wholly below the plane: the sections that meet it start
  // where a section's top first reaches it.
  const enter = h > 2 * rcr ? findEnter(p, side, h) : 0;
  // Steps 6-11: move along the ring to the first section that no longer reaches the plane (its
  // lowest point rises above it): a coarse walk finds the first sign change of the gap, then the
  // section is bracketed down to the last bits (d_s = Rcr there).
  const gapAt = (d: number) => cutAt(p, side, d, h).gapMm;
  let lo = Math.max(enter, start);
  if (gapAt(lo) < 0) lo = enter;
  let hi: number | null = null;
  const walk = 64;
  for (let i = 1; i <= walk; i++) {
    const d = lo + ((Math.PI - lo) * i) / walk;
    if (gapAt(d) < 0) {
      hi = d;
      break;
    }
    lo = d;
  }
  const found = hi !== null;
  let recorded = 0;
  if (hi !== null) {
    let high = hi;
    for (let i = 0; i < 200 && high - lo > 1e-16 * high; i++) {
      const d = 0.5 * (lo + high);
      if (recorded++ < 12)
        steps.push({ phase: 'approach', flank, ringAngleRad: ringAngle(d), dsMm: cutAt(p, side, d, h).dsMm });
      if (gapAt(d) >= 0) lo = d;
      else high = d;
    }
  }
  const scp = found ? lo : Math.PI;
  const scpCut = cutAt(p, side, scp, h);
  steps.push({
    phase: 'single-contact',
    flank,
    ringAngleRad: ringAngle(scp),
    dsMm: scpCut.dsMm,
    pHp: scpCut.point ?? [0, 0, h],
    found,
  });
  // Steps 15-25: refine a grid around the farthest crossing.
  const n = Math.max(5, gridSize | 1);
  lo = enter;
  let top = scp;
  let bestOut = Number.NEGATIVE_INFINITY;
  let bestPoint: Vec3 = [0, 0, h];
  let bestDelta = lo;
  for (let pass = 0; pass < 400; pass++) {
    const angles: number[] = [];
    const outs: Array<number | null> = [];
    const candidates: number[] = [];
    let bestIndex = 0;
    let passBest = Number.NEGATIVE_INFINITY;
    for (let i = 0; i < n; i++) {
      const d = lo + ((top - lo) * i) / (n - 1);
      const cut = cutAt(p, side, d, h);
      angles.push(ringAngle(d));
      outs.push(cut.outMm);
      if (cut.point !== null && cut.outMm !== null) {
        candidates.push(cut.point[0], cut.point[1], cut.point[2]);
        if (cut.outMm > passBest) {
          passBest = cut.outMm;
          bestIndex = i;
        }
        if (cut.outMm > bestOut) {
          bestOut = cut.outMm;
          bestPoint = cut.point;
          bestDelta = d;
        }
      }
    }
    if (pass < 60) {
      steps.push({
        phase: 'search',
        flank,
        rangeRad: [ringAngle(lo), ringAngle(top)],
        ringAnglesRad: angles,
        crossingOutMm: outs,
        candidates,
        bestIndex,
        pHp: bestPoint,
      });
    }
    // Step 23: the new range is the neighbours of the best section.
    const width = top - lo;
    const step = width / (n - 1);
    const centre = lo + step * bestIndex;
    const newLo = Math.max(lo, centre - step);
    const newTop = Math.min(top, centre + step);
    if (!(newTop - newLo < width) || width <= 1e-16 * Math.max(1e-300, top)) break;
    lo = newLo;
    top = newTop;
  }
  return { flank, widthMm: Math.max(0, bestOut), pHp: bestPoint, ringAngleRad: ringAngle(bestDelta) };
}

/** First section (smallest delta) whose circle reaches up to the plane: gap = 2 Rcr m. */
function findEnter(p: Placement, side: 1 | -1, h: number): number {
  // Wholly below the plane: no crossing although the lowest point is below it (gap > 2 Rcr m).
  const over = (d: number) => {
    const c = cutAt(p, side, d, h);
    return c.point === null && c.gapMm > 0;
  };
  if (!over(0)) return 0;
  let lo = 0;
  let hi = Math.PI;
  for (let i = 0; i < 200; i++) {
    const mid = 0.5 * (lo + hi);
    if (over(mid)) lo = mid;
    else hi = mid;
    if (hi - lo <= 1e-16 * hi) break;
  }
  return hi;
}

/** A ball end: the section through the farthest crossing is the meridian across the feed. */
function ballCut(p: Placement, side: 1 | -1, h: number): Cut {
  const rcr = p.cornerRadiusMm;
  const q = Math.min(h, 2 * rcr);
  const out = Math.sqrt(q * (2 * rcr - q));
  return { gapMm: h, dsMm: rcr - h, point: [0, side * out, h], outMm: out };
}
