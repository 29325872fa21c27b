import { afterAll, describe, expect, it } from 'vitest';
import { slopedPlaneForward } from '../../../src/core/threeAxis/slopedPlane';
import {
  type RevolutionCase,
  waterlineCuspAbove,
  waterlineForward,
  waterlineHeightLimitMm,
  waterlineInverse,
} from '../../../src/core/threeAxis/waterlineRevolution';
import { seededRandom } from '../../support/bruteForce';
import { bruteWaterlineCusp } from '../../support/reference/threeAxisBruteForce';

/**
 * Waterline on surfaces of revolution against the machine-frame brute force (the tool's slices
 * turned about the vertical axis, the material left sampled in the meridian half-plane, the cusp
 * measured radially from the meridian's centre), closed forms (a ball end on a sphere: two circles
 * in the meridian plane) and the posture solver on the plane (Rc and Rf infinite: the sloped plane
 * at tilt alpha). Stratified over the slope, the surface and the tool; seeds in the names.
 */
const worst = new Map<string, number>();
const record = (k: string, e: number) => worst.set(k, Math.max(worst.get(k) ?? 0, e));
afterAll(() => {
  const rows = [...worst].map(([k, v]) => `  ${k.padEnd(52)} ${v.toExponential(2)} mm`);
  console.info(`Waterline on surfaces of revolution, largest errors:\n${rows.join('\n')}`);
});

const TOOLS = [
  { name: 'ball', R: 3, Rcr: 3 },
  { name: 'bull-nose', R: 3, Rcr: 1 },
  { name: 'bull-nose 6/2', R: 6, Rcr: 2 },
  { name: 'small corner', R: 3, Rcr: 0.2 },
] as const;
/** Surfaces as multiples of R: [Rf, Rc] (null: infinite). */
const SURFACES: ReadonlyArray<readonly [string, number | null, number | null]> = [
  ['plane', null, null],
  ['cone', 8, null],
  ['dome (sphere)', 6, 6],
  ['bowl (sphere)', -10, -10],
  ['boss fillet (Rf > 0, Rc < 0)', 12, -4],
  ['pocket rim (Rf < 0, Rc > 0)', -20, 5],
];
const SLOPES = [0.01, 5, 30, 55, 80];

const caseOf = (
  tool: { R: number; Rcr: number },
  slope: number,
  rf: number | null,
  rc: number | null,
): RevolutionCase => ({
  toolRadiusMm: tool.R,
  cornerRadiusMm: tool.Rcr,
  slopeDeg: slope,
  feedRadiusMm: rf === null ? null : rf * tool.R,
  crossRadiusMm: rc === null ? null : rc * tool.R,
});

