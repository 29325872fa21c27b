/**
 * The 3D scene's marks written in place (sceneMarks.ts) and the in-place forms of the surface's
 * display geometry (surfaceGeometry.ts): each checked against the allocating form or against the
 * geometry it must have (distances, planes, the surface's own points).
 */
import { describe, expect, it } from 'vitest';
import type { Vec3 } from '../../../src/core/math/vec';
import { circleInto, dimensionPointCount, surfaceDimensionInto } from '../../../src/core/output/sceneMarks';
import {
  fromSurfaceSection,
  surfacePatch,
  surfacePoint,
  surfacePointInto,
  surfacePolyline,
} from '../../../src/core/output/surfaceGeometry';
import type { Surface } from '../../../src/core/surfaces/cylinder';

const SURFACES: Surface[] = [
  { kind: 'plane' },
  { kind: 'cylinder', radiusMm: 12, axis: 'feed' },
  { kind: 'cylinder', radiusMm: -40, axis: 'feed' },
  { kind: 'cylinder', radiusMm: 7, axis: 'cross' },
  { kind: 'cylinder', radiusMm: -60, axis: 'cross' },
];

const point = (a: ArrayLike<number>, i: number): Vec3 => [
  a[3 * i] as number,
  a[3 * i + 1] as number,
  a[3 * i + 2] as number,
];
const sub = (a: Vec3, b: Vec3): Vec3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a: Vec3, b: Vec3) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const norm = (a: Vec3) => Math.hypot(...a);
const unit = (a: Vec3): Vec3 => [a[0] / norm(a), a[1] / norm(a), a[2] / norm(a)];

describe('a circle written in place', () => {
  it('lies on the sphere of its radius about its centre, in the plane of its normal, evenly around', () => {
    const normals: Vec3[] = [
      [0, 0, 1],
      [0, 0, -1],
      [1, 0, 0],
      [0.6, 0.8, 0],
      [0.2, -0.3, 0.9327379053088815],
    ];
    for (const raw of normals) {
      const n = unit(raw);
      const centre: Vec3 = [0.4, -1.2, 2.5];
      const count = 96;
      const out = new Float64Array(3 * (count + 2));
      circleInto(out, 2, centre, n, 0.75, count);
      // Nothing written before the first point asked for.
      expect([...out.slice(0, 6)]).toEqual([0, 0, 0, 0, 0, 0]);
      for (let i = 0; i < count; i++) {
        const r = sub(point(out, i + 2), centre);
        expect(Math.abs(norm(r) - 0.75)).toBeLessThan(1e-12);
        expect(Math.abs(dot(r, n))).toBeLessThan(1e-12);
        // Consecutive points 2 pi / n apart: chord 2 r sin(pi / n).
        const next = sub(point(out, ((i + 1) % count) + 2), centre);
        expect(Math.abs(norm(sub(next, r)) - 2 * 0.75 * Math.sin(Math.PI / count))).toBeLessThan(1e-12);
      }
      // The first point along Z x n (X when n is along Z).
      const first = sub(point(out, 2), centre);
      const zxn: Vec3 = [-n[1], n[0], 0];
      const u: Vec3 = norm(zxn) < 1e-6 ? [1, 0, 0] : unit(zxn);
      for (let k = 0; k < 3; k++) expect(first[k]).toBeCloseTo(0.75 * (u[k] as number), 12);
    }
  });
});

describe('a dimension along the surface', () => {
  it('extension lines, arrowheads and the arc on the surface, from the path to the length across', () => {
    for (const s of SURFACES) {
      const segments = 48;
      const count = dimensionPointCount(segments);
      const out = new Float64Array(3 * count);
      const [x, length, tick, arrow] = [-3.9, 2.8, 0.24, 0.21];
      expect(surfaceDimensionInto(out, 0, s, x, length, tick, arrow, segments)).toBe(count);
      const at = (i: number) => point(out, i);
      const close = (a: Vec3, b: Vec3) => expect(norm(sub(a, b))).toBeLessThan(1e-12);
      // Extension line up from the path, the arrowhead's tip at the path, the arc, the other tip and line.
      close(at(0), surfacePoint(s, x, 0, tick));
      close(at(1), surfacePoint(s, x, 0, 0));
      close(at(3), surfacePoint(s, x, 0, 0));
      close(at(5), surfacePoint(s, x, 0, 0));
      const arc = surfacePolyline(s, 0, [x, 0], [x, length], segments);
      for (let i = 0; i <= segments; i++) close(at(6 + i), point(arc, i));
      close(at(count - 4), surfacePoint(s, x, length, 0));
      close(at(count - 2), surfacePoint(s, x, length, 0));
      close(at(count - 1), surfacePoint(s, x, length, tick));
      // The arrowheads' strokes point back along the dimension: into it at the start, out at the end.
      close(at(2), surfacePoint(s, x - 0.5 * arrow, arrow, 0));
      close(at(4), surfacePoint(s, x + 0.5 * arrow, arrow, 0));
      close(at(count - 5), surfacePoint(s, x - 0.5 * arrow, length - arrow, 0));
      close(at(count - 3), surfacePoint(s, x + 0.5 * arrow, length - arrow, 0));
    }
  });
});

describe('the surface geometry written in place', () => {
  it('equals the allocating forms: a point, a patch into a vertex buffer, a section point into a pair', () => {
    for (const s of SURFACES) {
      for (const [f, c, h] of [
        [0, 0, 0],
        [1.3, -2.2, 0.05],
        [-4, 3, 1.5],
      ] as const) {
        const out = [9, 9, 9, 9, 9];
        surfacePointInto(out, 1, s, f, c, h);
        expect(out).toEqual([9, ...surfacePoint(s, f, c, h), 9]);
      }
      const fresh = surfacePatch(s, 0.1, 4, 6, 6, 8);
      const buffer = new Float32Array(fresh.length);
      expect(surfacePatch(s, 0.1, 4, 6, 6, 8, buffer)).toBe(buffer);
      expect([...buffer]).toEqual([...Float32Array.from(fresh)]);
      const pair: [number, number] = [0, 0];
      for (const [cross, height] of [
        [0.7, 0.2],
        [-2.5, 0],
      ] as const) {
        expect(fromSurfaceSection(s, cross, height, pair)).toBe(pair);
        expect(pair).toEqual(fromSurfaceSection(s, cross, height));
        // The section's point is the surface's point at the contact's place along the feed.
        const p = surfacePoint(s, 0, cross, height);
        if (s.kind === 'plane' || s.axis === 'cross') expect(pair).toEqual([cross, height]);
        else expect(pair).toEqual([p[1], p[2]]);
      }
    }
  });
});
