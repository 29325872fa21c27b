import { afterAll, describe, expect, it } from 'vitest';
import { forwardInput, inverseInput } from '../../../src/core/input/validate';
import { answerQuestion, validateQuestion } from '../../../src/core/surfaces/question';
import { exactIntervalMm, exactInverse } from '../../../src/core/surfaces/solve';
import { slopedPlaneForward, slopedPlaneIntervalMm, slopedPlaneInverse } from '../../../src/core/threeAxis/slopedPlane';
import { seededRandom } from '../../support/bruteForce';
import { bruteRasterCusp } from '../../support/reference/threeAxisBruteForce';

/**
 * Raster and waterline on a sloped plane against the machine-frame brute force (the upright tool's
 * slices translated along the raster line, the material left sampled in the cross-section), the
 * closed forms (ball end: L = 2 sqrt(2Rh - h^2) at every slope and direction; alpha = 0: the flat
 * floor) and the posture solver's own inverse. Stratified over alpha, psi and the tool; each case
 * names its seed. The largest errors per family are printed at the end.
 */
const worst = new Map<string, number>();
const record = (k: string, e: number) => worst.set(k, Math.max(worst.get(k) ?? 0, e));
afterAll(() => {
  const rows = [...worst].map(([k, v]) => `  ${k.padEnd(52)} ${v.toExponential(2)} mm`);
  console.info(`Sloped plane, largest errors:\n${rows.join('\n')}`);
});

const TOOLS = [
  { name: 'ball', R: 3, Rcr: 3 },
  { name: 'flat', R: 3, Rcr: 0 },
  { name: 'bull-nose', R: 3, Rcr: 1 },
  { name: 'bull-nose 6/2', R: 6, Rcr: 2 },
] as const;
const ALPHAS = [0, 1e-6, 5, 30, 60, 85, 89.9];
const PSIS = [0, 45, 90];

describe('raster on a sloped plane against the brute force (polished to 1e-9 mm)', () => {
  let seed = 100;
  for (const tool of TOOLS)
    for (const alpha of ALPHAS)
      for (const psi0 of PSIS) {
        seed += 1;
        const s = seed;
        it(`${tool.name}, alpha ${alpha}, psi ~${psi0}, seed ${s}`, () => {
          const rand = seededRandom(s);
          const psi = Math.min(90, Math.max(0, psi0 + (psi0 === 45 ? 30 * (rand() - 0.5) : 0)));
          const c = {
            toolRadiusMm: tool.R,
            cornerRadiusMm: tool.Rcr,
            slopeDeg: alpha,
            passes: 'raster',
            rasterAngleDeg: psi,
          } as const;
          const probe = slopedPlaneForward(c, 1e-9);
          if (!probe.ok) {
            // Only a flat end, tilted or with its flank top below 1 nm, has no scallop flank.
            expect(['wall-only', 'flank-wall', 'shank-cuts']).toContain(probe.errors[0]?.code);
            expect(tool.Rcr).toBe(0);
            return;
          }
          const limit = Math.min(probe.value.heightLimitMm, 0.6 * tool.Rcr + 0.2);
          const h = Number.isFinite(limit) ? Math.max(1e-9, limit * (0.02 + 0.9 * rand())) : 0.05;
          const f = slopedPlaneForward(c, h);
          expect(f.ok, JSON.stringify(f)).toBe(true);
          if (!f.ok) return;
          // No scallop (a flat end on a flat floor, L = 2R): passes just inside 2R leave none either
          // (at 2R exactly the rounding of the placement can open a gap of 1e-16 mm, an uncut ridge).
          const b = bruteRasterCusp(tool, alpha, psi, f.value.intervalMm * (f.value.noScallop ? 0.999 : 1), 24);
          const expected = f.value.noScallop ? 0 : h;
          record(`raster forward, ${tool.name}`, Math.abs(b.polishedMm - expected));
          expect(Math.abs(b.polishedMm - expected)).toBeLessThan(1e-9);
          expect(Math.abs(b.sampledMm - expected)).toBeLessThanOrEqual(b.boundMm + 1e-12);
          // Inverse from the programmed Lxy, and a step 0.8 as wide, against the brute force.
          if (!f.value.noScallop) {
            const inv = slopedPlaneInverse(c, { field: 'horizontalStep', mm: 0.8 * f.value.horizontalStepMm });
            expect(inv.ok).toBe(true);
            if (inv.ok) {
              const bi = bruteRasterCusp(tool, alpha, psi, inv.value.intervalMm, 24);
              record(`raster inverse, ${tool.name}`, Math.abs(bi.polishedMm - inv.value.cuspHeightMm));
              expect(Math.abs(bi.polishedMm - inv.value.cuspHeightMm)).toBeLessThan(1e-9);
            }
          }
        });
      }

  it('the sampled estimate stays within its bound, and the bound shrinks with refinement (bull-nose, alpha 40, psi 30)', () => {
    const c = { toolRadiusMm: 3, cornerRadiusMm: 1, slopeDeg: 40, passes: 'raster', rasterAngleDeg: 30 } as const;
    const f = slopedPlaneForward(c, 0.05);
    if (!f.ok) throw new Error('solvable');
    const bounds = [8, 32, 128].map((cols) => {
      const b = bruteRasterCusp({ R: 3, Rcr: 1 }, 40, 30, f.value.intervalMm, cols);
      expect(Math.abs(b.sampledMm - 0.05)).toBeLessThanOrEqual(b.boundMm);
      return b.boundMm;
    });
    expect(bounds[1]).toBeLessThan((bounds[0] as number) / 3);
    expect(bounds[2]).toBeLessThan((bounds[1] as number) / 3);
  });
});

