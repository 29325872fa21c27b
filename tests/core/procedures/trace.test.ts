import { describe, expect, it } from 'vitest';
import { passGeometry } from '../../../src/core/output/geometry';
import { PAPER_CONDITIONS } from '../../../src/core/procedures/paper';
import { traceProcedure } from '../../../src/core/procedures/trace';
import { exactHalfIntervalMm } from '../../../src/core/surfaces/solve';
import { seededRandom } from '../../support/bruteForce';

const DEG = Math.PI / 180;
const input = (R: number, Rcr: number, rho: number, h: number) => ({
  toolRadiusMm: R,
  cornerRadiusMm: Rcr,
  leadAngleDeg: rho,
  tiltAngleDeg: 0,
  pattern: 'one-way' as const,
  surface: { kind: 'plane' as const },
  scallopHeightMm: h,
});

describe("the paper's 3D procedure (Figure 1) as a trace", () => {
  for (const c of PAPER_CONDITIONS) {
    it(`converges to the exact L/2 within 1e-9 mm: R=${c.R} Rcr=${c.Rcr} rho=${c.rho} h=${c.h}`, () => {
      const t = traceProcedure(input(c.R, c.Rcr, c.rho, c.h));
      expect(Math.abs(t.right.widthMm - exactHalfIntervalMm(input(c.R, c.Rcr, c.rho, c.h)))).toBeLessThan(1e-9);
    });
  }

  it('records the approach, a single-contact section with d_s = Rcr, and search passes that narrow', () => {
    const t = traceProcedure(input(3, 1, 5, 0.1));
    const phases = t.steps.map((s) => s.phase);
    expect(phases[0]).toBe('approach');
    const scp = t.steps.find((s) => s.phase === 'single-contact');
    expect(scp && scp.phase === 'single-contact' && scp.found).toBe(true);
    if (scp?.phase === 'single-contact') {
      expect(Math.abs(scp.dsMm - 1)).toBeLessThan(1e-12);
      // Its touching point P_hp lies on the h pseudo plane.
      expect(scp.pHp[2]).toBeCloseTo(0.1, 12);
    }
    const searches = t.steps.filter((s) => s.phase === 'search' && s.flank === 'right');
    expect(searches.length).toBeGreaterThan(3);
    const widths = searches.map((s) => (s.phase === 'search' ? s.rangeRad[1] - s.rangeRad[0] : 0));
    for (let i = 1; i < widths.length; i++) expect(widths[i]).toBeLessThan(widths[i - 1] as number);
    // The converged section is the exact solver's section gamma*.
    expect(
      Math.abs(t.right.ringAngleRad - passGeometry(input(3, 1, 5, 0.1), 0.1, 0.1, 8).right.ringAngleRad),
    ).toBeLessThan(1e-5);
  });

  it('Eq. 1 gives the starting ring angle: Rb sin(rho)(1 - cos gamma) = h/2', () => {
    const t = traceProcedure(input(6, 2, 10, 0.05));
    const first = t.steps[0];
    const b = 4 * Math.sin(10 * DEG);
    if (first?.phase !== 'approach') throw new Error('the trace starts with the approach');
    expect(b * (1 - Math.cos(first.ringAngleRad))).toBeCloseTo(0.025, 14);
  });

  it('rho = 0: every section meets the plane (no single contact) and the result is Rb + sqrt(2 Rcr h - h^2)', () => {
    const t = traceProcedure(input(3, 1, 0, 0.05));
    const scp = t.steps.find((s) => s.phase === 'single-contact');
    expect(scp?.phase === 'single-contact' && scp.found).toBe(false);
    expect(Math.abs(t.right.widthMm - (2 + Math.sqrt(0.1 - 0.0025)))).toBeLessThan(1e-9);
  });

  it('flat end (Rcr = 0): the ring itself reaches the plane', () => {
    const t = traceProcedure(input(4, 0, 20, 0.3));
    expect(Math.abs(t.right.widthMm - exactHalfIntervalMm(input(4, 0, 20, 0.3)))).toBeLessThan(1e-9);
  });

  for (const seed of [7, 42, 1234]) {
    it(`seed ${seed}: 25 random cases (h up to the limit, h > 2 Rcr included) agree with the exact solver within 1e-9 mm`, () => {
      const rand = seededRandom(seed);
      for (let k = 0; k < 25; k++) {
        const R = 0.2 + rand() * 20;
        const Rcr = R * rand();
        const rho = rand() * 89.9;
        const limit = (R - Rcr) * Math.sin(rho * DEG) + Rcr;
        const h = limit * (1e-4 + 0.999 * rand());
        const c = input(R, Rcr, rho, h);
        expect(Math.abs(traceProcedure(c).right.widthMm - exactHalfIntervalMm(c)), JSON.stringify(c)).toBeLessThan(
          1e-9,
        );
      }
    });
  }
});

describe('the trace in the placement of the tool', () => {
  it('its P_hp lie on the torus of the placed tool, also for a flat bottom lying on the plane', () => {
    for (const [R, Rcr, rho, tilt, h] of [
      [3, 1, 0, 0, 0.05],
      [3, 1, 5, 10, 0.05],
    ] as const) {
      const t = traceProcedure({ ...input(R, Rcr, rho, h), tiltAngleDeg: tilt });
      const p = t.placement;
      for (const f of [t.right, t.left]) {
        const dx = f.pHp[0] - p.centre[0];
        const dy = f.pHp[1] - p.centre[1];
        const dz = f.pHp[2] - p.centre[2];
        const w = dx * p.axis[0] + dy * p.axis[1] + dz * p.axis[2];
        const radial = Math.hypot(dx - w * p.axis[0], dy - w * p.axis[1], dz - w * p.axis[2]);
        expect(Math.abs(Math.hypot(radial - p.ringRadiusMm, w) - Rcr)).toBeLessThan(1e-12);
      }
    }
  });
});
