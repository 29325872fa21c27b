/** The camera's fit to the scene's points (src/render/cameraFit.ts): inside with a margin, filling the view. */
import fc from 'fast-check';
import { PerspectiveCamera, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import {
  type CameraPreset,
  cameraBasis,
  fitCamera,
  presetDirection,
  projectPoints,
  type Vec3,
  viewFill,
} from '../../src/render/cameraFit';

/** The corners of a box from `lo` to `hi` (flat xyz). */
function corners(lo: Vec3, hi: Vec3): number[] {
  const out: number[] = [];
  for (let i = 0; i < 8; i++) out.push(i & 1 ? hi[0] : lo[0], i & 2 ? hi[1] : lo[1], i & 4 ? hi[2] : lo[2]);
  return out;
}

/** A tool of radius 3 with its shank standing on the origin, tilted, and the paths beside it. */
const TOOL = corners([-3, -3, 0], [3, 3, 9.6]);

describe('fitCamera', () => {
  for (const preset of ['iso', 'feed', 'top'] as CameraPreset[]) {
    for (const aspect of [0.66, 1, 16 / 9, 3]) {
      it(`${preset} at aspect ${aspect.toFixed(2)}: every point inside, the limiting dimension filled to 1 - margin`, () => {
        const { towardsCamera, up } = presetDirection(preset);
        const options = { fovDeg: 40, aspect, margin: 0.1 };
        const fit = fitCamera(TOOL, 8, towardsCamera, up, options);
        if (fit === null) throw new Error('no fit');
        const { fill, inside } = viewFill(projectPoints(TOOL, 8, fit, up, options));
        expect(inside).toBe(true);
        expect(fill).toBeCloseTo(0.9, 9);
      });
    }
  }

  it('any points, direction and view: inside the margin, filling 1 - margin (property)', () => {
    const coordinate = fc.double({ min: -100, max: 100, noNaN: true });
    const point = fc.tuple(coordinate, coordinate, coordinate);
    fc.assert(
      fc.property(
        fc.array(point, { minLength: 2, maxLength: 30 }),
        fc.tuple(fc.double({ min: -1, max: 1, noNaN: true }), fc.double({ min: -1, max: 1, noNaN: true })),
        fc.double({ min: 0.3, max: 4, noNaN: true }),
        fc.double({ min: 20, max: 60, noNaN: true }),
        fc.double({ min: 0.02, max: 0.5, noNaN: true }),
        (points, [a, b], aspect, fovDeg, margin) => {
          const towards: Vec3 = [
            Math.cos(3 * a) * Math.cos(1.5 * b),
            Math.sin(3 * a) * Math.cos(1.5 * b),
            Math.sin(1.5 * b),
          ];
          const up: Vec3 = Math.abs(towards[2]) > 0.99 ? [0, 1, 0] : [0, 0, 1];
          // Points spread across the view more than in depth (as the scene is; nearly along one line of sight the projection is ill-conditioned) (not along one line of sight).
          const { right, upOnScreen, forward } = cameraBasis(towards, up);
          const across = (d: Vec3) => {
            const s = points.map((p) => p[0] * d[0] + p[1] * d[1] + p[2] * d[2]);
            return Math.max(...s) - Math.min(...s);
          };
          fc.pre(Math.max(across(right), across(upOnScreen)) > Math.max(1, 1.5 * across(forward)));
          const xyz = points.flat();
          const options = { fovDeg, aspect, margin };
          const fit = fitCamera(xyz, points.length, towards, up, options);
          if (fit === null) return false;
          const ndc = projectPoints(xyz, points.length, fit, up, options);
          const limit = 1 - margin + 1e-6;
          for (const p of ndc) {
            if (p === null) return false;
            if (Math.abs(p[0]) > limit || Math.abs(p[1]) > limit) return false;
          }
          // Both extremes of the limiting axis touch the margin: the view is filled, not just fitted;
          // except where the camera had to stop short of a point it would otherwise stand on.
          const nearest = Math.min(
            ...points.map(
              (p) =>
                (p[0] - fit.position[0]) * forward[0] +
                (p[1] - fit.position[1]) * forward[1] +
                (p[2] - fit.position[2]) * forward[2],
            ),
          );
          const extent = Math.max(...points.flat().map(Math.abs));
          const stoppedShort = nearest < 2e-3 * extent;
          return (stoppedShort || viewFill(ndc).fill >= 1 - margin - 1e-3) && fit.distanceMm > 0;
        },
      ),
      { numRuns: 300 },
    );
  });

  it('agrees with three.js: the fitted camera projects the points where a PerspectiveCamera does', () => {
    const { towardsCamera, up } = presetDirection('iso');
    const options = { fovDeg: 40, aspect: 1.5, margin: 0.2 };
    const fit = fitCamera(TOOL, 8, towardsCamera, up, options);
    if (fit === null) throw new Error('no fit');
    const camera = new PerspectiveCamera(40, 1.5, 0.01, 1000);
    camera.up.set(...up);
    camera.position.set(...fit.position);
    camera.lookAt(new Vector3(...fit.target));
    camera.updateMatrixWorld();
    const ours = projectPoints(TOOL, 8, fit, up, options);
    for (let i = 0; i < 8; i++) {
      const p = new Vector3(TOOL[3 * i], TOOL[3 * i + 1], TOOL[3 * i + 2]).project(camera);
      expect(ours[i]?.[0]).toBeCloseTo(p.x, 9);
      expect(ours[i]?.[1]).toBeCloseTo(p.y, 9);
    }
  });

  it('Top: +Y up the screen and X (the feed) to the right; along the feed: +Y to the right', () => {
    const top = presetDirection('top');
    const b = cameraBasis(top.towardsCamera, top.up);
    expect(b.upOnScreen).toEqual([0, 1, 0]);
    expect(b.right).toEqual([1, 0, 0]);
    const feed = presetDirection('feed');
    expect(cameraBasis(feed.towardsCamera, feed.up).right).toEqual([0, 1, 0]);
  });

  it('no points or a degenerate view: no fit', () => {
    expect(fitCamera([], 0, [0, 0, 1], [0, 1, 0], { fovDeg: 40, aspect: 1, margin: 0.1 })).toBeNull();
    expect(fitCamera(TOOL, 8, [0, 0, 1], [0, 1, 0], { fovDeg: 40, aspect: 0, margin: 0.1 })).toBeNull();
    const one = fitCamera([1, 2, 3], 1, [0, 0, 1], [0, 1, 0], { fovDeg: 40, aspect: 1, margin: 0.1 });
    expect(one?.distanceMm).toBeGreaterThan(0);
  });
});