describe('closed forms and the posture solver', () => {
  it('a ball end leaves L = 2 sqrt(2Rh - h^2) at every slope and direction (seed 7)', () => {
    const rand = seededRandom(7);
    for (let i = 0; i < 300; i++) {
      const R = 0.01 + 20 * rand();
      const alpha = 89.9 * rand();
      const psi = 90 * rand();
      const h = R * (1e-6 + 0.3 * rand());
      const c = { toolRadiusMm: R, cornerRadiusMm: R, slopeDeg: alpha, passes: 'raster', rasterAngleDeg: psi } as const;
      const f = slopedPlaneForward(c, h);
      if (!f.ok) {
        // Refused only where the shank would form the cusp: R (1 - sin beta') <= h.
        expect(f.errors[0]?.code).toBe('shank-cuts');
        expect(h).toBeGreaterThanOrEqual(f.errors[0]?.limit as number);
        continue;
      }
      const e = Math.abs(f.value.intervalMm - 2 * Math.sqrt(2 * R * h - h * h));
      record('ball closed form (L)', e);
      expect(e).toBeLessThan(1e-9 * Math.max(1, R));
    }
  });

  it('alpha = 0 is the upright tool on a flat floor: L = 2 (R - Rcr + sqrt(2 Rcr h - h^2)), any psi (seed 8)', () => {
    const rand = seededRandom(8);
    for (let i = 0; i < 100; i++) {
      const R = 0.1 + 10 * rand();
      const Rcr = R * rand();
      const h = Rcr * (0.001 + 0.9 * rand());
      const c = {
        toolRadiusMm: R,
        cornerRadiusMm: Rcr,
        slopeDeg: 0,
        passes: 'raster',
        rasterAngleDeg: 90 * rand(),
      } as const;
      const f = slopedPlaneForward(c, h);
      if (!f.ok) throw new Error(JSON.stringify(f));
      const e = Math.abs(f.value.intervalMm - 2 * (R - Rcr + Math.sqrt(2 * Rcr * h - h * h)));
      record('flat floor closed form (L)', e);
      expect(e).toBeLessThan(1e-9);
      expect(f.value.horizontalStepMm).toBe(f.value.intervalMm);
    }
    // A flat end on a flat floor: no scallop, L = 2R.
    const flat = slopedPlaneForward(
      { toolRadiusMm: 2, cornerRadiusMm: 0, slopeDeg: 0, passes: 'raster', rasterAngleDeg: 0 },
      0.1,
    );
    expect(flat.ok && flat.value).toMatchObject({ intervalMm: 4, noScallop: true, cuspHeightMm: 0 });
  });

  it('a flat end on a flat floor steps over its diameter 2R: the fast path, forward, inverse and surface model alike, as the brute force (seed 10)', () => {
    // The flat bottom, a disk of radius R, sweeps a strip 2R wide and leaves no scallop: adjacent
    // strips just touch at L = 2R (the tool's diameter; the brute force finds no cusp there), and any
    // wider step leaves a ridge of uncut floor. Any h, any raster angle.
    const rand = seededRandom(10);
    for (let i = 0; i < 50; i++) {
      const R = 0.001 + 999.999 * rand() ** 3;
      const c = {
        toolRadiusMm: R,
        cornerRadiusMm: 0,
        slopeDeg: 0,
        passes: 'raster',
        rasterAngleDeg: 90 * rand(),
      } as const;
      const h = R * 10 ** (-6 + 6 * rand());
      expect(slopedPlaneIntervalMm(c, h)).toBe(2 * R);
      const f = slopedPlaneForward(c, h);
      expect(f.ok && f.value).toMatchObject({ intervalMm: 2 * R, horizontalStepMm: 2 * R, noScallop: true });
      // The plane under the three-axis mode (the posture supplier) answers the same.
      const mode = { kind: 'threeAxis', slopeDeg: 0, passes: 'raster', rasterAngleDeg: c.rasterAngleDeg } as const;
      const q = validateQuestion({
        tool: { toolRadiusMm: R, cornerRadiusMm: 0 },
        mode,
        surface: { kind: 'plane' },
        pattern: 'zigzag',
        target: { quantity: 'h', mm: h },
      });
      expect(q.ok && answerQuestion(q.value).intervalMm).toBe(2 * R);
      const at = slopedPlaneInverse(c, { field: 'horizontalStep', mm: 2 * R });
      expect(at.ok && at.value).toMatchObject({ intervalMm: 2 * R, cuspHeightMm: 0, noScallop: true });
      const wider = slopedPlaneInverse(c, { field: 'horizontalStep', mm: 2 * R * (1 + 1e-9) });
      expect(!wider.ok && wider.errors[0]).toMatchObject({
        field: 'horizontalStep',
        code: 'beyond-step',
        limit: 2 * R,
      });
      if (i < 3) {
        const b = bruteRasterCusp({ R, Rcr: 0 }, 0, c.rasterAngleDeg, 2 * R, 8);
        expect(Math.abs(b.polishedMm)).toBeLessThan(1e-12 * R);
      }
    }
  });

  it('the inverse equals the posture solver at the same lead and tilt; Lxy and dz follow from L (seed 9)', () => {
    const rand = seededRandom(9);
    for (let i = 0; i < 200; i++) {
      const R = 0.5 + 10 * rand();
      const Rcr = R * (0.05 + 0.95 * rand());
      const alpha = 80 * rand();
      const waterline = rand() < 0.3;
      const c = {
        toolRadiusMm: R,
        cornerRadiusMm: Rcr,
        slopeDeg: waterline ? Math.max(alpha, 0.1) : alpha,
        passes: waterline ? 'waterline' : 'raster',
        rasterAngleDeg: 90 * rand(),
      } as const;
      const probe = slopedPlaneForward(c, 1e-7);
      if (!probe.ok) continue;
      const h = Math.min(probe.value.heightLimitMm, Rcr) * (0.01 + 0.9 * rand());
      const f = slopedPlaneForward(c, h);
      if (!f.ok) throw new Error(JSON.stringify(f));
      const tool = {
        toolRadiusMm: R,
        cornerRadiusMm: Rcr,
        leadAngleDeg: f.value.leadDeg,
        tiltAngleDeg: f.value.tiltDeg,
      };
      const eL = Math.abs(f.value.intervalMm - exactIntervalMm(forwardInput(tool, 'one-way', h)));
      record('forward vs posture solver (L)', eL);
      expect(eL).toBeLessThan(1e-12 * (1 + R));
      const step = waterline
        ? ({ field: 'stepDown', mm: f.value.stepDownMm as number } as const)
        : ({ field: 'horizontalStep', mm: f.value.horizontalStepMm } as const);
      const inv = slopedPlaneInverse(c, step);
      if (!inv.ok) throw new Error(JSON.stringify(inv));
      const eh = Math.abs(inv.value.cuspHeightMm - h);
      record('inverse round trip (h)', eh);
      expect(eh).toBeLessThan(1e-9);
      const eInv = Math.abs(
        inv.value.cuspHeightMm - exactInverse(inverseInput(tool, 'one-way', f.value.intervalMm)).cuspHeightMm,
      );
      expect(eInv).toBeLessThan(1e-9);
      if (waterline) {
        expect(f.value.stepDownMm).toBeCloseTo(f.value.intervalMm * Math.sin((c.slopeDeg * Math.PI) / 180), 12);
        expect(f.value.horizontalStepMm).toBeCloseTo(f.value.intervalMm * Math.cos((c.slopeDeg * Math.PI) / 180), 12);
      } else expect(f.value.stepDownMm).toBeNull();
    }
  });
});

