import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { exactHalfIntervalMm, exactScallopHeightMm } from '../../src/core/exact';
import { solveForwardRaw, solveInverseRaw } from '../../src/core/index';

const DEG = Math.PI / 180;
const SEED = 20261122;

/** A valid tool and a fraction of its corner-profile height. */
const caseArb = fc
  .record({
    R: fc.double({ min: 0.1, max: 50, noNaN: true }),
    rcrFrac: fc.double({ min: 0, max: 1, noNaN: true }),
    rho: fc.double({ min: 0, max: 89.99, noNaN: true }),
    hFrac: fc.double({ min: 1e-6, max: 0.999, noNaN: true }),
  })
  .map(({ R, rcrFrac, rho, hFrac }) => {
    const Rcr = R * rcrFrac;
    const limit = (R - Rcr) * Math.sin(rho * DEG) + Rcr;
    return { toolRadiusMm: R, cornerRadiusMm: Rcr, leadAngleDeg: rho, limit, hFrac };
  })
  .filter((c) => c.limit > 1e-9);

describe(`properties of the exact solver (fast-check seed ${SEED})`, () => {
  it('L/2 increases with h and never exceeds R', () => {
    fc.assert(
      fc.property(caseArb, fc.double({ min: 1.0001, max: 1.5, noNaN: true }), (c, grow) => {
        const h1 = c.limit * c.hFrac;
        const h2 = Math.min(c.limit * 0.9999, h1 * grow);
        fc.pre(h2 > h1);
        const l1 = exactHalfIntervalMm({ ...c, scallopHeightMm: h1 });
        const l2 = exactHalfIntervalMm({ ...c, scallopHeightMm: h2 });
        expect(l2).toBeGreaterThanOrEqual(l1);
        // Strictly greater wherever the change is above round-off (not saturated at R).
        if (h2 - h1 > 1e-9 * c.toolRadiusMm && l1 < c.toolRadiusMm * (1 - 1e-6)) expect(l2).toBeGreaterThan(l1);
        expect(l2).toBeLessThanOrEqual(c.toolRadiusMm);
      }),
      { seed: SEED, numRuns: 400 },
    );
  });

  it('L/2 does not increase with rho (same R, Rcr, h)', () => {
    fc.assert(
      fc.property(caseArb, fc.double({ min: 0, max: 30, noNaN: true }), (c, extra) => {
        const rho2 = Math.min(89.99, c.leadAngleDeg + extra);
        // h must be valid at both angles: the corner height grows with rho.
        const h = c.limit * c.hFrac;
        const l1 = exactHalfIntervalMm({ ...c, scallopHeightMm: h });
        const l2 = exactHalfIntervalMm({ ...c, leadAngleDeg: rho2, scallopHeightMm: h });
        expect(l2).toBeLessThanOrEqual(l1 + 1e-12);
      }),
      { seed: SEED, numRuns: 400 },
    );
  });

  it('the inverse of the forward solution returns h within 1e-9 mm', () => {
    fc.assert(
      fc.property(caseArb, (c) => {
        const h = c.limit * c.hFrac;
        const half = exactHalfIntervalMm({ ...c, scallopHeightMm: h });
        fc.pre(half < c.toolRadiusMm);
        const back = exactScallopHeightMm({ ...c, halfIntervalMm: half });
        expect(Math.abs(back - h)).toBeLessThan(1e-9);
      }),
      { seed: SEED, numRuns: 600 },
    );
  });

  it('arbitrary garbage input returns a typed error or finite numbers: never throws, never NaN', () => {
    const garbage = fc.oneof(
      fc.double(),
      fc.integer(),
      fc.string(),
      fc.constantFrom('', ' ', 'NaN', 'Infinity', '-0', '1e309', '0x10', '3,5', null, undefined),
      fc.object(),
      fc.boolean(),
    );
    const finiteDeep = (v: unknown): boolean =>
      typeof v === 'number'
        ? Number.isFinite(v)
        : typeof v === 'object' && v !== null
          ? Object.values(v).every(finiteDeep)
          : true;
    fc.assert(
      fc.property(garbage, garbage, garbage, garbage, (R, Rcr, rho, h) => {
        const fwd = solveForwardRaw({ R, Rcr, rho, h });
        const inv = solveInverseRaw({ R, Rcr, rho, halfInterval: h });
        for (const r of [fwd, inv]) {
          if (r.ok) expect(finiteDeep(r.value)).toBe(true);
          else for (const e of r.errors) expect(e.message.length).toBeGreaterThan(10);
        }
      }),
      { seed: SEED, numRuns: 2000 },
    );
  });

  it('valid random doubles anywhere in the domain give finite results for all four procedures', () => {
    fc.assert(
      fc.property(
        fc.double({ min: 0.001, max: 1000, noNaN: true }),
        fc.double({ min: 0, max: 1, noNaN: true }),
        fc.double({ min: 0, max: 89.999999, noNaN: true }),
        fc.double({ min: Number.MIN_VALUE, max: 1, noNaN: true, maxExcluded: true }),
        (R, f, rho, hf) => {
          const Rcr = R * f;
          const limit = (R - Rcr) * Math.sin(rho * DEG) + Rcr;
          const r = solveForwardRaw({ R, Rcr, rho, h: limit * hf });
          if (r.ok) {
            const json = JSON.stringify(r.value);
            expect(json).not.toMatch(/null|NaN/);
            expect(r.value.exact.halfIntervalMm).toBeGreaterThan(0);
            expect(r.value.exact.halfIntervalMm).toBeLessThanOrEqual(R);
          }
        },
      ),
      { seed: SEED, numRuns: 2000 },
    );
  });
});
