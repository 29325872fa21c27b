import { describe, expect, it } from 'vitest';
import { passGeometry } from '../../../src/core/output/geometry';
import { PAPER_CONDITIONS } from '../../../src/core/procedures/paper';
import { exactForward, exactHalfIntervalMm, exactScallopHeightMm } from '../../../src/core/surfaces/solve';
import { placeTool } from '../../../src/core/tool/placement';
import { bruteForceHalfIntervalMm, seededRandom } from '../../support/bruteForce';

const tool = (R: number, Rcr: number, rho: number) => ({
  toolRadiusMm: R,
  cornerRadiusMm: Rcr,
  leadAngleDeg: rho,
  tiltAngleDeg: 0,
});
const input = (R: number, Rcr: number, rho: number, h: number) => ({
  ...tool(R, Rcr, rho),
  pattern: 'one-way' as const,
  surface: { kind: 'plane' as const },
  scallopHeightMm: h,
});
const atHalf = (R: number, Rcr: number, rho: number, half: number) => ({
  ...tool(R, Rcr, rho),
  pattern: 'one-way' as const,
  surface: { kind: 'plane' as const },
  intervalMm: 2 * half,
});
const DEG = Math.PI / 180;
const TOL = 1e-9;

describe('exact solver against the exact column of notes/geometry.md', () => {
  for (const c of PAPER_CONDITIONS) {
    it(`R=${c.R} Rcr=${c.Rcr} rho=${c.rho} h=${c.h} -> ${c.notesExactHalf}`, () => {
      expect(Math.abs(exactHalfIntervalMm(input(c.R, c.Rcr, c.rho, c.h)) - c.notesExactHalf)).toBeLessThan(TOL);
    });
  }
});

describe("the paper's printed 3D column", () => {
  // The printed 3D values lie 0.0005-0.013 mm below the exact ones: Figure 1's search
  // range (steps 15-16) can end before the true maximum (notes, "The paper's tables").
  // So they agree within 0.015 mm, and are never above the exact value beyond rounding.
  for (const c of PAPER_CONDITIONS) {
    it(`R=${c.R} Rcr=${c.Rcr} rho=${c.rho} h=${c.h}: printed ${c.printedHalf.threeD} is within 0.015 mm below exact`, () => {
      const exact = exactHalfIntervalMm(input(c.R, c.Rcr, c.rho, c.h));
      expect(exact - c.printedHalf.threeD).toBeLessThan(0.015);
      expect(exact - c.printedHalf.threeD).toBeGreaterThan(-0.0005);
    });
  }
});

describe('closed-form limits (notes, "Limits worth testing")', () => {
  it('rho = 0: L/2 = Rb + sqrt(2 Rcr h - h^2)', () => {
    for (const [R, Rcr, h] of [
      [3, 1, 0.05],
      [6, 2, 1.5],
      [10, 0.5, 1e-7],
      [1, 0.999, 0.9],
    ] as const) {
      const expected = R - Rcr + Math.sqrt(2 * Rcr * h - h * h);
      expect(Math.abs(exactHalfIntervalMm(input(R, Rcr, 0, h)) - expected)).toBeLessThan(TOL);
    }
  });

  it('ball end (Rcr = R): L/2 = sqrt(2 R h - h^2) at every rho', () => {
    for (const rho of [0, 1e-6, 5, 33.3, 89.999]) {
      for (const h of [1e-9, 0.01, 1.2, 2.99]) {
        const expected = Math.sqrt(2 * 3 * h - h * h);
        expect(Math.abs(exactHalfIntervalMm(input(3, 3, rho, h)) - expected)).toBeLessThan(TOL);
      }
    }
  });

  it('flat end (Rcr = 0, rho > 0): L/2 = Rb sqrt(1 - (1 - h/(Rb sin rho))^2)', () => {
    for (const rho of [0.01, 5, 45, 89.99]) {
      const b = 4 * Math.sin(rho * DEG);
      for (const frac of [1e-9, 0.1, 0.5, 0.999999]) {
        const h = frac * b;
        const expected = 4 * Math.sqrt(1 - (1 - h / b) ** 2);
        expect(Math.abs(exactHalfIntervalMm(input(4, 0, rho, h)) - expected)).toBeLessThan(TOL);
      }
    }
  });

  it("Redonnet's Reff is the osculating circle: for h -> 0, L/2 -> sqrt(2 Reff h)", () => {
    const reff = 2 / Math.sin(5 * DEG) + 1;
    const h = 1e-8;
    const l = exactHalfIntervalMm(input(3, 1, 5, h));
    // Relative agreement improves with h; at 1e-8 mm it is better than 1e-5.
    expect(Math.abs(l / Math.sqrt(2 * reff * h - h * h) - 1)).toBeLessThan(1e-5);
  });

  it('h close to the corner height: L/2 approaches R and still matches brute force', () => {
    const limit = 2 * Math.sin(30 * DEG) + 1;
    for (const frac of [1 - 1e-3, 1 - 1e-6]) {
      const l = exactHalfIntervalMm(input(3, 1, 30, limit * frac));
      expect(l).toBeLessThanOrEqual(3);
      expect(Math.abs(l - bruteForceHalfIntervalMm(3, 1, 30, limit * frac))).toBeLessThan(TOL);
    }
    // Near the widest point R - L/2 shrinks with the square of (limit - h): L/2 rounds to R.
    expect(exactHalfIntervalMm(input(3, 1, 30, limit * (1 - 1e-12)))).toBeCloseTo(3, 12);
  });

  it('rho close to 90 degrees: the profile tends to a circle of radius R', () => {
    const l = exactHalfIntervalMm(input(3, 1, 89.9999999, 0.1));
    expect(Math.abs(l - Math.sqrt(2 * 3 * 0.1 - 0.01))).toBeLessThan(1e-6);
    expect(Math.abs(l - bruteForceHalfIntervalMm(3, 1, 89.9999999, 0.1))).toBeLessThan(TOL);
  });
});

