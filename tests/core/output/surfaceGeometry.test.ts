/** The design surface's display geometry (surfaceGeometry.ts): points on the cylinder, offsets, pass motions. */
import { describe, expect, it } from 'vitest';
import type { Vec3 } from '../../../src/core/math/vec';
import {
  applyMatrix,
  axisFoot,
  fromSurfaceSection,
  passMatrix,
  patchIndices,
  surfacePatch,
  surfacePoint,
  surfacePolyline,
  toSurfaceSection,
} from '../../../src/core/output/surfaceGeometry';
import type { CylinderSurface, Surface } from '../../../src/core/surfaces/cylinder';
import { placeTool } from '../../../src/core/tool/placement';

const cyl = (radiusMm: number, axis: 'feed' | 'cross'): CylinderSurface => ({ kind: 'cylinder', radiusMm, axis });
const CYLINDERS: CylinderSurface[] = [
  cyl(50, 'feed'),
  cyl(-50, 'feed'),
  cyl(7, 'cross'),
  cyl(-7, 'cross'),
  cyl(2.5, 'feed'),
];

/** Distance of p from the cylinder's axis (through z = -Rs, along X or Y). */
const fromAxis = (c: CylinderSurface, p: Vec3) =>
  c.axis === 'feed' ? Math.hypot(p[1], p[2] + c.radiusMm) : Math.hypot(p[0], p[2] + c.radiusMm);

