/**
 * Colours of a design surface patch that say its shape at a glance (pure: no DOM, no three.js; tested
 * in Node). Each vertex is coloured by its height above the CC point's tangent plane: where the
 * surface falls away from it (convex, as a dome does in every direction) blue, where it rises
 * (concave, a bowl) orange, in bands of equal height (iso-height terraces: rings on a dome or a bowl,
 * a cross of hyperbolas on a saddle), and lightened or darkened by a fixed light on the patch's
 * normal so that its relief reads too. A flat patch (a plane) is left white: the material's own
 * colour, as before.
 *
 * The bands are drawn from a strip of colours ({@link bandStripRgba}, read per pixel at its nearest
 * entry by bandMaterial.ts) at a coordinate interpolated across each triangle ({@link curvatureBandsInto}): their
 * edges follow the iso-height lines inside the triangles, not the grid's cells (a colour per vertex
 * drew them as stairs).
 */

/** The colour of a surface falling away from the tangent plane (convex) and rising from it (concave), 0-1 RGB. */
export const FALLING_RGB: readonly [number, number, number] = [0.2, 0.42, 0.95];
export const RISING_RGB: readonly [number, number, number] = [1, 0.5, 0.08];

/** Iso-height bands from the tangent plane to the patch's farthest height. */
export const SHADING_BANDS = 5;

/** Texels of the band strip: the falling bands (farthest first), then the rising ones (nearest first). */
export const BAND_TEXELS = 2 * SHADING_BANDS;

/** A band's colour (0-1 RGB) into `out` at `at`: white mixed towards the hue by the band's level, every other band darker. */
export function bandColourInto(out: { [index: number]: number }, at: number, falling: boolean, band: number): void {
  const level = (band + 1) / SHADING_BANDS;
  const hue = falling ? FALLING_RGB : RISING_RGB;
  const dim = band % 2 === 1 ? 0.84 : 1;
  for (let k = 0; k < 3; k++) out[at + k] = dim * (1 - level * (1 - (hue[k] as number)));
}

/** The band strip, {@link BAND_TEXELS} texels of RGBA bytes (texel t: falling band B-1-t, then rising band t-B). */
export function bandStripRgba(): Uint8Array {
  const rgb = new Float32Array(3);
  const out = new Uint8Array(4 * BAND_TEXELS);
  for (let t = 0; t < BAND_TEXELS; t++) {
    const falling = t < SHADING_BANDS;
    bandColourInto(rgb, 0, falling, falling ? SHADING_BANDS - 1 - t : t - SHADING_BANDS);
    for (let k = 0; k < 3; k++) out[4 * t + k] = Math.round(255 * (rgb[k] as number));
    out[4 * t + 3] = 255;
  }
  return out;
}

/**
 * Writes, per vertex of a grid patch (flat xyz `positions`, `rows` x `columns` vertices, row-major,
 * heights along z above the tangent plane at z = 0), its coordinate along the band strip (`uv`: u in
 * [0, 1], 0.5 on the tangent plane, 0 the farthest fall, 1 the highest rise; v 0.5) and its shade
 * (`shade`: the light on its normal, grey RGB). Heights within `flatMm` of the plane everywhere: u
 * 0.5 and shade 1 (the caller draws a flat patch white).
 * @returns the largest |height| on the patch (mm)
 */
export function curvatureBandsInto(
  uv: { [index: number]: number },
  shade: { [index: number]: number },
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
    for (let i = 0; i < n; i++) {
      uv[2 * i] = 0.5;
      uv[2 * i + 1] = 0.5;
      shade[3 * i] = shade[3 * i + 1] = shade[3 * i + 2] = 1;
    }
    return most;
  }
  const at = (r: number, c: number, k: number) =>
    positions[3 * (Math.min(rows - 1, Math.max(0, r)) * columns + Math.min(columns - 1, Math.max(0, c))) + k] as number;
  for (let r = 0; r < rows; r++)
    for (let c = 0; c < columns; c++) {
      const i = r * columns + c;
      const z = positions[3 * i + 2] as number;
      // Along the strip: each side's own range (a side with no extent, as a cylinder's on its
      // tangent line, stays at the tangent plane: never 0 / 0).
      const range = z < 0 ? -below : above;
      const t = range > 0 ? Math.min(1, Math.abs(z) / range) : 0;
      uv[2 * i] = z < 0 ? 0.5 - 0.5 * t : 0.5 + 0.5 * t;
      uv[2 * i + 1] = 0.5;
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
      shade[3 * i] = shade[3 * i + 1] = shade[3 * i + 2] = 0.75 + 0.25 * light;
    }
  return most;
}
