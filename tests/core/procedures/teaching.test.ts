import { describe, expect, it } from 'vitest';
import { forwardInput } from '../../../src/core/input/validate';
import {
  bediHalfInterval,
  redonnetHalfInterval,
  sekineHalfInterval,
} from '../../../src/core/procedures/approximations';
import { PAPER_CONDITIONS } from '../../../src/core/procedures/paper';
import { paperTables, profileCurves, rhoSweep, stepOverSweep } from '../../../src/core/procedures/teaching';
import { exactForward, exactIntervalMm } from '../../../src/core/surfaces/solve';

const tool = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 };

/** Linear interpolation of a (y, z) polyline at y, or NaN outside it. */
function zAt(pts: Float64Array, y: number): number {
  for (let i = 0; i + 2 < pts.length; i += 2) {
    const y0 = pts[i] as number;
    const y1 = pts[i + 2] as number;
    if (Math.min(y0, y1) <= y && y <= Math.max(y0, y1) && y1 !== y0)
      return (pts[i + 1] as number) + (((pts[i + 3] as number) - (pts[i + 1] as number)) * (y - y0)) / (y1 - y0);
  }
  return Number.NaN;
}

describe('teaching data', () => {
  it('the exact profile curve passes through (L/2, h) and ends at (R, Rb sin rho + Rcr)', () => {
    const c = profileCurves(tool, 2000);
    const half = exactIntervalMm(forwardInput(tool, 'one-way', 0.05)) / 2;
    const e = c.exact;
    expect(e[e.length - 2]).toBeCloseTo(3, 12);
    expect(e[e.length - 1]).toBeCloseTo(2 * Math.sin((5 * Math.PI) / 180) + 1, 12);
    expect(Math.abs(zAt(e, half) - 0.05)).toBeLessThan(1e-4);
  });

  it('with tilt the full profile passes through both flanks at (wR, h) and (-wL, h), and starts at the contact', () => {
    const tilted = { ...tool, tiltAngleDeg: 12 };
    const c = profileCurves(tilted, 4000);
    const f = exactForward(forwardInput(tilted, 'one-way', 0.05));
    expect(f.halfWidthRightMm).not.toBeCloseTo(f.halfWidthLeftMm, 3);
    expect(Math.abs(zAt(c.profile, f.halfWidthRightMm) - 0.05)).toBeLessThan(1e-4);
    expect(Math.abs(zAt(c.profile, -f.halfWidthLeftMm) - 0.05)).toBeLessThan(1e-4);
    expect(Math.abs(zAt(c.profile, 0))).toBeLessThan(1e-9);
  });

  it("the approximations' curves reach height h at their own L/2 (Eqs. 8 and 11)", () => {
    const c = profileCurves(tool, 4000);
    const input = forwardInput(tool, 'one-way', 0.05);
    for (const [curve, r] of [
      [c.sekine, sekineHalfInterval(input)],
      [c.redonnet, redonnetHalfInterval(input)],
      [c.bedi, bediHalfInterval(input)],
    ] as const) {
      if (!curve || !r.ok) throw new Error('applicable at rho = 5');
      expect(Math.abs(zAt(curve, r.halfIntervalMm) - 0.05)).toBeLessThan(1e-5);
    }
    expect(profileCurves({ ...tool, leadAngleDeg: 0 }).sekine).toBeNull();
  });

  it('the rho sweep includes the current angle and matches the exact solver there; no value where h is beyond the corner', () => {
    const s = rhoSweep(3, 1, 0.05, 0.5, 89, 40, 7.3);
    // Geometric spacing: the ends exact, a constant ratio between neighbours (7.3 aside).
    const plain = rhoSweep(3, 1, 0.05, 0.5, 89, 40).rhoDeg;
    expect(plain).toHaveLength(41);
    expect(plain[0]).toBe(0.5);
    expect(plain[40]).toBe(89);
    for (let j = 1; j < plain.length; j++)
      expect((plain[j] as number) / (plain[j - 1] as number)).toBeCloseTo((89 / 0.5) ** (1 / 40), 12);
    expect(s.rhoDeg).toHaveLength(42);
    const i = s.rhoDeg.indexOf(7.3);
    expect(i).toBeGreaterThan(0);
    expect(s.exact[i]).toBe(exactIntervalMm(forwardInput({ ...tool, leadAngleDeg: 7.3 }, 'one-way', 0.05)) / 2);
    // h = 1.05 is beyond the corner height Rcr + Rb sin(rho) for small rho.
    const high = rhoSweep(3, 1, 1.05, 0.5, 89, 40);
    expect(high.exact[0]).toBeNull();
    expect(high.exact[high.exact.length - 1]).not.toBeNull();
  });
});

