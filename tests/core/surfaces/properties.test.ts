import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import {
  compareForward,
  exactForward,
  exactInverse,
  type ForwardInput,
  forwardInput,
  inverseInput,
  maxIntervalMm,
  type PassPattern,
  scallopHeightLimits,
  solveForwardRaw,
  solveInverseRaw,
  type ToolInput,
} from '../../../src/core/index';
import { everyNumberFinite } from '../../support/finite';

const SEED = 20261122;

/**
 * A valid tool and posture, stratified over the whole domain: R log-uniform from 0.001 to 1000 mm;
 * Rcr 0, tiny (1e-9 R), small, any, or R; rho 0, tiny, any, or near 90; tilt 0, tiny, any, or
 * near +-90. Every generated tool is valid, so no case is rejected.
 */
const toolArb: fc.Arbitrary<ToolInput> = fc
  .record({
    logR: fc.double({ min: -3, max: 3, noNaN: true }),
    rcrKind: fc.constantFrom('zero', 'tiny', 'small', 'any', 'ball'),
    rcrFrac: fc.double({ min: 0, max: 1, noNaN: true }),
    rhoKind: fc.constantFrom('zero', 'tiny', 'any', 'steep'),
    rhoFrac: fc.double({ min: 0, max: 1, noNaN: true }),
    tiltKind: fc.constantFrom('zero', 'tiny', 'any', 'steep'),
    tiltFrac: fc.double({ min: -1, max: 1, noNaN: true }),
  })
  .map(({ logR, rcrKind, rcrFrac, rhoKind, rhoFrac, tiltKind, tiltFrac }) => {
    const R = 10 ** logR;
    const Rcr = { zero: 0, tiny: 1e-9 * R, small: 0.05 * R * rcrFrac, any: R * rcrFrac, ball: R }[rcrKind];
    const rho = { zero: 0, tiny: 1e-6 * rhoFrac, any: 89.99 * rhoFrac, steep: 89 + 0.99 * rhoFrac }[rhoKind];
    const tilt = { zero: 0, tiny: 1e-6 * tiltFrac, any: 80 * tiltFrac, steep: 89.5 * Math.sign(tiltFrac || 1) }[
      tiltKind
    ];
    return { toolRadiusMm: R, cornerRadiusMm: Math.min(R, Rcr), leadAngleDeg: rho, tiltAngleDeg: tilt };
  });

/**
 * A valid forward case: h log-uniform from 1e-12 to 0.999 of the tool's limit (at least 1 nm).
 * Tools that cannot leave a scallop of 10 nm (a tilted flat end cuts a step; a tool tilted
 * almost flat has a tiny shank limit) are redrawn by `filter`, which regenerates rather than
 * skips, so every run asserts; their rejection is tested below.
 */
const caseArb = fc
  .record({
    tool: toolArb.filter((t) => scallopHeightLimits(t).limitMm > 1e-8),
    pattern: fc.constantFrom<PassPattern>('one-way', 'zigzag'),
    logFrac: fc.double({ min: -12, max: Math.log10(0.999), noNaN: true }),
  })
  .map(({ tool, pattern, logFrac }) => {
    const limit = scallopHeightLimits(tool).limitMm;
    return { tool, pattern, limit, h: Math.max(1e-9, limit * 10 ** logFrac) };
  });

/** Counts the cases a property really asserted, so a mostly-rejected generator shows up. */
function counted<T>(arb: fc.Arbitrary<T>, check: (c: T) => boolean, runs: number): number {
  let asserted = 0;
  fc.assert(
    fc.property(arb, (c) => {
      if (check(c)) asserted++;
    }),
    { seed: SEED, numRuns: runs },
  );
  return asserted;
}

const usable = (c: { limit: number; h: number }) => c.h < c.limit;

