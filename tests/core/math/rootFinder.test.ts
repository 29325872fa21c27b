import { describe, expect, it } from 'vitest';
import {
  bracketedRoot,
  goldenMinimum,
  maximise,
  type NewtonObjective,
  newSearchEnd,
  newtonRoot,
  type Objective,
} from '../../../src/core/math/rootFinder';

/** An objective that counts its evaluations and records where it was evaluated. */
function counted(fn: (x: number) => number): Objective & { calls: number; xs: number[] } {
  return {
    calls: 0,
    xs: [],
    value(x: number) {
      this.calls++;
      this.xs.push(x);
      return fn(x);
    },
  };
}

/** A Newton objective from f and f'. */
function withSlope(
  fn: (x: number) => number,
  d: (x: number) => number,
): NewtonObjective & { calls: number; slope: number } {
  return {
    calls: 0,
    slope: 0,
    value(x: number) {
      this.calls++;
      this.slope = d(x);
      return fn(x);
    },
  };
}

describe('bracketedRoot', () => {
  it('finds known roots to the last bits (sqrt 2, cos x = x, a root of multiplicity 3)', () => {
    const cases: Array<[(x: number) => number, number, number, number]> = [
      [(x) => x * x - 2, 0, 2, Math.SQRT2],
      [(x) => Math.cos(x) - x, 0, 1, 0.7390851332151607],
      [(x) => (x - 0.3) ** 3, -1, 2, 0.3],
      [(x) => Math.exp(x) - 1e6, 0, 100, Math.log(1e6)],
    ];
    for (const [fn, lo, hi, root] of cases) {
      const f = counted(fn);
      const x = bracketedRoot(f, lo, hi, fn(lo), fn(hi));
      expect(Math.abs(x - root)).toBeLessThanOrEqual(1e-15 * Math.max(1, Math.abs(root)));
      expect(f.calls).toBeLessThan(200);
    }
  });

  it('works on a falling function and a reversed bracket', () => {
    const fn = (x: number) => 2 - x * x;
    expect(bracketedRoot(counted(fn), 0, 2, fn(0), fn(2))).toBeCloseTo(Math.SQRT2, 15);
    expect(bracketedRoot(counted(fn), 2, 0, fn(2), fn(0))).toBeCloseTo(Math.SQRT2, 15);
  });

  it('returns a bracket end where f is 0, without evaluating', () => {
    const f = counted((x) => x - 1);
    expect(bracketedRoot(f, 1, 3, 0, 2)).toBe(1);
    expect(bracketedRoot(f, -1, 1, -2, 0)).toBe(1);
    expect(f.calls).toBe(0);
  });

  it('evaluates only strictly inside the bracket and reports the final bracket around the root', () => {
    const f = counted((x) => Math.atan(x - 0.7));
    const end = newSearchEnd();
    const x = bracketedRoot(f, 0, 1, f.value(0), f.value(1), 1e-12, 200, end);
    f.xs.splice(0, 2);
    for (const t of f.xs) expect(t > 0 && t < 1).toBe(true);
    expect(end.lo).toBeLessThanOrEqual(0.7);
    expect(end.hi).toBeGreaterThanOrEqual(0.7);
    expect(end.x).toBe(x);
  });

  it('honours the tolerance: a coarse one stops early with the root inside the final bracket', () => {
    const fn = (x: number) => x ** 5 - 0.2;
    const fine = counted(fn);
    const coarse = counted(fn);
    const end = newSearchEnd();
    bracketedRoot(fine, 0, 1, fn(0), fn(1));
    bracketedRoot(coarse, 0, 1, fn(0), fn(1), 1e-3, 200, end);
    expect(coarse.calls).toBeLessThan(fine.calls);
    expect(end.hi - end.lo).toBeLessThanOrEqual(1e-3);
    expect(end.lo).toBeLessThanOrEqual(0.2 ** 0.2);
    expect(end.hi).toBeGreaterThanOrEqual(0.2 ** 0.2);
  });

  it('stops at the iteration cap', () => {
    const fn = (x: number) => x ** 20 - 1e-3;
    const f = counted(fn);
    bracketedRoot(f, 0, 1, fn(0), fn(1), 0, 7);
    expect(f.calls).toBe(7);
  });

  it('keeps converging on a function flat at one end (regula falsi alone would stall there)', () => {
    // x^20 - 1e-3 on [0, 1]: the secant from the flat end creeps; the forced bisections bound the count.
    const fn = (x: number) => x ** 20 - 1e-3;
    const f = counted(fn);
    const x = bracketedRoot(f, 0, 1, fn(0), fn(1));
    expect(x).toBeCloseTo(1e-3 ** (1 / 20), 14);
    expect(f.calls).toBeLessThan(80);
  });

  it('forces a bisection every fourth step: a jump of 1e10 is bracketed to the last bits, a steep exponential fast', () => {
    // Regula falsi creeps from the low side of a jump (steps of 1e-10 of the bracket); the forced
    // bisections find it (without them: 200 evaluations and 5e-5 off).
    const jump = (x: number) => (x < 0.3 ? -1 : 1e10);
    const f = counted(jump);
    expect(Math.abs(bracketedRoot(f, 0, 1, -1, 1e10) - 0.3)).toBeLessThan(1e-15);
    expect(f.calls).toBeLessThan(150);
    const steep = (x: number) => Math.exp(50 * x) - 2;
    const g = counted(steep);
    expect(bracketedRoot(g, 0, 1, steep(0), steep(1))).toBeCloseTo(Math.log(2) / 50, 15);
    expect(g.calls).toBeLessThan(50);
  });

  it('takes an infinite end and a NaN inside without leaving the bracket', () => {
    const fn = (x: number) => (x > 0.9 ? Number.POSITIVE_INFINITY : x - 0.5);
    const f = counted(fn);
    expect(bracketedRoot(f, 0, 1, -0.5, Number.POSITIVE_INFINITY)).toBeCloseTo(0.5, 15);
    const g = counted((x) => (x > 0.8 ? Number.NaN : x - 0.25));
    const r = bracketedRoot(g, 0, 1, -0.25, 1);
    expect(r).toBeCloseTo(0.25, 12);
  });

  it('without a sign change returns the end with the smaller |f|', () => {
    const f = counted((x) => x * x + 1);
    expect(bracketedRoot(f, -3, 2, 10, 5)).toBe(2);
    expect(f.calls).toBe(0);
  });
});