describe("the paper's tables recomputed (every row, every procedure)", () => {
  const rows = paperTables();
  // A value printed with 3 decimals is reproduced when it rounds to the printed digits.
  const printed = (v: number, p: number) => Math.abs(v - p) <= 0.0005 + 1e-12;

  it('has one row per printed condition, carrying the printed values unchanged', () => {
    expect(rows).toHaveLength(PAPER_CONDITIONS.length);
    rows.forEach((r, k) => {
      expect(r.printedHalf).toEqual(PAPER_CONDITIONS[k]?.printedHalf);
      expect(r.printedHeight).toEqual(PAPER_CONDITIONS[k]?.printedHeight);
    });
  });

  for (const [k, c] of PAPER_CONDITIONS.entries()) {
    it(`Table ${c.table}, R=${c.R} Rcr=${c.Rcr} rho=${c.rho} h=${c.h}: each approximation's L/2 rounds to the printed one, the 3D one is the exact value`, () => {
      const r = rows[k];
      if (!r) throw new Error('missing row');
      expect(printed(r.computedHalf.sekine, c.printedHalf.sekine)).toBe(true);
      expect(printed(r.computedHalf.redonnet, c.printedHalf.redonnet)).toBe(true);
      expect(printed(r.computedHalf.bedi, c.printedHalf.bedi)).toBe(true);
      // The 3D column is the exact solver's (notes' exact column, 12 decimals), not the printed one.
      expect(Math.abs(r.computedHalf.threeD - c.notesExactHalf)).toBeLessThan(1e-9);
      // Tables 4-5: the heights at the printed L/2 are within one unit of the last printed digit.
      for (const key of ['sekine', 'redonnet', 'bedi'] as const)
        expect(Math.abs(r.computedHeight[key] - c.printedHeight[key]), key).toBeLessThan(0.001);
    });
  }
});

describe('step-over sweeps along lead and tilt', () => {
  it('tilt sweep: symmetric in the tilt for one-way passes, the exact value at the current tilt, null past the limit', () => {
    const s = stepOverSweep(tool, 'one-way', 0.05, 'tilt', -60, 60, 24, 7);
    const i = s.angleDeg.indexOf(7);
    expect(s.values.exact[i]).toBe(exactIntervalMm(forwardInput({ ...tool, tiltAngleDeg: 7 }, 'one-way', 0.05)));
    const at = (deg: number) => s.values.exact[s.angleDeg.indexOf(deg)] as number;
    expect(Math.abs(at(-30) - at(30))).toBeLessThan(1e-12);
    // Tilt shrinks the one-way step-over of this tool (issue figures: 2.887 at 0, 1.879 at 5 degrees).
    expect(at(0)).toBeGreaterThan(at(30));
    // The paper's lead-only models do not see the tilt: constant along the sweep.
    const sek = s.values.sekine.filter((v): v is number => v !== null);
    expect(Math.max(...sek) - Math.min(...sek)).toBeLessThan(1e-12);
    // h = 1.5 is above every posture's limit of this tool at a 5 degree lead: nothing there.
    expect(stepOverSweep(tool, 'one-way', 1.5, 'tilt', -60, 60, 8).values.exact.every((v) => v === null)).toBe(true);
  });

  it('lead sweep: geometric spacing and the exact step-over at each sample', () => {
    const s = stepOverSweep(tool, 'zigzag', 0.05, 'lead', 0.5, 89, 10);
    expect(s.angleDeg[0]).toBe(0.5);
    expect(s.angleDeg[10]).toBe(89);
    expect((s.angleDeg[1] as number) / (s.angleDeg[0] as number)).toBeCloseTo((89 / 0.5) ** 0.1, 12);
    const k = 4;
    expect(s.values.exact[k]).toBe(
      exactIntervalMm(forwardInput({ ...tool, leadAngleDeg: s.angleDeg[k] as number }, 'zigzag', 0.05)),
    );
  });
});