describe('waterline against the brute force (polished to 1e-9 mm)', () => {
  let seed = 300;
  let solved = 0;
  for (const [sname, rf, rc] of SURFACES)
    for (const slope of SLOPES) {
      seed += 1;
      const s = seed;
      const tool = TOOLS[s % TOOLS.length] as (typeof TOOLS)[number];
      it(`${sname}, alpha ${slope}, ${tool.name}, seed ${s}`, () => {
        const rand = seededRandom(s);
        const c = caseOf(tool, slope, rf, rc);
        const limit = waterlineHeightLimitMm(c);
        const h = Math.min(limit, tool.Rcr) * (0.02 + 0.9 * rand());
        const f = waterlineForward(c, h);
        if (!f.ok) {
          // Refused only by gouging or the end of the surface, each with its limit.
          expect(['gouging', 'past-surface']).toContain(f.errors[0]?.code);
          return;
        }
        solved += 1;
        const b = bruteWaterlineCusp(tool, c, f.value.intervalMm, 8);
        record(`forward, ${sname}`, Math.abs(b.polishedMm - h));
        expect(Math.abs(b.polishedMm - h)).toBeLessThan(1e-9);
        expect(Math.abs(b.sampledMm - h)).toBeLessThanOrEqual(b.boundMm + 1e-12);
        // The inverse from the programmed dz, at 0.7 of it (every third stratum: the brute force is slow).
        if (s % 3 !== 0) return;
        const inv = waterlineInverse(c, { field: 'stepDown', mm: 0.7 * f.value.stepDownMm });
        expect(inv.ok).toBe(true);
        if (inv.ok) {
          const bi = bruteWaterlineCusp(tool, c, inv.value.intervalMm, 4);
          record(`inverse, ${sname}`, Math.abs(bi.polishedMm - inv.value.cuspHeightMm));
          expect(Math.abs(bi.polishedMm - inv.value.cuspHeightMm)).toBeLessThan(1e-9);
        }
      });
    }
  it('most strata are answered', () => expect(solved).toBeGreaterThanOrEqual(22));

  it('the sampled estimate stays within its bound, which shrinks with refinement (bull-nose on a dome)', () => {
    const c = caseOf({ R: 3, Rcr: 1 }, 35, 8, 8);
    const f = waterlineForward(c, 0.04);
    if (!f.ok) throw new Error(JSON.stringify(f));
    const bounds = [4, 16, 64].map((cols) => {
      const b = bruteWaterlineCusp({ R: 3, Rcr: 1 }, c, f.value.intervalMm, cols);
      expect(Math.abs(b.sampledMm - 0.04)).toBeLessThanOrEqual(b.boundMm);
      return b.boundMm;
    });
    expect(bounds[1]).toBeLessThan(bounds[0] as number);
    expect(bounds[2]).toBeLessThan((bounds[1] as number) / 2);
  });
});

