/**
 * One exact answer at a doubly curved point (issue 27 point 3): every number the worker's doubly
 * curved reply (solve and teach) and the command line's report show for the exact answer (step-over,
 * flank reaches, contact offset, cusps, limits, the widest step-over, the sliders' limits, the
 * roughness, the scallops the comparison rows' step-overs leave) is the registry's doubly curved
 * model's; and where a radius is straight, the cylinder model's (its axis along the feed for Rf
 * straight, Rs = Rc; across it for Rc straight, Rs = Rf) or the plane's, named here and not by the
 * model. The inverse cusp never lies above its flank limit (the point's own solver, which these
 * parts called before, gave 2.57 mm above a 1.46 mm limit: jobsAskRegistries.test.ts).
 */
import { describe, expect, it } from 'vitest';
import type { CylinderSurface, DoublyCurvedSurface, PlaneSurface } from '../../src/core/domain/surface';
import type { PassPattern, ToolInput } from '../../src/core/domain/tool';
import { seededRandom } from '../../src/core/math/seededRandom';
import { exactRoughness, exactRoughnessAtInterval, type Roughness } from '../../src/core/roughness/roughness';
import { doublyCurvedGouges } from '../../src/core/surfaces/doublyCurved';
import { findSurfaceModel } from '../../src/core/surfaces/registry';
import type { ExactForward, ExactInverse, SurfaceModel } from '../../src/core/surfaces/surface';
import { solvePage } from '../../src/worker/jobs/page';
import { teachCurved } from '../../src/worker/jobs/teachPage';
import type { CurvedReply, CurvedRequest } from '../../src/worker/pageProtocol';
import { runMain } from '../cli/helpers';

type AnySurface = DoublyCurvedSurface | CylinderSurface | PlaneSurface;

function registered(kind: string): SurfaceModel<AnySurface> {
  const model = findSurfaceModel(kind);
  if (model === null) throw new Error(`no ${kind} model`);
  return model as unknown as SurfaceModel<AnySurface>;
}

/** The surface that answers: the point's own, or the cylinder or plane a straight radius makes it. */
function answering(rf: number, rc: number): AnySurface {
  const point: DoublyCurvedSurface = { kind: 'doublyCurved', feedRadiusMm: rf, crossRadiusMm: rc };
  if (Number.isFinite(rf) && Number.isFinite(rc)) return point;
  if (Number.isFinite(rc)) return { kind: 'cylinder', radiusMm: rc, axis: 'feed' };
  if (Number.isFinite(rf)) return { kind: 'cylinder', radiusMm: rf, axis: 'cross' };
  return { kind: 'plane' };
}

const I = Number.POSITIVE_INFINITY;

/** The families of points: [name, Rf, Rc] from a draw of the tool radius (mm). */
const FAMILIES: ReadonlyArray<readonly [string, (R: number, r: () => number) => readonly [number, number]]> = [
  ['Rf straight, Rc convex', (R, r) => [r() < 0.5 ? I : -I, R * (0.3 + 20 * r() ** 2)]],
  // Rc below the tool radius: where the point's own solver's inverse rose above its flank limit.
  ['Rf straight, Rc convex below R', (R, r) => [r() < 0.5 ? I : -I, R * (0.3 + 0.7 * r())]],
  ['Rf straight, Rc concave', (R, r) => [r() < 0.5 ? I : -I, -R * (1.5 + 40 * r())]],
  ['Rc straight, Rf convex', (R, r) => [R * (0.3 + 20 * r() ** 2), r() < 0.5 ? I : -I]],
  ['Rc straight, Rf concave', (R, r) => [-R * (1.5 + 40 * r()), r() < 0.5 ? I : -I]],
  ['both straight', (_R, r) => [r() < 0.5 ? I : -I, r() < 0.5 ? I : -I]],
  [
    'a sphere',
    (R, r) => {
      const s = (r() < 0.5 ? 1 : -1) * R * (2 + 40 * r());
      return [s, s];
    },
  ],
  ['both curved', (R, r) => [(r() < 0.5 ? 1 : -1) * R * (2 + 40 * r()), (r() < 0.5 ? 1 : -1) * R * (2 + 40 * r())]],
];

