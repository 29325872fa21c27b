import type { CylinderSurface } from '../../domain/surface';
import type { ToolInput } from '../../domain/tool';
import type { Flank } from '../../tool/posture';
import { cylinderSolver } from './solvers';

/**
 * The profile one pass leaves on a cylinder, in the coordinates a cross-section view draws (mm):
 * along the feed, the plane profile of geometry.ts (y, z from the contact), which a view turns about
 * the axis at (0, -Rs) for the next pass; across the feed, the revolved profile in the meridian
 * plane, (position along the axis from the contact, radial height above the surface), from one
 * flank's widest point to the other's.
 * @param samplesPerHalf points per flank (>= 8).
 */
export function revolvedProfile(tool: ToolInput, surface: CylinderSurface, samplesPerHalf = 96): Float64Array {
  const n = Math.max(8, Math.round(samplesPerHalf));
  const c = cylinderSolver(tool, surface);
  const lim = c.limits();
  const out: number[] = [];
  const flankPoints = (flank: Flank) => {
    const wTop = c.reach(flank, flank === 'right' ? lim.topRightMm : lim.topLeftMm);
    const pts: Array<[number, number]> = [];
    for (let i = 0; i <= n; i++) {
      // Denser near the contact, where scallops form.
      const u = i / n;
      const w = wTop * u * u;
      pts.push([w, Math.max(0, c.heightAt(flank, w))]);
    }
    return pts;
  };
  const left = flankPoints('left');
  const right = flankPoints('right');
  for (let i = left.length - 1; i >= 1; i--)
    out.push(-(left[i] as [number, number])[0], (left[i] as [number, number])[1]);
  for (const [w, h] of right) out.push(w, h);
  return Float64Array.from(out);
}
