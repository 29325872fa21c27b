/**
 * Surface of the filleted end mill in its posture as a triangle mesh of fixed topology: flat
 * bottom disk (radius Rb), torus corner (lower outer quarter, radius Rcr) and shank cylinder
 * (radius R), revolved about the tool axis. Frame and placement as in placement.ts (contact at
 * the origin, designed plane z = 0). Pure: plain typed arrays, mm.
 */

import type { ToolInput } from '../domain/tool';
import { placeTool } from './placement';

/** Points along the revolved profile: bottom centre, corner arc, shank top. */
const CORNER_STEPS = 16;
export const TOOL_PROFILE_POINTS = CORNER_STEPS + 3;

export interface ToolMesh {
  /** x, y, z per vertex, mm. */
  readonly positions: Float32Array;
  /** Triangle vertex indices; depends only on `radialSegments`. */
  readonly indices: Uint32Array;
}

/**
 * @param tool validated tool and posture; @param shankLengthMm length of the drawn shank above
 * the corner's top, mm (> 0); @param radialSegments segments around the axis (>= 8).
 */
export function toolMesh(tool: ToolInput, shankLengthMm: number, radialSegments = 64): ToolMesh {
  const p = placeTool(tool);
  const toolRadiusMm = tool.toolRadiusMm;
  const cornerRadiusMm = tool.cornerRadiusMm;
  const rb = p.ringRadiusMm;
  const [ox, oy, oz] = p.centre;
  const [ax, ay, az] = p.axis;
  const profile: Array<[number, number]> = [[0, -cornerRadiusMm]];
  for (let k = 0; k <= CORNER_STEPS; k++) {
    const phi = -Math.PI / 2 + (Math.PI / 2) * (k / CORNER_STEPS);
    profile.push([rb + cornerRadiusMm * Math.cos(phi), cornerRadiusMm * Math.sin(phi)]);
  }
  profile.push([toolRadiusMm, shankLengthMm]);
  const segs = Math.max(8, Math.round(radialSegments));
  const positions = new Float32Array(profile.length * (segs + 1) * 3);
  let w = 0;
  for (const [r, axial] of profile) {
    for (let j = 0; j <= segs; j++) {
      const alpha = (2 * Math.PI * j) / segs;
      const c = r * Math.cos(alpha);
      const s = r * Math.sin(alpha);
      positions[w++] = ox + c * p.v2[0] + s * p.v1[0] + axial * ax;
      positions[w++] = oy + c * p.v2[1] + s * p.v1[1] + axial * ay;
      positions[w++] = oz + c * p.v2[2] + s * p.v1[2] + axial * az;
    }
  }
  return { positions, indices: toolMeshIndices(segs) };
}

/** Triangle indices of {@link toolMesh} for a given number of radial segments. */
export function toolMeshIndices(radialSegments: number): Uint32Array {
  const segs = Math.max(8, Math.round(radialSegments));
  const rows = TOOL_PROFILE_POINTS;
  const out = new Uint32Array((rows - 1) * segs * 6);
  let w = 0;
  for (let i = 0; i < rows - 1; i++) {
    for (let j = 0; j < segs; j++) {
      const a = i * (segs + 1) + j;
      const b = a + segs + 1;
      out[w++] = a;
      out[w++] = b;
      out[w++] = a + 1;
      out[w++] = b;
      out[w++] = b + 1;
      out[w++] = a + 1;
    }
  }
  return out;
}