interface Case {
  readonly tool: ToolInput;
  readonly pattern: PassPattern;
  readonly rf: number;
  readonly rc: number;
  /** The fraction of the height limit (forward) or the widest step-over (inverse) asked. */
  readonly at: number;
}

/** Seeded cases of one family that take the tool (no gouging, a scallop forms). */
function casesOf(seed: number, family: (typeof FAMILIES)[number][1], count: number): Case[] {
  const r = seededRandom(seed);
  const out: Case[] = [];
  while (out.length < count) {
    const R = 0.5 + 10 * r();
    const k = r();
    const tool = {
      toolRadiusMm: R,
      cornerRadiusMm: k < 0.25 ? R : R * (0.05 + 0.9 * r()),
      leadAngleDeg: 2 + 78 * r(),
      tiltAngleDeg: r() < 0.5 ? 0 : 60 * r() - 30,
    };
    const [rf, rc] = family(R, r);
    const pattern: PassPattern = r() < 0.5 ? 'one-way' : 'zigzag';
    const at = 0.02 + 0.979 * Math.sqrt(r());
    const surface = answering(rf, rc);
    const model = registered(surface.kind);
    if (doublyCurvedGouges(tool, { feedRadiusMm: rf, crossRadiusMm: rc }) || model.fit(tool, surface).gouges) continue;
    if (model.leavesNoScallop(tool, surface) || !(model.limits(tool, surface).limitMm > 1e-6)) continue;
    out.push({ tool, pattern, rf, rc, at });
  }
  return out;
}

function answered(request: CurvedRequest): Extract<CurvedReply, { ok: true }> {
  const reply = solvePage(request) as CurvedReply;
  if (!reply.ok) throw new Error(`refused: ${JSON.stringify(request)} ${JSON.stringify(reply.errors)}`);
  return reply;
}

const exactParts = (e: ExactForward | ExactInverse) => ({
  intervalMm: e.intervalMm,
  halfWidthRightMm: e.halfWidthRightMm,
  halfWidthLeftMm: e.halfWidthLeftMm,
  contactOffsetMm: e.contactOffsetMm,
  cuspHeightMm: e.cuspHeightMm,
  otherCuspHeightMm: e.otherCuspHeightMm,
});

const roughnessParts = (r: Roughness) => ({ rzMm: r.rzMm, raMm: r.raMm, rqMm: r.rqMm });