describe(`properties of the exact solver (fast-check seed ${SEED}, valid inputs only)`, () => {
  it('tools that cannot leave a 1 nm scallop are rejected with a message naming the limit, never NaN', () => {
    const n = counted(
      toolArb,
      (t) => {
        const limit = scallopHeightLimits(t).limitMm;
        if (limit > 1e-9) return false;
        const v = solveForwardRaw({
          R: t.toolRadiusMm,
          Rcr: t.cornerRadiusMm,
          rho: t.leadAngleDeg,
          tilt: t.tiltAngleDeg,
          h: 1e-9,
        });
        // The one exception: a flat end lying flat leaves no scallop at all, a valid answer.
        if (v.ok) expect(v.value.exact.noScallop).toBe(true);
        else expect(v.errors[0]?.message).toMatch(/must be below|wall|shank/);
        return true;
      },
      2000,
    );
    // The strata above put a few hundred such tools in 2000 draws.
    expect(n).toBeGreaterThan(100);
  });

  it('L grows with h and stays below the widest step-over that leaves a scallop', () => {
    const n = counted(
      fc.tuple(caseArb, fc.double({ min: 1.001, max: 3, noNaN: true })),
      ([c, grow]) => {
        const h2 = Math.min(c.h * grow, c.limit * (1 - 1e-9));
        if (!usable(c) || !(h2 > c.h)) return false;
        const l1 = exactForward(forwardInput(c.tool, c.pattern, c.h)).intervalMm;
        const l2 = exactForward(forwardInput(c.tool, c.pattern, h2)).intervalMm;
        expect(l2).toBeGreaterThanOrEqual(l1 * (1 - 1e-14));
        expect(l2).toBeLessThanOrEqual(maxIntervalMm(c.tool, c.pattern) * (1 + 1e-12));
        return true;
      },
      600,
    );
    expect(n).toBeGreaterThan(540);
  });

  it('the inverse of the forward solution returns h within 1e-9 mm (both patterns)', () => {
    const n = counted(
      caseArb,
      (c) => {
        if (!usable(c)) return false;
        const f = exactForward(forwardInput(c.tool, c.pattern, c.h));
        if (f.noScallop || !(f.intervalMm < maxIntervalMm(c.tool, c.pattern))) return false;
        const back = exactInverse(inverseInput(c.tool, c.pattern, f.intervalMm));
        expect(Math.abs(back.cuspHeightMm - c.h), JSON.stringify(c)).toBeLessThan(1e-9);
        return true;
      },
      800,
    );
    expect(n).toBeGreaterThan(700);
  });

  it('mirroring the tilt swaps the flanks and negates the contact offset', () => {
    const n = counted(
      caseArb,
      (c) => {
        if (!usable(c)) return false;
        const a = exactForward(forwardInput(c.tool, c.pattern, c.h));
        const mirrored = { ...c.tool, tiltAngleDeg: -c.tool.tiltAngleDeg };
        const b = exactForward(forwardInput(mirrored, c.pattern, c.h));
        const tol = 1e-12 * c.tool.toolRadiusMm + 1e-15;
        expect(Math.abs(a.halfWidthRightMm - b.halfWidthLeftMm)).toBeLessThan(tol);
        expect(Math.abs(a.halfWidthLeftMm - b.halfWidthRightMm)).toBeLessThan(tol);
        expect(Math.abs(a.contactOffsetMm + b.contactOffsetMm)).toBeLessThan(tol);
        return true;
      },
      400,
    );
    expect(n).toBeGreaterThan(360);
  });

  it('zigzag never steps over more than one-way, and its other cusp is never above h', () => {
    const n = counted(
      caseArb,
      (c) => {
        if (!usable(c)) return false;
        const one = exactForward(forwardInput(c.tool, 'one-way', c.h));
        const zig = exactForward(forwardInput(c.tool, 'zigzag', c.h));
        expect(zig.intervalMm).toBeLessThanOrEqual(one.intervalMm * (1 + 1e-15));
        expect(zig.otherCuspHeightMm ?? Number.NaN).toBeLessThanOrEqual(c.h * (1 + 1e-12));
        return true;
      },
      400,
    );
    expect(n).toBeGreaterThan(360);
  });

  it('every number of a comparison is finite (checked number by number, not through JSON)', () => {
    const n = counted(
      caseArb,
      (c) => {
        if (!usable(c)) return false;
        const r = compareForward(forwardInput(c.tool, c.pattern, c.h) as ForwardInput);
        expect(everyNumberFinite(r), JSON.stringify(c)).toBe(true);
        return true;
      },
      600,
    );
    expect(n).toBeGreaterThan(540);
  });

  it('arbitrary garbage input returns a typed error or finite numbers: never throws, never NaN', () => {
    const garbage = fc.oneof(
      fc.double(),
      fc.integer(),
      fc.string(),
      fc.constantFrom('', ' ', 'NaN', 'Infinity', '-0', '1e309', '1e-400', '0x10', '3,5', null, undefined),
      fc.object(),
      fc.boolean(),
    );
    let valid = 0;
    fc.assert(
      fc.property(garbage, garbage, garbage, garbage, garbage, garbage, (R, Rcr, rho, tilt, pattern, h) => {
        const fwd = solveForwardRaw({ R, Rcr, rho, tilt, pattern, h });
        const inv = solveInverseRaw({ R, Rcr, rho, tilt, pattern, interval: h });
        for (const r of [fwd, inv]) {
          if (r.ok) {
            valid++;
            expect(everyNumberFinite(r.value)).toBe(true);
          } else for (const e of r.errors) expect(e.message.length).toBeGreaterThan(10);
        }
      }),
      { seed: SEED, numRuns: 2000 },
    );
    // Garbage is meant to be rejected; the point is that nothing throws or leaks NaN.
    expect(valid).toBeLessThan(4000);
  });
});
