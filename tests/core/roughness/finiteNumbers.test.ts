/**
 * Roughness and the simulation at tiny step-overs and targets: always finite numbers (issue 26,
 * point 6). A doubly curved point's flank reach is -Infinity below the rounding of its radial
 * heights (about 1e-16 mm), where the roughness integral sampled it near the contact (Ra, Rq NaN);
 * a flat end's simulation mesh put its rim at a section angle of (q - Rb) / 0 (every height NaN).
 */
import { describe, expect, it } from 'vitest';
import type { DoublyCurvedSurface } from '../../../src/core/domain/surface';
import type { PassPattern, ToolInput } from '../../../src/core/domain/tool';
import { forwardInput, inverseInput, MIN_LENGTH_MM } from '../../../src/core/input/validate';
import {
  doublyCurvedHeightForRaMm,
  doublyCurvedMaxRaMm,
  doublyCurvedRoughnessAtInterval,
} from '../../../src/core/roughness/doublyCurved';
import {
  exactRoughness,
  exactRoughnessAtInterval,
  maxRaMm,
  scallopHeightForRaMm,
} from '../../../src/core/roughness/roughness';
import { SimulationTooLargeError, simulatePasses } from '../../../src/core/simulation/simulation';
import { curvedForward, curvedInverse, curvedLimits, curvedPoint } from '../../../src/core/surfaces/doublyCurvedPoint';
import { surfaceModel } from '../../../src/core/surfaces/registry';
import { exactForward, exactInverse } from '../../../src/core/surfaces/solve';
import { maxIntervalMm, scallopHeightLimits } from '../../../src/core/surfaces/validate';
import { seededRandom } from '../../support/bruteForce';
import { everyNumberFinite } from '../../support/finite';

/** A parabolic scallop's Ra / Rz and Rq / Rz: 4 / (9 sqrt 3) and 2 / (3 sqrt 5). */
const PARABOLA_RA = 4 / (9 * Math.sqrt(3));
const PARABOLA_RQ = 2 / (3 * Math.sqrt(5));

const logUniform = (rand: () => number, lo: number, hi: number) => lo * (hi / lo) ** rand();