/** Checks one case, forward and inverse (and the teaching views), against the answering surface's model. */
function check(c: Case, teach: boolean): void {
  const { tool, pattern, rf, rc } = c;
  const label = JSON.stringify({ ...c, rf: String(rf), rc: String(rc) });
  const surface = answering(rf, rc);
  const model = registered(surface.kind);
  const point = { ...tool, pattern, feedRadiusMm: rf, crossRadiusMm: rc };
  const limits = model.limits(tool, surface);
  const maxMm = model.maxIntervalMm(tool, pattern, surface);
  const base = { ...tool, pattern, surface };

  // Forward: h to L.
  const h = c.at * limits.limitMm;
  const f = answered({ mode: 'curved-forward', input: { ...point, scallopHeightMm: h } });
  const ef = model.forward({ ...base, scallopHeightMm: h });
  expect(f.exact, label).toMatchObject({ ...exactParts(ef), maxIntervalMm: maxMm, limits });
  expect(f.limits, label).toMatchObject({ hMm: limits.limitMm, intervalMm: maxMm });
  expect(f.roughness, label).toMatchObject(roughnessParts(exactRoughness({ ...base, scallopHeightMm: h }, ef)));
  // Each comparison row's step-over leaves the model's cusp.
  for (const row of [f.comparison?.plane, f.comparison?.cylinderAlong, f.comparison?.cylinderAcross])
    if (row?.ok && row.realScallopMm !== null)
      expect(row.realScallopMm, label).toBe(model.inverse({ ...base, intervalMm: row.intervalMm }).cuspHeightMm);

  // Inverse: L to the cusps, never above the flank limit; at c.at of the widest step-over and near it
  // (where the point's own solver went wrong with Rf straight and Rc convex).
  for (const L of [c.at * maxMm, (0.9 + 0.099 * c.at) * maxMm]) {
    const i = answered({ mode: 'curved-inverse', input: { ...point, intervalMm: L } });
    expect(i.exact.cuspHeightMm, `${label} L ${L}`).toBeLessThanOrEqual(limits.limitMm);
    const ei = model.inverse({ ...base, intervalMm: L });
    expect(i.exact, label).toMatchObject({ ...exactParts(ei), maxIntervalMm: maxMm, limits });
    expect(i.roughness, label).toMatchObject(roughnessParts(exactRoughnessAtInterval(tool, pattern, ei, surface)));
  }
  if (!teach) return;
  const L = c.at * maxMm;

  // The teaching views in inverse mode are drawn at the model's cusp, the profile's cusps the model's.
  const t = teachCurved({ mode: 'curved-inverse', input: { ...point, intervalMm: L } });
  if (!t.ok) return;
  const section = model.inverse({ ...base, intervalMm: t.section.exact.intervalMm });
  expect(t.section.exact.cuspHeightMm, label).toBe(section.cuspHeightMm);
  expect(t.section.exact.maxIntervalMm, label).toBe(maxMm);
}

describe('a doubly curved point has one exact answer: the registry model, a straight radius its cylinder or plane', () => {
  for (const [name, family] of FAMILIES) {
    it(`seed 2728: ${name}, forward and inverse, the reply and the teaching views`, () => {
      casesOf(2728, family, 5).forEach((c, k) => {
        check(c, k === 0);
      });
    });
  }

  it('seed 2729: the command line report (JSON) shows the model for both radii curved and a sphere', async () => {
    const model = registered('doublyCurved');
    const family = (name: string) => (FAMILIES.find(([n]) => n === name) as (typeof FAMILIES)[number])[1];
    const cases = [...casesOf(2729, family('a sphere'), 2), ...casesOf(2729, family('both curved'), 2)];
    for (const c of cases) {
      const { tool, pattern, rf, rc } = c;
      const surface: DoublyCurvedSurface = { kind: 'doublyCurved', feedRadiusMm: rf, crossRadiusMm: rc };
      const args = [
        ...['--R', String(tool.toolRadiusMm), '--Rcr', String(tool.cornerRadiusMm)],
        ...['--rho', String(tool.leadAngleDeg), '--tilt', String(tool.tiltAngleDeg), '--pattern', pattern],
        ...['--feed-radius', String(rf), '--cross-radius', String(rc), '--json'],
      ];
      const base = { ...tool, pattern, surface };
      const h = c.at * model.limits(tool, surface).limitMm;
      const f = await runMain([...args, '--h', String(h)]);
      const ef = model.forward({ ...base, scallopHeightMm: h });
      expect(JSON.parse(f.stdout), f.stderr).toMatchObject({
        maxInterval: model.maxIntervalMm(tool, pattern, surface),
        exact: { interval: ef.intervalMm, halfWidthRight: ef.halfWidthRightMm, scallopHeight: ef.cuspHeightMm },
        roughness: { Ra: exactRoughness({ ...base, scallopHeightMm: h }, ef).raMm },
      });
      const L = c.at * model.maxIntervalMm(tool, pattern, surface);
      const i = await runMain([...args, '--interval', String(L)]);
      const ei = model.inverse({ ...base, intervalMm: L });
      expect(JSON.parse(i.stdout), i.stderr).toMatchObject({
        exact: { scallopHeight: ei.cuspHeightMm, halfWidthLeft: ei.halfWidthLeftMm },
        roughness: { Ra: exactRoughnessAtInterval(tool, pattern, ei, surface).raMm },
      });
    }
  });
});