describe('newtonRoot', () => {
  it('converges quadratically on a smooth root from a start inside the bracket', () => {
    const f = withSlope(
      (x) => x * x - 2,
      (x) => 2 * x,
    );
    const x = newtonRoot(f, 0, 2, 1.5, true, 1e-15);
    expect(x).toBeCloseTo(Math.SQRT2, 15);
    expect(f.calls).toBeLessThan(8);
  });

  it('falls back to bisection where the slope has the wrong sign or a step leaves the bracket', () => {
    // The derivative is given with the wrong sign: every step is a bisection, still converging.
    const f = withSlope(
      (x) => x - 0.3,
      () => -1,
    );
    const x = newtonRoot(f, 0, 1, 0.9, true, 1e-15);
    expect(x).toBeCloseTo(0.3, 14);
    expect(f.calls).toBeGreaterThan(40);
    // A falling function: g > 0 below the root.
    const g = withSlope(
      (x) => Math.cos(x) - x,
      (x) => -Math.sin(x) - 1,
    );
    expect(newtonRoot(g, 0, 1, 0.99, false, 1e-15)).toBeCloseTo(0.7390851332151607, 15);
  });

  it('brackets by doubling when hi is infinite', () => {
    const f = withSlope(
      (x) => Math.atan(x - 1000),
      (x) => 1 / (1 + (x - 1000) ** 2),
    );
    expect(newtonRoot(f, 0, Number.POSITIVE_INFINITY, 1, true, 1e-15)).toBeCloseTo(1000, 10);
  });

  it('stops at the iteration cap and at the step tolerance', () => {
    const f = withSlope(
      (x) => x - 0.3,
      () => -1,
    );
    newtonRoot(f, 0, 1, 0.9, true, 1e-15, 5);
    expect(f.calls).toBe(5);
    const loose = withSlope(
      (x) => x * x - 2,
      (x) => 2 * x,
    );
    const x = newtonRoot(loose, 0, 2, 1.5, true, 1e-2);
    expect(Math.abs(x - Math.SQRT2)).toBeLessThan(1e-3);
    expect(loose.calls).toBeLessThanOrEqual(3);
  });
});

