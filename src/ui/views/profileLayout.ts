/**
 * The cross-feed profile's layout, pure (no DOM; tested in Node): the vertical exaggeration a
 * section allows, the stretch of surface shown, the band of heights drawn, the view's home box and
 * how tall the plot grows for an exaggerated drawing. Display coordinates are the SVG's: x across
 * the feed (mm), y down (mm, heights times the exaggeration k).
 */
import { EXAGGERATION_STEPS } from '../../core/output/drawingScale';

/** A box in display coordinates (the SVG's viewBox). */
export interface Box {
  readonly x: number;
  readonly y: number;
  readonly w: number;
  readonly h: number;
}

/** The plot's width, its height as the stylesheet sets it, and the most it may grow to (px). */
export interface PlotRoom {
  readonly widthPx: number;
  readonly baseHeightPx: number;
  readonly maxHeightPx: number;
}

/** What the layout depends on (mm). */
export interface ProfileLayoutInput {
  readonly toolRadiusMm: number;
  readonly intervalMm: number;
  /** The scallop height h (the highest cusp). */
  readonly cuspHeightMm: number;
  /** The higher of the two cusps drawn (zigzag: they differ). */
  readonly highestCuspMm: number;
  /** y0: the contact's offset from the tool centre across the feed. */
  readonly contactOffsetMm: number;
  /** The section's signed radius (sectionProfile.ts sectionRadiusMm; +infinity when straight). */
  readonly sectionRadiusMm: number;
  /** The exaggeration asked for (a step of EXAGGERATION_STEPS). */
  readonly wantedK: number;
  readonly room: PlotRoom;
}

export interface ProfileLayout {
  /** The vertical exaggeration drawn: the one asked for, or less where the section would fold. */
  readonly k: number;
  /** The highest height drawn above the surface (mm). */
  readonly topMm: number;
  /** The stretch of surface shown, as arc lengths across the feed from the contact (mm). */
  readonly fromMm: number;
  readonly toMm: number;
  /** The unit of the drawing's spacing (dimension lines, margins): 3 % of the stretch shown (mm). */
  readonly d: number;
}

/**
 * The largest exaggeration up to `wantedK` at which heights up to `bandMm` do not fold a concave
 * section over: drawn radially, they reach the axis of a trough of radius |Rs| when k h = |Rs|, so
 * k is kept to at most |Rs| / (2 h), down to the step below (1 at least). A straight or convex
 * section takes any k.
 */
export function foldFreeExaggeration(wantedK: number, sectionRadiusMm: number, bandMm: number): number {
  const kMax = sectionRadiusMm < 0 ? (0.5 * Math.abs(sectionRadiusMm)) / bandMm : Number.POSITIVE_INFINITY;
  if (wantedK <= kMax) return wantedK;
  return Math.max(1, ...EXAGGERATION_STEPS.filter((step) => step <= kMax));
}

/**
 * The layout of one drawing: three passes L apart and the tool centre, a margin of 0.2 R beyond
 * the outer contacts (an arc kept within 0.98 of half a turn of a curved section); heights up to
 * min(R, 4h), but an exaggerated band no taller than the plot's shape allows over the whole width
 * (else the drawing shrinks to a strip), while keeping the cusps with a margin.
 */
export function profileLayout(input: ProfileLayoutInput): ProfileLayout {
  const R = input.toolRadiusMm;
  const L = input.intervalMm;
  const y0 = input.contactOffsetMm;
  const band = Math.min(R, 4 * input.cuspHeightMm);
  const k = foldFreeExaggeration(input.wantedK, input.sectionRadiusMm, band);
  const limit = 0.98 * Math.PI * Math.abs(input.sectionRadiusMm);
  const fromMm = Math.max(-limit, Math.min(-L - 0.2 * R, -y0 - 0.1 * R));
  const toMm = Math.min(limit, Math.max(L + 0.2 * R, -y0 + 0.1 * R));
  const d = 0.03 * (toMm - fromMm);
  const { room } = input;
  const fits = ((room.maxHeightPx / room.widthPx) * (toMm - fromMm) - 6 * d) / k;
  const topMm = Math.max(Math.min(band, fits), Math.min(band, 1.5 * input.highestCuspMm));
  return { k, topMm, fromMm, toMm, d };
}

/**
 * The home box of a drawing whose points span [minX, maxX] x [minY, maxY] (display coordinates):
 * all of it, with `d` to spare above.
 */
export function homeBox(minX: number, maxX: number, minY: number, maxY: number, d: number): Box {
  return { x: minX, y: minY - d, w: maxX - minX, h: maxY - minY + d };
}

/**
 * The height the plot grows to (px) so that `home` fills its width at the box's aspect, up to the
 * room's limit; null (the stylesheet's height) when that is no taller or the plot is not laid out.
 */
export function grownHeightPx(room: PlotRoom, home: Box, laidOut: boolean): number | null {
  const wantedPx = (room.widthPx * home.h) / home.w;
  return wantedPx > room.baseHeightPx && laidOut ? Math.round(Math.min(wantedPx, room.maxHeightPx)) : null;
}