describe('exact solver against brute-force sampling of the implicit torus', () => {
  for (const seed of [1, 2, 3, 20261122]) {
    it(`seed ${seed}: 6 random tools and heights agree within 1e-9 mm`, () => {
      const rand = seededRandom(seed);
      for (let k = 0; k < 6; k++) {
        const R = 0.5 + rand() * 12;
        const Rcr = R * (0.05 + 0.95 * rand());
        const rho = rand() * 89;
        const limit = (R - Rcr) * Math.sin(rho * DEG) + Rcr;
        const h = limit * (0.001 + 0.99 * rand() ** 2);
        const exact = exactHalfIntervalMm(input(R, Rcr, rho, h));
        const brute = bruteForceHalfIntervalMm(R, Rcr, rho, h);
        expect(Math.abs(exact - brute), `R=${R} Rcr=${Rcr} rho=${rho} h=${h}`).toBeLessThan(TOL);
      }
    });
  }
});

describe('exact inverse', () => {
  it('returns the h it was solved for (paper conditions)', () => {
    for (const c of PAPER_CONDITIONS) {
      const half = exactHalfIntervalMm(input(c.R, c.Rcr, c.rho, c.h));
      const h = exactScallopHeightMm(atHalf(c.R, c.Rcr, c.rho, half));
      expect(Math.abs(h - c.h)).toBeLessThan(TOL);
    }
  });

  it('is 0 on the flat bottom at rho = 0 and follows the corner circle beyond it', () => {
    expect(exactScallopHeightMm(atHalf(3, 1, 0, 1.5))).toBe(0);
    expect(exactScallopHeightMm(atHalf(3, 1, 0, 2.6))).toBeCloseTo(1 - Math.sqrt(1 - 0.36), 12);
  });

  it("gives the paper's printed 3D heights (Tables 4-5) within what the printed L/2 allows", () => {
    // Tables 4-5 feed the printed (low) 3D L/2 back in, so exact h there is below the printed
    // h by at most (exact L/2 - printed L/2) times the profile slope tan(theta) at the exact
    // L/2 (the slope only grows with L/2), plus the rounding of the printed h.
    for (const c of PAPER_CONDITIONS) {
      const sol = exactForward(input(c.R, c.Rcr, c.rho, c.h));
      const h = exactScallopHeightMm(atHalf(c.R, c.Rcr, c.rho, c.printedHalf.threeD));
      const allowed = (sol.halfIntervalMm - c.printedHalf.threeD) * Math.tan(sol.right.normalAngleRad) + 0.0005;
      expect(c.printedHeight.threeD - h).toBeGreaterThanOrEqual(-0.0005);
      expect(c.printedHeight.threeD - h).toBeLessThanOrEqual(allowed);
    }
  });
});

/** Signed distance (mm) from a point to the surface of the tool's torus in its placement. */
function torusDistanceMm(t: ReturnType<typeof tool>, q: readonly number[]): number {
  const p = placeTool(t);
  const dx = (q[0] as number) - p.centre[0];
  const dy = (q[1] as number) - p.centre[1];
  const dz = (q[2] as number) - p.centre[2];
  const w = dx * p.axis[0] + dy * p.axis[1] + dz * p.axis[2];
  const radial = Math.hypot(dx - w * p.axis[0], dy - w * p.axis[1], dz - w * p.axis[2]);
  return Math.hypot(radial - p.ringRadiusMm, w) - p.cornerRadiusMm;
}