describe('closed forms and cross-checks', () => {
  it('a ball end on a sphere: two circles in the meridian plane (convex and concave, seed 11)', () => {
    const rand = seededRandom(11);
    let n = 0;
    for (let i = 0; i < 300; i++) {
      const R = 0.05 + 10 * rand();
      const convex = rand() < 0.5;
      const Rs = (convex ? 1 : -1) * R * (convex ? 0.2 + 40 * rand() : 1.05 + 40 * rand());
      const alpha = 0.5 + 85 * rand();
      const c: RevolutionCase = {
        toolRadiusMm: R,
        cornerRadiusMm: R,
        slopeDeg: alpha,
        feedRadiusMm: Rs,
        crossRadiusMm: Rs,
      };
      const h = R * (1e-6 + 0.2 * rand());
      const f = waterlineForward(c, h);
      if (!f.ok) continue;
      n += 1;
      // Ball centres on the offset circle of radius Ro about the sphere's centre; the cusp on the
      // bisector at |Rs| + h (convex) or |Rs| - h (concave) from it.
      const Ro = convex ? Rs + R : -Rs - R;
      const p = convex ? Rs + h : -Rs - h;
      // The angle at the centre between a ball centre (Ro) and the cusp (p), opposite the side R:
      // half-angle form tan(t/2) = sqrt((s - Ro)(s - p) / (s (s - R))), well conditioned for small t.
      const sp = (Ro + p + R) / 2;
      const half = 2 * Math.atan(Math.sqrt(((sp - Ro) * (sp - p)) / (sp * (sp - R))));
      const phi = 2 * half;
      const L = Math.abs(Rs) * phi;
      const a0 = (alpha * Math.PI) / 180;
      const a1 = a0 + (convex ? phi : -phi);
      // Tips on the circle Ro about the centre, R below the ball centres: dz = Ro |cos a0 - cos a1|.
      const dz = Math.abs(2 * Ro * Math.sin((a0 + a1) / 2) * Math.sin((a1 - a0) / 2));
      const eL = Math.abs(f.value.intervalMm - L);
      record('ball on a sphere, closed form (L)', eL);
      record('ball on a sphere, closed form (dz)', Math.abs(f.value.stepDownMm - dz));
      expect(eL).toBeLessThan(1e-9);
      expect(Math.abs(f.value.stepDownMm - dz)).toBeLessThan(1e-9);
    }
    expect(n).toBeGreaterThan(150);
  });

  it('Rc and Rf infinite is the sloped plane at tilt alpha (the posture solver), and a cone (Rf finite) the same (seed 12)', () => {
    const rand = seededRandom(12);
    for (let i = 0; i < 200; i++) {
      const R = 0.1 + 10 * rand();
      const Rcr = R * (0.02 + 0.98 * rand());
      const alpha = 0.001 + 85 * rand();
      const plane = slopedPlaneForward(
        { toolRadiusMm: R, cornerRadiusMm: Rcr, slopeDeg: alpha, passes: 'waterline', rasterAngleDeg: 0 },
        1e-9,
      );
      if (!plane.ok) continue;
      const h = Math.min(plane.value.heightLimitMm, Rcr) * (0.001 + 0.95 * rand());
      const p = slopedPlaneForward(
        { toolRadiusMm: R, cornerRadiusMm: Rcr, slopeDeg: alpha, passes: 'waterline', rasterAngleDeg: 0 },
        h,
      );
      const w = waterlineForward(
        { toolRadiusMm: R, cornerRadiusMm: Rcr, slopeDeg: alpha, feedRadiusMm: null, crossRadiusMm: null },
        h,
      );
      if (!p.ok || !w.ok) throw new Error(JSON.stringify([p, w]));
      const e = Math.abs(w.value.intervalMm - p.value.intervalMm);
      record('plane: meridian solver vs posture solver (L)', e);
      expect(e).toBeLessThan(1e-11 * (1 + R));
      expect(Math.abs(w.value.stepDownMm - (p.value.stepDownMm as number))).toBeLessThan(1e-11 * (1 + R));
      // A convex cone (the axis far enough not to be crossed): the same cusp, Rf only gouges.
      const cone = waterlineForward(
        { toolRadiusMm: R, cornerRadiusMm: Rcr, slopeDeg: alpha, feedRadiusMm: 50 * R, crossRadiusMm: null },
        h,
      );
      if (cone.ok) expect(Math.abs(cone.value.intervalMm - w.value.intervalMm)).toBeLessThan(1e-12 * (1 + R));
    }
  });

  it('forward and inverse agree (dz and L, seed 13)', () => {
    const rand = seededRandom(13);
    for (let i = 0; i < 300; i++) {
      const R = 0.1 + 10 * rand();
      const Rcr = R * (0.02 + 0.98 * rand());
      const rc = rand() < 0.2 ? null : (rand() < 0.5 ? 1 : -1) * R * (1 + 100 * rand());
      const rf = rand() < 0.2 ? null : (rand() < 0.5 ? 1 : -1) * R * (1 + 100 * rand());
      const c: RevolutionCase = {
        toolRadiusMm: R,
        cornerRadiusMm: Rcr,
        slopeDeg: 0.01 + 89 * rand(),
        feedRadiusMm: rf,
        crossRadiusMm: rc,
      };
      const limit = waterlineHeightLimitMm(c);
      const h = Math.min(limit, Rcr) * (0.001 + 0.98 * rand());
      const f = waterlineForward(c, h);
      if (!f.ok) {
        expect(['gouging', 'past-surface', 'shank-cuts']).toContain(f.errors[0]?.code);
        continue;
      }
      for (const step of [
        { field: 'stepDown', mm: f.value.stepDownMm },
        { field: 'interval', mm: f.value.intervalMm },
      ] as const) {
        const inv = waterlineInverse(c, step);
        if (!inv.ok) throw new Error(JSON.stringify([c, h, step, inv]));
        const e = Math.abs(inv.value.cuspHeightMm - h);
        record('forward-inverse round trip (h)', e);
        expect(e).toBeLessThan(1e-10);
      }
    }
  });
});

