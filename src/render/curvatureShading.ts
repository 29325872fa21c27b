/**
 * Colours of a design surface patch that say its shape at a glance (pure: no DOM, no three.js; tested
 * in Node). Each vertex is coloured by its height above the CC point's tangent plane: where the
 * surface falls away from it (convex, as a dome does in every direction) blue, where it rises
 * (concave, a bowl) orange, in bands of equal height (iso-height terraces: rings on a dome or a bowl,
 * a cross of hyperbolas on a saddle), and lightened or darkened by a fixed light on the patch's
 * normal so that its relief reads too. A flat patch (a plane) is left white: the material's own
 * colour, as before.
 */

/** The colour of a surface falling away from the tangent plane (convex) and rising from it (concave), 0-1 RGB. */
export const FALLING_RGB: readonly [number, number, number] = [0.2, 0.42, 0.95];
export const RISING_RGB: readonly [number, number, number] = [1, 0.5, 0.08];

/** Iso-height bands from the tangent plane to the patch's farthest height. */
export const SHADING_BANDS = 5;

/**
 * Writes an RGB colour per vertex of a grid patch (flat xyz `positions`, `rows` x `columns`
 * vertices, row-major, heights along z above the tangent plane at z = 0) into `out` (at least as
 * long as `positions`). Heights within `flatMm` of the plane everywhere: all white.
 * @returns the largest |height| on the patch (mm)
 */
export function curvatureColoursInto(
  out: { [index: number]: number },
  positions: ArrayLike<number>,
  rows: number,
  columns: number,
  flatMm: number,
): number {
  const n = rows * columns;
  // The farthest height on each side of the tangent plane: each side's bands span its own range.
  let below = 0;
  let above = 0;
  for (let i = 0; i < n; i++) {
    const z = positions[3 * i + 2] as number;
    if (z < below) below = z;
    if (z > above) above = z;
  }
  const most = Math.max(-below, above);
  if (!(most > flatMm)) {
    for (let i = 0; i < 3 * n; i++) out[i] = 1;
    return most;
  }
  const at = (r: number, c: number, k: number) =>
    positions[3 * (Math.min(rows - 1, Math.max(0, r)) * columns + Math.min(columns - 1, Math.max(0, c))) + k] as number;
  for (let r = 0; r < rows; r++)
    for (let c = 0; c < columns; c++) {
      const i = r * columns + c;
      const z = positions[3 * i + 2] as number;
      const falling = z < 0;
      // Terraces: the band's index, pale near the tangent plane, full farther from it; every other band darker (iso-lines).
      // (A side with no extent, as a cylinder's on its tangent line, is the first band: never 0 / 0.)
      const range = falling ? -below : above;
      const band = range > 0 ? Math.min(SHADING_BANDS - 1, Math.floor((SHADING_BANDS * Math.abs(z)) / range)) : 0;
      const level = (band + 1) / SHADING_BANDS;
      const hue = falling ? FALLING_RGB : RISING_RGB;
      // The normal from the grid's neighbours (central differences) against a light from above and the side.
      const ux = at(r + 1, c, 0) - at(r - 1, c, 0);
      const uy = at(r + 1, c, 1) - at(r - 1, c, 1);
      const uz = at(r + 1, c, 2) - at(r - 1, c, 2);
      const vx = at(r, c + 1, 0) - at(r, c - 1, 0);
      const vy = at(r, c + 1, 1) - at(r, c - 1, 1);
      const vz = at(r, c + 1, 2) - at(r, c - 1, 2);
      const nx = uy * vz - uz * vy;
      const ny = uz * vx - ux * vz;
      const nz = ux * vy - uy * vx;
      const len = Math.hypot(nx, ny, nz) || 1;
      const light = Math.abs(0.36 * nx - 0.48 * ny + 0.8 * nz) / len;
      const shade = (0.75 + 0.25 * light) * (band % 2 === 1 ? 0.84 : 1);
      // White mixed towards the hue by the band's level.
      for (let k = 0; k < 3; k++) out[3 * i + k] = shade * (1 - level * (1 - (hue[k] as number)));
    }
  return most;
}