describe('maximise', () => {
  it('finds a smooth maximum and its argument', () => {
    const end = newSearchEnd();
    const v = maximise(
      counted((x) => Math.sin(x)),
      0,
      3,
      8,
      1e-12,
      end,
    );
    expect(v).toBe(Math.sin(end.x));
    expect(end.x).toBeCloseTo(Math.PI / 2, 6);
    expect(v).toBeCloseTo(1, 15);
  });

  it('finds a kinked maximum (|x - a| peak) to the tolerance', () => {
    const a = 0.123456789;
    const end = newSearchEnd();
    const v = maximise(
      counted((x) => -Math.abs(x - a)),
      0,
      1,
      4,
      1e-13,
      end,
    );
    expect(Math.abs(end.x - a)).toBeLessThan(1e-12);
    expect(v).toBeGreaterThan(-1e-12);
  });

  it('takes the bracket ends and a flat function', () => {
    const end = newSearchEnd();
    expect(
      maximise(
        counted((x) => x),
        2,
        5,
        4,
        1e-12,
        end,
      ),
    ).toBe(5);
    expect(end.x).toBe(5);
    expect(
      maximise(
        counted((x) => -x),
        2,
        5,
        4,
        1e-12,
        end,
      ),
    ).toBe(-2);
    expect(end.x).toBe(2);
    expect(
      maximise(
        counted(() => 7),
        2,
        5,
        4,
        1e-12,
        end,
      ),
    ).toBe(7);
    expect(end.x).toBeGreaterThanOrEqual(2);
    expect(end.x).toBeLessThanOrEqual(5);
  });

  it('uses the point it must visit when the scan steps over a narrow peak', () => {
    const peak = (x: number) => (Math.abs(x - 0.51) < 1e-3 ? 1 - Math.abs(x - 0.51) : 0);
    expect(maximise(counted(peak), 0, 1, 4, 1e-12)).toBe(0);
    expect(maximise(counted(peak), 0, 1, 4, 1e-12, undefined, 0.5105)).toBeCloseTo(1, 11);
  });

  it('caps its evaluations', () => {
    const f = counted((x) => -(Math.abs(x - 1 / 3) ** 0.5));
    maximise(f, 0, 1, 16, 0);
    expect(f.calls).toBeLessThanOrEqual(16 + 1 + 200);
  });
});

describe('goldenMinimum', () => {
  it('finds the minimum of a unimodal function and honours its tolerance', () => {
    const f = counted((x) => (x - 0.4) ** 2);
    expect(goldenMinimum(f, 0, 1)).toBeCloseTo(0.4, 7);
    const g = counted((x) => Math.abs(x - 0.4));
    expect(goldenMinimum(g, 0, 1)).toBeCloseTo(0.4, 14);
    const coarse = counted((x) => Math.abs(x - 0.4));
    expect(Math.abs(goldenMinimum(coarse, 0, 1, 1e-3) - 0.4)).toBeLessThan(1e-3);
    expect(coarse.calls).toBeLessThan(g.calls);
  });
});
