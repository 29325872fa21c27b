/**
 * Three-axis answers and errors carry finite numbers only (issue 26): a seeded fuzz over the whole
 * domain and its edges (tools from 0.001 to 1000 mm, flat, bull-nose and ball ends, slopes 0, 1e-9,
 * 45, 89.999, 90 - 1e-9 and 90, raster angles, convex and concave radii from 0.001 mm to 1e6 mm, h
 * and steps from 1e-9 mm up past the tool) through the validation and solvers the command line,
 * the batch and the page use, the slope sweep and the up-slope cusp: no NaN, Infinity, -0 or null
 * (but for the members documented as absent: a raster answer's dz, an error without a limit, a
 * sweep point the slope refuses) and no such word in a message.
 */
import { describe, expect, it } from 'vitest';
import { slopeSweep } from '../../../src/core/threeAxis/slopeSweep';
import { solveThreeAxis } from '../../../src/core/threeAxis/solve';
import { validateThreeAxis } from '../../../src/core/threeAxis/validate';
import { waterlineCuspAbove } from '../../../src/core/threeAxis/waterlineRevolution';
import { seededRandom } from '../../support/bruteForce';

/** Paths of the non-finite, -0 or null values (and of messages naming one) in `v`. */
function faults(v: unknown, path: string, out: string[] = []): string[] {
  if (v === null) out.push(`${path} = null`);
  else if (typeof v === 'number' && (!Number.isFinite(v) || Object.is(v, -0))) out.push(`${path} = ${v}`);
  else if (typeof v === 'string' && /NaN|Infinity|undefined|null/.test(v)) out.push(`${path}: ${v}`);
  else if (Array.isArray(v)) for (const [i, x] of v.entries()) faults(x, `${path}[${i}]`, out);
  else if (typeof v === 'object' && v !== null) for (const [k, x] of Object.entries(v)) faults(x, `${path}.${k}`, out);
  return out;
}

/** An error with its documented absent limit left out. */
const withoutAbsent = (e: { readonly limit: number | null }) => (e.limit === null ? { ...e, limit: 0 } : e);

describe('three-axis outputs are finite numbers or stated reasons', () => {
  it('a concave meridian no rounder than the corner at 90 degrees: the up-slope cusp is the gouging error, not a limit of -0', () => {
    const r = waterlineCuspAbove(
      { toolRadiusMm: 1000, cornerRadiusMm: 1000, slopeDeg: 90, feedRadiusMm: 22260, crossRadiusMm: -248 },
      1e-9,
    );
    expect(!r.ok && r.errors[0]?.code).toBe('gouging');
    expect(faults(r, 'r')).toEqual([]);
  });

  it('fuzz over the domain and its edges (seed 2026, 1500 questions, 75 sweeps)', () => {
    const rand = seededRandom(2026);
    const pick = <T>(xs: readonly T[]): T => xs[Math.floor(rand() * xs.length)] as T;
    const logU = (lo: number, hi: number) => lo * (hi / lo) ** rand();
    const found: string[] = [];
    const codes = new Set<string>();
    for (let i = 0; i < 1500; i++) {
      const R = pick([0.001, 1000, logU(0.001, 1000), logU(0.1, 20)]);
      const Rcr = pick([0, R, R * rand(), R * logU(1e-6, 1)]);
      const passes = pick(['raster', 'waterline'] as const);
      const slope = pick([0, 90, 90 - 1e-9, 1e-9, 89.999, 45, 90 * rand(), 90 * rand()]);
      const radius = () =>
        rand() < 0.25 ? undefined : (rand() < 0.5 ? 1 : -1) * pick([0.001, 1e6, logU(0.001, 1e6), R * logU(0.1, 100)]);
      const raw = {
        R,
        Rcr,
        slope,
        passes,
        ...(passes === 'raster' ? { rasterAngle: pick([0, 90, 90 * rand()]) } : {}),
        ...(passes === 'waterline' && rand() < 0.7 ? { feedRadius: radius(), crossRadius: radius() } : {}),
      };
      const quantity = pick(
        passes === 'raster' ? (['h', 'interval', 'horizontalStep'] as const) : (['h', 'interval', 'stepDown'] as const),
      );
      const mm = pick([1e-9, R * logU(1e-9, 1), R * logU(1e-4, 0.3), 2 * R, R * logU(0.01, 3)]);
      const label = JSON.stringify([raw, quantity, mm]);
      const v = validateThreeAxis(raw, quantity, mm);
      if (!v.ok) {
        found.push(...faults(v.errors.map(withoutAbsent), `${label} validation`));
        continue;
      }
      const r = solveThreeAxis(v.value);
      if (r.ok) {
        codes.add('ok');
        const a = r.value;
        found.push(...faults({ ...a, stepDownMm: a.stepDownMm ?? (passes === 'raster' ? 0 : null) }, label));
      } else {
        codes.add(r.errors[0]?.code ?? '');
        found.push(...faults(r.errors.map(withoutAbsent), label));
      }
      const feed = 'feedRadius' in raw ? (raw.feedRadius ?? null) : null;
      const cross = 'crossRadius' in raw ? (raw.crossRadius ?? null) : null;
      if (i % 20 === 0) {
        const s = slopeSweep({
          toolRadiusMm: R,
          cornerRadiusMm: Rcr,
          hMm: mm,
          passes,
          rasterAngleDeg: ('rasterAngle' in raw ? raw.rasterAngle : undefined) ?? 90,
          feedRadiusMm: feed,
          crossRadiusMm: cross,
          count: 31,
        });
        codes.add(s.ok ? 'sweep' : `sweep ${s.errors[0]?.code}`);
        const points = s.ok
          ? s.value.points.map((p) => ({
              ...p,
              stepMm: p.stepMm ?? 0,
              intervalMm: p.intervalMm ?? 0,
              heightLimitMm: p.heightLimitMm === Number.POSITIVE_INFINITY ? 0 : p.heightLimitMm,
              cuspAtProgrammedStepMm: p.cuspAtProgrammedStepMm ?? 0,
              programmedStepRefusal: p.programmedStepRefusal ?? '',
            }))
          : [];
        found.push(...faults(s.ok ? { ...s.value, points } : s.errors.map(withoutAbsent), `${label} sweep`));
      }
      if (passes === 'waterline' && i % 3 === 0) {
        const u = waterlineCuspAbove(
          { toolRadiusMm: R, cornerRadiusMm: Rcr, slopeDeg: slope, feedRadiusMm: feed, crossRadiusMm: cross },
          mm,
        );
        const g = u.ok ? u.value.geometry : null;
        found.push(
          ...faults(
            u.ok && g
              ? { ...u.value, geometry: { ...g, meridianCentre: g.meridianCentre ?? 0, axisS: g.axisS ?? 0 } }
              : u.ok
                ? u
                : u.errors.map(withoutAbsent),
            `${label} above`,
          ),
        );
      }
    }
    expect(found.slice(0, 10)).toEqual([]);
    // The fuzz reaches the answers and every kind of refusal.
    for (const code of [
      'ok',
      'gouging',
      'shank-cuts',
      'wall-only',
      'vertical-wall',
      'past-surface',
      'sweep',
      'sweep gouging',
    ])
      expect(codes, code).toContain(code);
  });
});