describe('viewer geometry', () => {
  const t = tool(3, 1, 5);
  const half = exactHalfIntervalMm(input(3, 1, 5, 0.05));
  const sol = passGeometry(t, 0.05, 0.05, 64);
  const rho = 5 * DEG;

  it('P_hp lies on the h pseudo plane at Y = L/2, on the torus and on the section circle', () => {
    expect(Math.abs(sol.right.pHp[1] - half)).toBeLessThan(1e-12);
    expect(sol.right.pHp[2]).toBeCloseTo(0.05, 14);
    expect(Math.abs(torusDistanceMm(t, sol.right.pHp))).toBeLessThan(1e-12);
    const { sectionCentre: centre, sectionNormal: normal, sectionRadiusMm: radiusMm } = sol.right;
    const d = [sol.right.pHp[0] - centre[0], sol.right.pHp[1] - centre[1], sol.right.pHp[2] - centre[2]] as const;
    expect(Math.hypot(...d)).toBeCloseTo(radiusMm, 12);
    expect(d[0] * normal[0] + d[1] * normal[1] + d[2] * normal[2]).toBeCloseTo(0, 12);
  });

  it('the tool centre is at Z_tc = Rb sin(rho) + Rcr (Eq. 7) above the contact, which is at the origin', () => {
    expect(sol.toolCentre[2]).toBeCloseTo(2 * Math.sin(rho) + 1, 14);
    expect(sol.toolCentre[1]).toBe(0);
    expect(sol.toolAxis[0]).toBeCloseTo(Math.sin(rho), 15);
    expect(Math.abs(torusDistanceMm(t, [0, 0, 0]))).toBeLessThan(1e-14);
  });

  it('every intersection-loop point is on the torus and on the plane, and the loop reaches P_hp exactly', () => {
    expect(sol.loopsRight.length).toBe(1);
    const loop = sol.loopsRight[0] as Float64Array;
    let maxY = Number.NEGATIVE_INFINITY;
    for (let i = 0; i < loop.length; i += 3) {
      const q = [loop[i] as number, loop[i + 1] as number, loop[i + 2] as number];
      expect(q[2]).toBeCloseTo(0.05, 12);
      expect(Math.abs(torusDistanceMm(t, q))).toBeLessThan(1e-12);
      maxY = Math.max(maxY, q[1] as number);
    }
    expect(Math.abs(maxY - half)).toBeLessThan(1e-12);
  });

  it('flat end (Rcr = 0): the plane cuts the flat bottom along a chord whose ends are at z = h and Y = +-L/2', () => {
    const flatEnd = passGeometry(tool(3, 0, 5), 0.05, 0.05, 32);
    expect(flatEnd.loopsRight.length).toBe(1);
    const chord = flatEnd.loopsRight[0] as Float64Array;
    expect(chord.length).toBe(6);
    // Closed form for the flat end (see the limits above): L/2 = Rb sqrt(1 - (1 - h/(Rb sin rho))^2).
    const q = 1 - 0.05 / (3 * Math.sin((5 * Math.PI) / 180));
    const halfFlat = 3 * Math.sqrt(1 - q * q);
    expect(chord[2]).toBeCloseTo(0.05, 12);
    expect(chord[5]).toBeCloseTo(0.05, 12);
    expect(Math.max(chord[1] as number, chord[4] as number)).toBeCloseTo(halfFlat, 12);
    expect(Math.min(chord[1] as number, chord[4] as number)).toBeCloseTo(-halfFlat, 12);
    expect(chord[0]).toBeCloseTo(chord[3] as number, 12);
  });

  it('rho = 0 gives two concentric loops (outer and inner crossing of the corner)', () => {
    const flat = passGeometry(tool(3, 1, 0), 0.05, 0.05, 32);
    expect(flat.loopsRight.length).toBe(2);
  });

  it('the profile runs from -R to R, is symmetric, starts at height 0 and passes through (L/2, h)', () => {
    const p = sol.profile;
    expect(p[0]).toBeCloseTo(-3, 12);
    expect(p[p.length - 2]).toBeCloseTo(3, 12);
    let minZ = Number.POSITIVE_INFINITY;
    for (let i = 1; i < p.length; i += 2) minZ = Math.min(minZ, p[i] as number);
    expect(minZ).toBe(0);
    // Linear interpolation of the polyline at L/2 is within its sampling error of h.
    for (let i = 0; i + 2 < p.length; i += 2) {
      const y0 = p[i] as number;
      const y1 = p[i + 2] as number;
      if (y0 <= half && half <= y1) {
        const z = (p[i + 1] as number) + (((p[i + 3] as number) - (p[i + 1] as number)) * (half - y0)) / (y1 - y0);
        expect(Math.abs(z - 0.05)).toBeLessThan(2e-3);
      }
    }
  });

  it('a flat-bottom profile (rho = 0) keeps the flat segment from -Rb to Rb', () => {
    const p = passGeometry(tool(3, 1, 0), 0.05, 0.05, 16).profile;
    const flat: number[] = [];
    for (let i = 0; i < p.length; i += 2) if (p[i + 1] === 0) flat.push(p[i] as number);
    expect(flat).toEqual([-2, 2]);
  });
});
