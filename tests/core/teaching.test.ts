import { describe, expect, it } from 'vitest';
import { bediHalfInterval, redonnetHalfInterval, sekineHalfInterval } from '../../src/core/approximations';
import { exactHalfIntervalMm } from '../../src/core/exact';
import { PAPER_CONDITIONS } from '../../src/core/paper';
import { paperTables, profileCurves, rhoSweep } from '../../src/core/teaching';

const tool = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5 };

describe('teaching data', () => {
  it('the exact profile curve passes through (L/2, h) and ends at (R, Rb sin rho + Rcr)', () => {
    const c = profileCurves(tool, 2000);
    const half = exactHalfIntervalMm({ ...tool, scallopHeightMm: 0.05 });
    const e = c.exact;
    expect(e[e.length - 2]).toBeCloseTo(3, 12);
    expect(e[e.length - 1]).toBeCloseTo(2 * Math.sin((5 * Math.PI) / 180) + 1, 12);
    for (let i = 0; i + 2 < e.length; i += 2) {
      const y0 = e[i] as number;
      const y1 = e[i + 2] as number;
      if (y0 <= half && half <= y1) {
        const z = (e[i + 1] as number) + (((e[i + 3] as number) - (e[i + 1] as number)) * (half - y0)) / (y1 - y0);
        expect(Math.abs(z - 0.05)).toBeLessThan(1e-4);
      }
    }
  });

  it("the approximations' curves reach height h at their own L/2 (Eqs. 8 and 11)", () => {
    const c = profileCurves(tool, 4000);
    const input = { ...tool, scallopHeightMm: 0.05 };
    const at = (pts: Float64Array, y: number) => {
      for (let i = 0; i + 2 < pts.length; i += 2) {
        const y0 = pts[i] as number;
        const y1 = pts[i + 2] as number;
        if (y0 <= y && y <= y1)
          return (pts[i + 1] as number) + (((pts[i + 3] as number) - (pts[i + 1] as number)) * (y - y0)) / (y1 - y0);
      }
      return Number.NaN;
    };
    for (const [curve, r] of [
      [c.sekine, sekineHalfInterval(input)],
      [c.redonnet, redonnetHalfInterval(input)],
      [c.bedi, bediHalfInterval(input)],
    ] as const) {
      if (!curve || !r.ok) throw new Error('applicable at rho = 5');
      expect(Math.abs(at(curve, r.halfIntervalMm) - 0.05)).toBeLessThan(1e-5);
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
    expect(s.exact[i]).toBe(exactHalfIntervalMm({ ...tool, leadAngleDeg: 7.3, scallopHeightMm: 0.05 }));
    // h = 1.05 is beyond the corner height Rcr + Rb sin(rho) for small rho.
    const high = rhoSweep(3, 1, 1.05, 0.5, 89, 40);
    expect(high.exact[0]).toBeNull();
    expect(high.exact[high.exact.length - 1]).not.toBeNull();
  });

  it('the recomputed tables carry the printed values and the solver values side by side', () => {
    const rows = paperTables();
    expect(rows).toHaveLength(PAPER_CONDITIONS.length);
    const first = rows[0];
    // biome-ignore lint/suspicious/noApproximativeNumericConstant: 1.442 is the paper's printed value.
    expect(first?.printedHalf.threeD).toBe(1.442);
    expect(first?.computedHalf.threeD).toBe(exactHalfIntervalMm({ ...tool, scallopHeightMm: 0.05 }));
  });
});
