/**
 * Three-axis replies carry Rz, Ra, Rq on a sloped plane (issue 28 point 2): the upright tool is the
 * tool at the slope's lead and tilt, so the plane's roughness at that posture. Checked against the
 * core's plane roughness at a posture this test computes itself, from the vectors of the slope and
 * the pass (not slopePosture's closed form), over a seeded stratified sweep of slopes, raster
 * angles, passes, tools and heights; on a surface of revolution the reply has none (null).
 */
import { describe, expect, it } from 'vitest';
import { exactForward, exactRoughness, forwardInput } from '../../src/core/index';
import { validateThreeAxis } from '../../src/core/threeAxis/validate';
import { solveThreeAxisRequest } from '../../src/worker/jobs/threeAxis';
import { seededRandom } from '../support/bruteForce';

type Vec = [number, number, number];
const dot = (a: Vec, b: Vec) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a: Vec, b: Vec): Vec => [
  a[1] * b[2] - a[2] * b[1],
  a[2] * b[0] - a[0] * b[2],
  a[0] * b[1] - a[1] * b[0],
];
const unit = (a: Vec): Vec => {
  const n = Math.hypot(...a);
  return [a[0] / n, a[1] / n, a[2] / n];
};
const RAD = Math.PI / 180;

/**
 * Lead and tilt (degrees) of the vertical tool on a plane of slope `slopeDeg` (x uphill), fed up the
 * slope in the vertical plane at `psiDeg` in plan from the fall line: the feed X is where that
 * vertical plane cuts the sloped one, Z the normal, Y = Z x X; the axis (0, 0, 1) in that frame is
 * (cos b sin r, sin b, cos b cos r).
 */
function postureByVectors(slopeDeg: number, psiDeg: number): { lead: number; tilt: number } {
  const a = slopeDeg * RAD;
  const n: Vec = [-Math.sin(a), 0, Math.cos(a)];
  const plan: Vec = [Math.cos(psiDeg * RAD), -Math.sin(psiDeg * RAD), 0];
  // The feed lies in the plane (n . X = 0) above the plan direction: X = plan + t z, t from n . X = 0.
  const X = unit([plan[0], plan[1], -dot(n, plan) / n[2]]);
  const Y = cross(n, X);
  const up: Vec = [0, 0, 1];
  return {
    lead: Math.atan2(dot(up, X), dot(up, n)) / RAD,
    tilt: Math.asin(Math.max(-1, Math.min(1, dot(up, Y)))) / RAD,
  };
}

describe('three-axis roughness on a sloped plane', () => {
  it('is the plane roughness at the posture of the slope (seed 2828, 120 cases over slope, raster angle, passes, tool, h)', () => {
    const rand = seededRandom(2828);
    let checked = 0;
    for (let i = 0; i < 120; i++) {
      // Strata: 8 slopes bands over [0, 88), 6 raster-angle bands over [0, 90], edges included.
      const slope = i % 40 === 0 ? 0 : ((i % 8) + rand()) * 11;
      const passes = i % 5 === 0 ? 'waterline' : 'raster';
      const psi = i % 17 === 0 ? 90 : i % 13 === 0 ? 0 : ((Math.floor(i / 8) % 6) + rand()) * 15;
      const R = 0.5 + rand() * 9.5;
      const Rcr = i % 11 === 0 ? R : R * (0.05 + 0.9 * rand());
      const hMm = Rcr * (1e-4 + 0.05 * rand() ** 2);
      const v = validateThreeAxis(
        { R, Rcr, slope: passes === 'waterline' && slope === 0 ? 5 : slope, passes, rasterAngle: psi },
        'h',
        hMm,
      );
      if (!v.ok) continue;
      const reply = solveThreeAxisRequest({ mode: 'three-axis', input: v.value });
      if (!reply.ok) continue;
      const c = v.value.case as { slopeDeg: number };
      const { lead, tilt } = postureByVectors(c.slopeDeg, passes === 'waterline' ? 90 : psi);
      const input = forwardInput(
        { toolRadiusMm: R, cornerRadiusMm: Rcr, leadAngleDeg: lead, tiltAngleDeg: tilt },
        'one-way',
        hMm,
      );
      const e = exactForward(input);
      const want = exactRoughness(input, e);
      const got = reply.roughness;
      if (got === null) throw new Error('a sloped plane has roughness');
      const tol = 1e-9 + 1e-7 * want.rzMm;
      expect(Math.abs(got.rzMm - want.rzMm), `case ${i}`).toBeLessThan(tol);
      expect(Math.abs(got.raMm - want.raMm), `case ${i}`).toBeLessThan(tol);
      expect(Math.abs(got.rqMm - want.rqMm), `case ${i}`).toBeLessThan(tol);
      // The same surface: the reply's L is this posture's L.
      expect(Math.abs(reply.answer.intervalMm - e.intervalMm), `case ${i}`).toBeLessThan(1e-7 * e.intervalMm + 1e-9);
      expect(got.scallopHeightMm).toBe(reply.answer.cuspHeightMm);
      checked++;
    }
    expect(checked).toBeGreaterThan(75);
  });

  it('a waterline on a surface of revolution has no roughness (null; the page says why)', () => {
    const v = validateThreeAxis(
      { R: 3, Rcr: 1, slope: 40, passes: 'waterline', feedRadius: 50, crossRadius: 50 },
      'h',
      0.02,
    );
    if (!v.ok) throw new Error('valid');
    const reply = solveThreeAxisRequest({ mode: 'three-axis', input: v.value });
    expect(reply.ok && reply.roughness).toBe(null);
  });
});
