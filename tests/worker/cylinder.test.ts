/**
 * The worker's answers on a cylinder (issue 12, the page): the exact step-over of the core, the
 * comparison rows of the core (plane answer, corrected procedures) with their deviations, the scene's
 * surface and cusps on the h pseudo surface, and the profile view's curves in surface coordinates.
 */
import { describe, expect, it } from 'vitest';
import {
  CURVATURE_ROW_KEYS,
  type CylinderSurface,
  compareForward,
  compareInverse,
  exactForward,
  exactInverse,
  forwardInput,
  inverseInput,
  maxIntervalMm,
  type ToolInput,
} from '../../src/core/index';
import { solve, teach, transferables } from '../../src/worker/api';
import { everyNumberFinite } from '../support/finite';

const tool = (tilt = 0): ToolInput => ({ toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: tilt });
const cyl = (radiusMm: number, axis: 'feed' | 'cross'): CylinderSurface => ({ kind: 'cylinder', radiusMm, axis });
const CASES: CylinderSurface[] = [cyl(20, 'feed'), cyl(-40, 'feed'), cyl(10, 'cross'), cyl(-200, 'cross')];

describe('worker solve and teach on a cylinder', () => {
  it('forward: exact L of the core; the comparison rows of the core, L/2 and deviations, the scallop each leaves', () => {
    for (const s of CASES) {
      for (const pattern of ['one-way', 'zigzag'] as const) {
        const input = forwardInput(tool(6), pattern, 0.05, s);
        const reply = solve({ mode: 'forward', input });
        if (!reply.ok) throw new Error(JSON.stringify(reply.errors));
        expect(everyNumberFinite(reply)).toBe(true);
        const e = exactForward(input);
        expect(reply.exact.intervalMm).toBe(e.intervalMm);
        expect(reply.exact.widthRightMm).toBe(e.halfWidthRightMm);
        const c = compareForward(input);
        const k = c.curvature;
        if (k === null || reply.curvature === null) throw new Error('a cylinder has comparison rows');
        expect(reply.curvature.map((r) => r.key)).toEqual([...CURVATURE_ROW_KEYS]);
        const byKey = new Map(reply.curvature.map((r) => [r.key, r]));
        const plane = byKey.get('plane');
        if (!k.plane.ok) throw new Error('plane applies');
        expect(plane?.valueMm).toBe(k.plane.halfIntervalMm);
        expect(plane?.deviationMm).toBe(k.plane.deviationMm / 2);
        expect(plane?.deviationPercent).toBe(k.plane.deviationPercent);
        expect(plane?.realScallopMm).toBe(k.plane.realScallopMm);
        for (const key of ['sekine', 'redonnet', 'osculating', 'cornerBall'] as const) {
          const r = k.corrected[key];
          const row = byKey.get(`${key}Corrected`);
          if (r.ok) expect(row?.valueMm).toBe(r.halfIntervalMm);
          else expect(row?.note).not.toBeNull();
        }
      }
    }
  });

  it('inverse: the cusp height of the core, the widest step-over on the cylinder, the comparison heights', () => {
    for (const s of CASES) {
      const input = inverseInput(tool(0), 'one-way', 2.2, s);
      const reply = solve({ mode: 'inverse', input });
      if (!reply.ok) throw new Error(JSON.stringify(reply.errors));
      expect(reply.exact.cuspHeightMm).toBe(exactInverse(input).cuspHeightMm);
      expect(reply.exact.maxIntervalMm).toBe(maxIntervalMm(input, 'one-way', s));
      const k = compareInverse(input).curvature;
      if (k === null || !k.plane.ok || reply.curvature === null) throw new Error('rows');
      expect(reply.curvature[0]?.valueMm).toBe(k.plane.scallopHeightMm);
    }
    // A plane has none.
    const plane = solve({ mode: 'forward', input: forwardInput(tool(), 'one-way', 0.05) });
    expect(plane.ok && plane.curvature).toBe(null);
  });

  it('a corrected step-over beyond the widest that leaves a scallop is said as data (a wall), its own L kept', () => {
    // Redonnet's Reff (about 24 mm at 5 degrees of lead) against a trough of 30 mm: 1/rho = 1/24 - 1/30.
    const input = forwardInput(tool(0), 'one-way', 0.05, cyl(-30, 'feed'));
    const reply = solve({ mode: 'forward', input });
    if (!reply.ok || reply.curvature === null) throw new Error('valid');
    const red = reply.curvature.find((r) => r.key === 'redonnetCorrected');
    const c = compareForward(input).curvature?.corrected.redonnet;
    if (!c?.ok || c.warning === null) throw new Error('a wall here');
    expect(red?.valueMm).toBe(c.halfIntervalMm);
    expect(red?.realScallopMm).toBe(null);
    expect(red?.note).toEqual({ kind: 'wall', intervalMm: c.intervalMm, maxIntervalMm: reply.exact.maxIntervalMm });
  });

  it('the scene: the surface, and the cusps on the h pseudo surface (radially h from the cylinder)', () => {
    for (const s of CASES) {
      const reply = solve({ mode: 'forward', input: forwardInput(tool(6), 'one-way', 0.05, s) });
      if (!reply.ok) throw new Error('valid');
      const g = reply.scene;
      expect(g.surface).toEqual(s);
      expect(g.right).toBe(null);
      const p = g.cuspPoints?.right;
      if (!p) throw new Error('a cusp');
      const fromAxis = s.axis === 'feed' ? Math.hypot(p[1], p[2] + s.radiusMm) : Math.hypot(p[0], p[2] + s.radiusMm);
      expect(Math.abs(fromAxis - (Math.abs(s.radiusMm) + Math.sign(s.radiusMm) * 0.05))).toBeLessThan(1e-12);
    }
    const plane = solve({ mode: 'forward', input: forwardInput(tool(6), 'one-way', 0.05) });
    expect(plane.ok && plane.scene.cuspPoints).toBe(null);
    expect(plane.ok && plane.scene.surface).toEqual({ kind: 'plane' });
  });

  it("teach: the pass profile in surface coordinates, where each comparison row puts the next pass; no plane procedure's frames", () => {
    for (const s of CASES) {
      const input = forwardInput(tool(0), 'one-way', 0.05, s);
      const reply = teach({ mode: 'forward', input });
      if (!reply.ok || reply.cylinder === null) throw new Error('cylinder curves');
      expect(reply.frames).toEqual([]);
      const c = reply.cylinder;
      const e = exactForward(input);
      // The profile passes through the contact, and its height at +-L/2 is h (no tilt: symmetric).
      const at = (target: number) => {
        const p = c.passProfile;
        for (let i = 2; i < p.length; i += 2) {
          const a = p[i - 2] as number;
          const b = p[i] as number;
          if (a <= target && target <= b) {
            const u = (target - a) / (b - a);
            return (p[i - 1] as number) + u * ((p[i + 1] as number) - (p[i - 1] as number));
          }
        }
        return Number.NaN;
      };
      expect(at(0)).toBeCloseTo(0, 9);
      expect(Math.abs(at(e.intervalMm / 2) - 0.05)).toBeLessThan(2e-3);
      // The charts' exact curve is the cylinder's (at the current lead: the result's L).
      const at5 = reply.sweeps.lead.angleDeg.indexOf(5);
      expect(reply.sweeps.lead.values.exact[at5]).toBe(e.intervalMm);
      const plane = c.comparison.find((r) => r.key === 'plane');
      expect(plane?.intervalMm).toBe(exactForward(forwardInput(tool(0), 'one-way', 0.05)).intervalMm);
      const buffers = transferables(reply);
      expect(buffers).toContain(c.passProfile.buffer);
      // Inverse mode: the views' forward state keeps the surface.
      const back = teach({ mode: 'inverse', input: inverseInput(tool(0), 'one-way', e.intervalMm, s) });
      expect(back.ok && back.forward.surface).toEqual(s);
    }
  });
});