describe('roughness and the simulation stay finite at tiny step-overs and targets (issue 26, point 6)', () => {
  it('a doubly curved point at a step-over of 4.2e-5 mm (h 2.1e-9 mm): Ra and Rq those of a parabola', () => {
    const tool: ToolInput = {
      toolRadiusMm: 1.116,
      cornerRadiusMm: 0.6216,
      leadAngleDeg: 41.627362190769055,
      tiltAngleDeg: 0,
    };
    const point = curvedPoint(tool, { feedRadiusMm: 3413.9965998497723, crossRadiusMm: 0.1143 }, 'one-way');
    const e = curvedInverse(point, 0.000042261027907111694);
    const r = doublyCurvedRoughnessAtInterval(point, e);
    expect(everyNumberFinite(r)).toBe(true);
    // A scallop a millionth of every radius is a parabola to a relative 1e-6 and better.
    expect(Math.abs(r.raMm / r.rzMm - PARABOLA_RA)).toBeLessThan(1e-6);
    expect(Math.abs(r.rqMm / r.rzMm - PARABOLA_RQ)).toBeLessThan(1e-6);
  });

  it('a flat end leaning 37.7 deg, target Ra 1.64e-8 mm: every simulated height finite, the cusp and Ra within their bounds', () => {
    const tool: ToolInput = {
      toolRadiusMm: 4.231758111389403,
      cornerRadiusMm: 0,
      leadAngleDeg: 2.5549168162280695,
      tiltAngleDeg: 37.69496732666157,
    };
    const h = scallopHeightForRaMm(tool, 'one-way', 1.6396786026998403e-8);
    const input = forwardInput(tool, 'one-way', h);
    const e = exactForward(input);
    const sim = simulatePasses({ tool, pattern: 'one-way', intervalMm: e.intervalMm });
    expect(everyNumberFinite(sim)).toBe(true);
    expect(Math.abs(sim.cuspHeightMm - h)).toBeLessThanOrEqual(sim.resolutionBoundMm);
    expect(Math.abs(sim.roughness.raMm - exactRoughness(input, e).raMm)).toBeLessThanOrEqual(sim.roughnessBoundMm);
  });

  const SEED = 626;
  it(`seed ${SEED}: roughness at tiny step-overs and target Ra on planes, cylinders and doubly curved points: every number finite`, () => {
    const rand = seededRandom(SEED);
    let checked = 0;
    for (let i = 0; i < 60; i++) {
      const R = logUniform(rand, 0.01, 100);
      const Rcr = [0, R, R * rand(), R * logUniform(rand, 1e-9, 1e-3)][i % 4] as number;
      const tool: ToolInput = {
        toolRadiusMm: R,
        cornerRadiusMm: Rcr,
        leadAngleDeg: [0, logUniform(rand, 1e-6, 1), 85 * rand()][Math.floor(i / 4) % 3] as number,
        tiltAngleDeg: [0, 120 * (rand() - 0.5)][Math.floor(i / 12) % 2] as number,
      };
      const pattern: PassPattern = i % 2 === 0 ? 'one-way' : 'zigzag';
      const signed = () => (rand() < 0.5 ? -1 : 1) * R * logUniform(rand, 0.05, 1e4);
      const kind = Math.floor(i / 24) % 3;
      if (kind === 2) {
        // A doubly curved point.
        const radii = { feedRadiusMm: signed(), crossRadiusMm: signed() };
        const surface: DoublyCurvedSurface = { kind: 'doublyCurved', ...radii };
        const model = surfaceModel(surface);
        if (model.fit(tool, surface).gouges || model.leavesNoScallop(tool, surface)) continue;
        const point = curvedPoint(tool, radii, pattern);
        const limit = curvedLimits(point).limitMm;
        if (!(limit > 1e3 * MIN_LENGTH_MM)) continue;
        const widest = curvedForward(point, limit * (1 - 1e-9)).intervalMm;
        const L = widest * logUniform(rand, 1e-8, 1e-3);
        const r = doublyCurvedRoughnessAtInterval(point, curvedInverse(point, L));
        expect(everyNumberFinite(r), JSON.stringify({ tool, radii, pattern, L })).toBe(true);
        const maxRa = doublyCurvedMaxRaMm(point);
        const target = Math.max(MIN_LENGTH_MM, maxRa * logUniform(rand, 1e-9, 1e-3));
        if (target < maxRa) {
          const hRa = doublyCurvedHeightForRaMm(point, target);
          expect(Number.isFinite(hRa) && hRa > 0, JSON.stringify({ tool, radii, pattern, target })).toBe(true);
        }
      } else {
        // The plane, or a cylinder along or across the feed.
        const surface =
          kind === 0
            ? undefined
            : {
                kind: 'cylinder' as const,
                radiusMm: signed(),
                axis: rand() < 0.5 ? ('feed' as const) : ('cross' as const),
              };
        const s = surface ?? { kind: 'plane' as const };
        const model = surfaceModel(s);
        if (model.fit(tool, s).gouges || model.leavesNoScallop(tool, s)) continue;
        if (!(scallopHeightLimits(tool, s).limitMm > 1e3 * MIN_LENGTH_MM)) continue;
        const L = maxIntervalMm(tool, pattern, s) * logUniform(rand, 1e-8, 1e-3);
        const e = exactInverse(inverseInput(tool, pattern, L, s));
        const r = exactRoughnessAtInterval(tool, pattern, e, s);
        expect(everyNumberFinite(r), JSON.stringify({ tool, surface, pattern, L })).toBe(true);
        const maxRa = maxRaMm(tool, pattern, s);
        const target = Math.max(MIN_LENGTH_MM, maxRa * logUniform(rand, 1e-9, 1e-3));
        if (target < maxRa) {
          const hRa = scallopHeightForRaMm(tool, pattern, target, s);
          expect(Number.isFinite(hRa) && hRa > 0, JSON.stringify({ tool, surface, pattern, target })).toBe(true);
        }
      }
      checked++;
    }
    expect(checked).toBeGreaterThanOrEqual(30);
  }, 120_000);

  it(`seed ${SEED}: simulations at tiny step-overs (flat, tiny and round corners, rho 0 and leaning): every number finite or too large, said so`, () => {
    const rand = seededRandom(SEED + 1);
    let simulated = 0;
    for (let i = 0; i < 8; i++) {
      const R = logUniform(rand, 0.2, 2);
      const tool: ToolInput = {
        toolRadiusMm: R,
        cornerRadiusMm: [0, R * logUniform(rand, 1e-6, 1e-2), R * rand(), R][i % 4] as number,
        leadAngleDeg: i < 4 ? 0 : 80 * rand(),
        tiltAngleDeg: i % 2 === 0 ? 0 : 60 * (rand() - 0.5),
      };
      const pattern: PassPattern = i % 3 === 0 ? 'zigzag' : 'one-way';
      if (surfaceModel({ kind: 'plane' }).leavesNoScallop(tool, { kind: 'plane' })) continue;
      if (!(scallopHeightLimits(tool).limitMm > 1e3 * MIN_LENGTH_MM)) continue;
      const L = maxIntervalMm(tool, pattern) * logUniform(rand, 1e-3, 1e-2);
      try {
        const sim = simulatePasses({ tool, pattern, intervalMm: L }, { cellsAcross: 32, cellsAlong: 2 });
        expect(everyNumberFinite(sim), JSON.stringify({ tool, pattern, L })).toBe(true);
        simulated++;
      } catch (err) {
        if (!(err instanceof SimulationTooLargeError)) throw err;
      }
    }
    expect(simulated).toBeGreaterThanOrEqual(4);
  }, 120_000);
});
