/**
 * Index pairs of the outlines drawn over the scene's own vertices (pure: no DOM, tested in Node):
 * the neighbouring passes' tools (over the tool mesh, core toolMesh.ts) and the surfaces' edges and
 * the h pseudo surface's grid (over a patch, drawables/designSurfaces.ts).
 */
import { TOOL_PROFILE_POINTS } from '../core/tool/toolMesh';

/** The surface patches' grid: segments along the feed and across it. */
export const PATCH_FEED = 48;
export const PATCH_CROSS = 64;

/**
 * Line segments (vertex index pairs) of the tool mesh's outline (toolMesh.ts: rows of
 * `segments + 1` vertices up the profile, row 1 the flat end's edge, the last but one the top of
 * the corner, the last the shank's top): those three rings and four lines up the side.
 */
export function toolOutlineIndices(segments: number): Uint32Array {
  const row = (r: number, j: number) => r * (segments + 1) + j;
  const last = TOOL_PROFILE_POINTS - 1;
  const out: number[] = [];
  for (const r of [1, last - 1, last]) for (let j = 0; j < segments; j++) out.push(row(r, j), row(r, j + 1));
  for (let q = 0; q < 4; q++) {
    const j = Math.round((q * segments) / 4);
    for (let r = 1; r < last; r++) out.push(row(r, j), row(r + 1, j));
  }
  return Uint32Array.from(out);
}

/**
 * Line segments (vertex index pairs) over a patch's grid (`PATCH_FEED + 1` rows of `PATCH_CROSS + 1`
 * vertices): its edge, and with `every` > 0 the grid lines every `every` rows and columns.
 */
export function patchLineIndices(every: number): Uint32Array {
  const at = (r: number, c: number) => r * (PATCH_CROSS + 1) + c;
  const out: number[] = [];
  const rows = new Set([0, PATCH_FEED]);
  const cols = new Set([0, PATCH_CROSS]);
  if (every > 0) {
    for (let r = every; r < PATCH_FEED; r += every) rows.add(r);
    for (let c = every; c < PATCH_CROSS; c += every) cols.add(c);
  }
  for (const r of rows) for (let c = 0; c < PATCH_CROSS; c++) out.push(at(r, c), at(r, c + 1));
  for (const c of cols) for (let r = 0; r < PATCH_FEED; r++) out.push(at(r, c), at(r + 1, c));
  return Uint32Array.from(out);
}
