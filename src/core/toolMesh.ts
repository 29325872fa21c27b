/**
 * Surface of the inclined filleted end mill as a triangle mesh of fixed topology: flat
 * bottom disk (radius Rb), torus corner (lower outer quarter, radius Rcr) and shank
 * cylinder (radius R), revolved about the tool axis. Frame and placement as in torus.ts
 * (designed plane z = 0, tool centre on the Z axis). Pure: plain typed arrays, mm.
 */
import { torusFrame } from './torus';

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
 * @param toolRadiusMm R > 0; @param cornerRadiusMm 0 <= Rcr <= R; @param leadAngleRad 0 <= rho < pi/2;
 * @param shankLengthMm length of the drawn shank above the corner's top, mm (> 0);
 * @param radialSegments segments around the axis (>= 8).
 */
export function toolMesh(
  toolRadiusMm: number,
  cornerRadiusMm: number,
  leadAngleRad: number,
  shankLengthMm: number,
  radialSegments = 64,
): ToolMesh {
  const f = torusFrame(toolRadiusMm, cornerRadiusMm, leadAngleRad);
  const rb = f.ringRadiusMm;
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
      positions[w++] = f.centre[0] + c * f.xt[0] + axial * f.zt[0];
      positions[w++] = f.centre[1] + s;
      positions[w++] = f.centre[2] + c * f.xt[2] + axial * f.zt[2];
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