describe('limits and refusals', () => {
  const bull = { toolRadiusMm: 3, cornerRadiusMm: 1 } as const;
  it('the shank limit on a plane is Rcr (1 - sin alpha); just below it is answered, at it refused', () => {
    for (const a of [10, 45, 75, 89]) {
      const c: RevolutionCase = { ...bull, slopeDeg: a, feedRadiusMm: null, crossRadiusMm: null };
      const expected = 1 - Math.sin((a * Math.PI) / 180);
      const limit = waterlineHeightLimitMm(c);
      expect(Math.abs(limit - expected)).toBeLessThan(1e-12);
      expect(waterlineForward(c, limit * (1 - 1e-9)).ok).toBe(true);
      const f = waterlineForward(c, limit * (1 + 1e-9));
      expect(f.ok).toBe(false);
      if (!f.ok) {
        expect(f.errors[0]).toMatchObject({ field: 'h', code: 'shank-cuts' });
        expect(Math.abs((f.errors[0]?.limit as number) - expected)).toBeLessThan(1e-12);
      }
    }
  });
  it('on a dome the shank limit is the cusp height at the L where the cusp reaches the next corner top', () => {
    const c: RevolutionCase = { ...bull, slopeDeg: 60, feedRadiusMm: 20, crossRadiusMm: 20 };
    const limit = waterlineHeightLimitMm(c);
    const below = waterlineForward(c, limit * (1 - 1e-9));
    expect(below.ok).toBe(true);
    const inv = waterlineInverse(c, { field: 'stepDown', mm: 50 });
    expect(inv.ok).toBe(false);
    if (!inv.ok && below.ok) {
      // The step-down limit is where the cusp reaches the shank: at its dz the cusp is the h limit.
      expect(inv.errors[0]).toMatchObject({ field: 'stepDown', code: 'shank-cuts' });
      const at = waterlineInverse(c, { field: 'stepDown', mm: (inv.errors[0]?.limit as number) * (1 - 1e-12) });
      expect(at.ok).toBe(true);
      if (at.ok) expect(Math.abs(at.value.cuspHeightMm - limit)).toBeLessThan(1e-9);
    }
  });
  it('a bowl: the next pass cannot go past the bottom; the limit is where it would', () => {
    const c: RevolutionCase = {
      toolRadiusMm: 1,
      cornerRadiusMm: 1,
      slopeDeg: 3,
      feedRadiusMm: -20,
      crossRadiusMm: -20,
    };
    const f = waterlineInverse(c, { field: 'interval', mm: 2 });
    expect(f.ok).toBe(false);
    if (!f.ok) {
      expect(f.errors[0]).toMatchObject({ field: 'interval', code: 'past-surface' });
      expect(f.errors[0]?.limit).toBeCloseTo((20 * 3 * Math.PI) / 180, 12);
      expect(f.errors[0]?.message).toContain('bottom');
    }
  });
  it('a step past the vertical of a convex meridian (closed form L = (90 - alpha) Rc) is refused by the first limit met on the way, the shank below the vertical (seed 15)', () => {
    // The next pass past the vertical is on an overhang no upright tool reaches: no pass is placed
    // (or checked for gouging) there. The refusal is the upper pass's own gouging, or the shank,
    // whose limit lies before the vertical (the lower contact reaches the corner's top, where the
    // shank starts, at the vertical); just inside it the cusp is the brute force's.
    const rand = seededRandom(15);
    let shank = 0;
    let brute = 0;
    for (let i = 0; i < 400; i++) {
      const R = 0.5 + 5 * rand();
      const Rcr = R * (0.1 + 0.9 * rand());
      const rc = R * (0.5 + 5 * rand());
      const rf = (rand() < 0.5 ? 1 : -1) * R * (0.5 + 5 * rand());
      const c: RevolutionCase = {
        toolRadiusMm: R,
        cornerRadiusMm: Rcr,
        slopeDeg: 30 + 59 * rand(),
        feedRadiusMm: rf,
        crossRadiusMm: rc,
      };
      const toVertical = ((90 - c.slopeDeg) * Math.PI * rc) / 180;
      const L = toVertical * (1.01 + 2 * rand());
      const r = waterlineInverse(c, { field: 'interval', mm: L });
      expect(r.ok).toBe(false);
      if (r.ok) continue;
      const e = r.errors[0];
      if (e?.code === 'gouging') {
        const upper = waterlineInverse(c, { field: 'interval', mm: 1e-6 });
        expect(!upper.ok && upper.errors[0]?.code, JSON.stringify(c)).toBe('gouging');
        continue;
      }
      shank += 1;
      expect(e?.code).toBe('shank-cuts');
      expect(e?.limit as number).toBeLessThan(toVertical);
      if (brute >= 3) continue;
      const inside = waterlineInverse(c, { field: 'interval', mm: (e?.limit as number) * (1 - 1e-6) });
      if (!inside.ok) continue;
      brute += 1;
      const b = bruteWaterlineCusp({ R, Rcr }, c, inside.value.intervalMm, 8);
      expect(Math.abs(b.polishedMm - inside.value.cuspHeightMm)).toBeLessThan(1e-9);
    }
    expect(shank).toBeGreaterThan(300);
    expect(brute).toBe(3);
  });
  it('a flat end in waterline: the side forms every cusp; alpha 90: a vertical wall; alpha 0: no step', () => {
    const flat = waterlineForward(
      { toolRadiusMm: 3, cornerRadiusMm: 0, slopeDeg: 30, feedRadiusMm: null, crossRadiusMm: null },
      0.01,
    );
    expect(!flat.ok && flat.errors[0]?.code).toBe('wall-only');
    const wall = waterlineForward({ ...bull, slopeDeg: 90, feedRadiusMm: 10, crossRadiusMm: null }, 0.01);
    expect(!wall.ok && wall.errors[0]?.code).toBe('vertical-wall');
    const floor = waterlineForward({ ...bull, slopeDeg: 0, feedRadiusMm: null, crossRadiusMm: null }, 0.01);
    expect(!floor.ok && floor.errors[0]?.code).toBe('needs-slope');
    const radius = waterlineForward({ ...bull, slopeDeg: 20, feedRadiusMm: 0, crossRadiusMm: 2e6 }, 0.01);
    expect(radius.ok ? [] : radius.errors.map((e) => e.field)).toEqual(['feedRadius', 'crossRadius']);
  });
});