describe('surface geometry for the views', () => {
  it('patch points lie on the cylinder, and the h surface at radius Rs + h (convex) or |Rs| - h (concave), to 1e-12', () => {
    for (const c of CYLINDERS) {
      for (const h of [0, 0.05, 1]) {
        const pts = surfacePatch(c, h, 4, 6, 12, 16);
        expect(pts.length).toBe(13 * 17 * 3);
        const expected = Math.abs(c.radiusMm) + Math.sign(c.radiusMm) * h;
        for (let i = 0; i < pts.length; i += 3) {
          const p: Vec3 = [pts[i] as number, pts[i + 1] as number, pts[i + 2] as number];
          expect(Math.abs(fromAxis(c, p) - expected), `${JSON.stringify(c)} h ${h}`).toBeLessThan(1e-12);
        }
      }
    }
  });

  it('the contact is the origin, the normal there is +Z, and arc lengths along the surface are kept', () => {
    for (const c of CYLINDERS) {
      expect(surfacePoint(c, 0, 0, 0)).toEqual([0, 0, 0]);
      const up = surfacePoint(c, 0, 0, 0.3);
      expect(up[0]).toBe(0);
      expect(up[1]).toBe(0);
      expect(up[2]).toBeCloseTo(0.3, 14);
      // A polyline across the feed (around the cylinder for axis = feed): its length tends to the arc's.
      const n = 2000;
      const line = surfacePolyline(c, 0, [0, 0], [0, 3], n);
      let length = 0;
      for (let i = 1; i <= n; i++) {
        const d = [0, 1, 2].map((k) => (line[3 * i + k] as number) - (line[3 * i - 3 + k] as number));
        length += Math.hypot(...(d as [number, number, number]));
      }
      expect(Math.abs(length - 3)).toBeLessThan(1e-6);
    }
    // A plane is (feed, cross, height) itself.
    expect(surfacePoint({ kind: 'plane' }, 1, 2, 3)).toEqual([1, 2, 3]);
  });

  it('no cancellation on a cylinder of a kilometre: a nanometre above the surface stays a nanometre', () => {
    const c = cyl(1e6, 'feed');
    const p = surfacePoint(c, 0, 1, 1e-9);
    // z = h cos(theta) - 2 Rs sin^2(theta / 2), theta = 1e-6: -5e-7 + 1e-9.
    expect(p[2]).toBeCloseTo(1e-9 * Math.cos(1e-6) - 2e6 * Math.sin(5e-7) ** 2, 20);
  });

  it('patch indices cover the grid with two triangles per cell', () => {
    const idx = patchIndices(3, 4);
    expect(idx.length).toBe(3 * 4 * 6);
    expect(Math.max(...idx)).toBe(4 * 5 - 1);
  });

  it('a pass motion carries the contact to the surface at the given arc length, and the normal to the normal', () => {
    const surfaces: Surface[] = [{ kind: 'plane' }, ...CYLINDERS];
    for (const c of surfaces) {
      for (const s of [2.5, -2.5, 0.3]) {
        for (const mirror of [false, true]) {
          const m = passMatrix(c, s, mirror);
          const contact = applyMatrix(m, [0, 0, 0]);
          const target = surfacePoint(c, 0, s, 0);
          for (let k = 0; k < 3; k++)
            expect(Math.abs((contact[k] as number) - (target[k] as number))).toBeLessThan(1e-12);
          // A point h above the contact goes h above the new contact (radially).
          const up = applyMatrix(m, [0, 0, 0.2]);
          const targetUp = surfacePoint(c, 0, s, 0.2);
          for (let k = 0; k < 3; k++) expect(Math.abs((up[k] as number) - (targetUp[k] as number))).toBeLessThan(1e-12);
          // Along the feed stays along the feed; mirror flips what lies across the feed.
          const side = applyMatrix(m, [0, 1, 0]);
          const ahead = applyMatrix(m, [1, 0, 0]);
          expect(ahead[0] - contact[0]).toBeCloseTo(1, 12);
          const across = [side[0] - contact[0], side[1] - contact[1], side[2] - contact[2]];
          expect(Math.hypot(...(across as [number, number, number]))).toBeCloseTo(1, 12);
          if (c.kind === 'plane' || c.axis === 'cross') expect(across[1]).toBeCloseTo(mirror ? -1 : 1, 12);
        }
      }
    }
  });

  it('the tool axis meets the cylinder at its foot, below the tool centre', () => {
    const p = placeTool({ toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 10, tiltAngleDeg: 12 });
    for (const c of CYLINDERS) {
      const foot = axisFoot(c, p.centre, p.axis);
      expect(Math.abs(fromAxis(c, foot) - Math.abs(c.radiusMm))).toBeLessThan(1e-12);
      // On the line through O along the axis, below O.
      const d = [0, 1, 2].map((k) => (p.centre[k] as number) - (foot[k] as number));
      const t = (d[2] as number) / p.axis[2];
      expect(t).toBeGreaterThan(0);
      for (let k = 0; k < 3; k++) expect(Math.abs((d[k] as number) - t * (p.axis[k] as number))).toBeLessThan(1e-12);
    }
    const plane = axisFoot({ kind: 'plane' }, p.centre, p.axis);
    expect(Math.abs(plane[2])).toBeLessThan(1e-15);
  });

  it('a section in surface coordinates (arc length, radial height) and back', () => {
    for (const c of CYLINDERS) {
      const pts = [0, 0, 1, 0.2, -2, 0.7, 0.5, 1.5];
      const s = toSurfaceSection(c, pts);
      expect(s[0]).toBe(0);
      expect(s[1]).toBe(0);
      for (let i = 0; i < pts.length; i += 2) {
        const [y, z] = fromSurfaceSection(c, s[i] as number, s[i + 1] as number);
        expect(Math.abs(y - (pts[i] as number))).toBeLessThan(1e-12);
        expect(Math.abs(z - (pts[i + 1] as number))).toBeLessThan(1e-12);
        if (c.axis === 'feed') {
          // The radial height is the distance from the axis less |Rs| (convex) or |Rs| less it (concave).
          const rho = Math.hypot(pts[i] as number, (pts[i + 1] as number) + c.radiusMm);
          const h = c.radiusMm > 0 ? rho - c.radiusMm : -c.radiusMm - rho;
          expect(Math.abs((s[i + 1] as number) - h)).toBeLessThan(1e-12);
        }
      }
    }
    // Across the axis (and on a plane) the section is straight: the coordinates are kept.
    expect([...toSurfaceSection(cyl(5, 'cross'), [1, 2])]).toEqual([1, 2]);
  });
});