describe('refusals', () => {
  const bull = { toolRadiusMm: 3, cornerRadiusMm: 1 } as const;
  it('a vertical wall leaves no scallop: no step', () => {
    const f = slopedPlaneForward({ ...bull, slopeDeg: 90, passes: 'raster', rasterAngleDeg: 0 }, 0.01);
    expect(f.ok).toBe(false);
    if (!f.ok) {
      expect(f.errors[0]).toMatchObject({ field: 'slope', code: 'vertical-wall' });
      expect(f.errors[0]?.message).toContain('no scallop');
    }
  });
  it('waterline at 75 degrees: the shank forms the cusp above Rcr (1 - sin alpha)', () => {
    const c = { ...bull, slopeDeg: 75, passes: 'waterline', rasterAngleDeg: 0 } as const;
    const limit = 1 - Math.sin((75 * Math.PI) / 180);
    const f = slopedPlaneForward(c, 0.05);
    expect(f.ok).toBe(false);
    if (!f.ok) {
      expect(f.errors[0]).toMatchObject({ field: 'h', code: 'shank-cuts' });
      expect(f.errors[0]?.limit).toBeCloseTo(limit, 14);
      expect(f.errors[0]?.message).toContain('0.034074174 mm');
    }
    expect(slopedPlaneForward(c, limit * (1 - 1e-9)).ok).toBe(true);
    if (!f.ok) expect(slopedPlaneForward(c, f.errors[0]?.limit as number).ok).toBe(false);
  });
  it('a step beyond the widest one is refused in its own terms; just below it is answered', () => {
    const c = { ...bull, slopeDeg: 50, passes: 'waterline', rasterAngleDeg: 0 } as const;
    const f = slopedPlaneInverse(c, { field: 'stepDown', mm: 5 });
    expect(f.ok).toBe(false);
    if (!f.ok) {
      // Beyond it the shank would form the cusp: dz < Rcr sin(2 alpha) above 45 degrees.
      expect(f.errors[0]).toMatchObject({ field: 'stepDown', code: 'shank-cuts' });
      expect(f.errors[0]?.limit).toBeCloseTo(Math.sin((100 * Math.PI) / 180), 12);
      const limit = f.errors[0]?.limit as number;
      const just = slopedPlaneInverse(c, { field: 'stepDown', mm: limit * (1 - 1e-9) });
      expect(just.ok).toBe(true);
      if (just.ok) expect(just.value.cuspHeightMm).toBeCloseTo(1 - Math.sin((50 * Math.PI) / 180), 6);
    }
  });
  it('bad inputs: one line each, no NaN', () => {
    const cases = [
      slopedPlaneForward({ ...bull, slopeDeg: -1, passes: 'raster', rasterAngleDeg: 0 }, 0.01),
      slopedPlaneForward({ ...bull, slopeDeg: 30, passes: 'raster', rasterAngleDeg: 91 }, 0.01),
      slopedPlaneForward({ ...bull, slopeDeg: 0, passes: 'waterline', rasterAngleDeg: 0 }, 0.01),
      slopedPlaneForward({ ...bull, slopeDeg: 30, passes: 'raster', rasterAngleDeg: 0 }, Number.NaN),
      slopedPlaneForward(
        { toolRadiusMm: 3, cornerRadiusMm: 0, slopeDeg: 30, passes: 'waterline', rasterAngleDeg: 0 },
        0.01,
      ),
      slopedPlaneInverse({ ...bull, slopeDeg: 30, passes: 'raster', rasterAngleDeg: 0 }, { field: 'stepDown', mm: 1 }),
    ];
    const codes = cases.map((r) => (r.ok ? 'ok' : r.errors.map((e) => e.code).join()));
    expect(codes).toEqual(['out-of-range', 'out-of-range', 'needs-slope', 'out-of-range', 'wall-only', 'out-of-range']);
    for (const r of cases)
      if (!r.ok)
        for (const e of r.errors) {
          expect(e.message).not.toMatch(/\n|NaN mm|Infinity/);
          expect(e.limit === null || Number.isFinite(e.limit)).toBe(true);
        }
  });
});