describe('the up-slope cusp for a constant step-down', () => {
  it('is the pair whose lower pass is this one; equal to the down-slope cusp on a plane, not on a curved meridian (seed 14)', () => {
    const rand = seededRandom(14);
    let curved = 0;
    for (let i = 0; i < 100; i++) {
      const R = 0.5 + 6 * rand();
      const Rcr = R * (0.1 + 0.9 * rand());
      const rc = rand() < 0.2 ? null : (rand() < 0.5 ? 1 : -1) * R * (3 + 30 * rand());
      const rf = rand() < 0.3 ? null : (rand() < 0.5 ? 1 : -1) * R * (3 + 30 * rand());
      const c: RevolutionCase = {
        toolRadiusMm: R,
        cornerRadiusMm: Rcr,
        slopeDeg: 10 + 70 * rand(),
        feedRadiusMm: rf,
        crossRadiusMm: rc,
      };
      const down = waterlineForward(c, Rcr * 0.01 * (0.1 + rand()));
      if (!down.ok) continue;
      const dz = down.value.stepDownMm;
      const up = waterlineCuspAbove(c, dz);
      if (!up.ok) {
        expect(['gouging', 'past-surface', 'shank-cuts']).toContain(up.errors[0]?.code);
        continue;
      }
      // The pair's lower pass is this pass: its slope, the same dz.
      expect(Math.abs(up.value.slopeNextDeg - c.slopeDeg)).toBeLessThan(1e-9);
      expect(Math.abs(up.value.stepDownMm - dz)).toBeLessThan(1e-12 * (1 + dz));
      if (rc === null) expect(Math.abs(up.value.cuspHeightMm - down.value.cuspHeightMm)).toBeLessThan(1e-12);
      else if (Math.abs(up.value.cuspHeightMm - down.value.cuspHeightMm) > 1e-6 * down.value.cuspHeightMm) curved += 1;
    }
    expect(curved).toBeGreaterThan(20);
  });
});
