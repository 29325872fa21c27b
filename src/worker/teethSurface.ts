/**
 * The surface the teeth leave as the Machined surface view draws it in 3D (issue 29): the areal
 * map (core arealMap.ts, the notes' grid) over a whole number of period cells, enough to show
 * several feed marks and passes, a few hundred points a side at most, laid out as the view's
 * height fields are (rows along the feed, each row across it), with the exact lowest height and
 * Sz so that the colour ramp and its scale bar span exactly the finish's Sz. Pure. Lengths mm.
 */
import type { ArealParameters } from '../core/finish/areal';
import { arealMap } from '../core/finish/arealMap';
import type { ToothModel } from '../core/finish/toothModel';

/** Points along each side of the drawn map at most. */
export const TEETH_SURFACE_MAX_POINTS = 240;

/** The period cells of the drawn map and its points (along the feed, across it). */
export interface TeethSurfaceGrid {
  /** Feed periods along the feed and cross periods across it (whole numbers >= 1). */
  readonly feedPeriods: number;
  readonly crossPeriods: number;
  /** Points along the feed and across it (whole multiples of the periods). */
  readonly pointsAlong: number;
  readonly pointsAcross: number;
}

/**
 * The cells drawn: across, three periods of the passes (two with zigzag, whose period is two
 * passes); along, as many feed periods as make the map about as long as it is wide, from 3 to 12
 * (so each mark keeps at least 20 points); points a whole number per cell, at most `maxPoints` a side.
 */
export function teethSurfaceGrid(
  feedPeriodMm: number,
  crossPeriodMm: number,
  zigzag: boolean,
  maxPoints = TEETH_SURFACE_MAX_POINTS,
): TeethSurfaceGrid {
  const crossPeriods = zigzag ? 2 : 3;
  const wide = (crossPeriods * crossPeriodMm) / feedPeriodMm;
  const feedPeriods = Math.min(12, Math.max(3, Number.isFinite(wide) ? Math.round(wide) : 3));
  return {
    feedPeriods,
    crossPeriods,
    pointsAlong: feedPeriods * Math.floor(maxPoints / feedPeriods),
    pointsAcross: crossPeriods * Math.floor(maxPoints / crossPeriods),
  };
}

/** The drawn map: a height field as the view draws it, with its cells and exact range. */
export interface TeethSurface {
  /** Points across the feed (one row) and rows along it. */
  readonly cellsAcross: number;
  readonly cellsAlong: number;
  /** The first and last row's x span and the rows' y span (sample centres, mm). */
  readonly alongLengthMm: number;
  readonly acrossFromMm: number;
  readonly acrossToMm: number;
  /** Heights above the design plane (mm): row-major, `cellsAlong` rows of `cellsAcross`. */
  readonly heightsMm: Float32Array;
  readonly feedPeriods: number;
  readonly crossPeriods: number;
  /** The surface's exact lowest height (mean - Sv) and Sz (highest peak to deepest valley), mm. */
  readonly lowestMm: number;
  readonly szMm: number;
  /** The question drawn: teeth z, feed per tooth fz and step-over L (mm). */
  readonly flutes: number;
  readonly feedPerToothMm: number;
  readonly intervalMm: number;
}

/**
 * The surface of tooth model `m` with its areal parameters `a`, on teethSurfaceGrid's cells: the
 * core's areal map, sample (i, j) at x = (i + 1/2) dx along the feed, y = (j + 1/2) dy across.
 */
export function teethSurface(m: ToothModel, a: ArealParameters): TeethSurface {
  const g = teethSurfaceGrid(m.feedPeriodMm, m.crossPeriodMm, m.input.pattern === 'zigzag');
  const map = arealMap(m, g.pointsAlong, g.pointsAcross, g.feedPeriods, g.crossPeriods);
  const heights = new Float32Array(map.nx * map.ny);
  for (let i = 0; i < map.nx; i++)
    for (let j = 0; j < map.ny; j++) heights[i * map.ny + j] = map.heightsMm[i + map.nx * j] as number;
  return {
    cellsAcross: map.ny,
    cellsAlong: map.nx,
    alongLengthMm: (map.nx - 1) * map.dxMm,
    acrossFromMm: map.dyMm / 2,
    acrossToMm: (map.ny - 0.5) * map.dyMm,
    heightsMm: heights,
    feedPeriods: g.feedPeriods,
    crossPeriods: g.crossPeriods,
    lowestMm: a.meanMm - a.svMm,
    szMm: a.szMm,
    flutes: m.input.finish.flutes,
    feedPerToothMm: m.input.finish.feedPerToothMm,
    intervalMm: m.input.intervalMm,
  };
}
