/**
 * A three-axis lookup table (issue 28 point 2): the programmed step (Lxy for raster passes, dz for
 * waterline) of one upright tool and one strategy (passes, raster angle; on a surface of revolution
 * its two radii) over a grid of slopes x scallop heights, as CSV in the command line's batch layout
 * for three-axis rows: the input columns R, Rcr, h, slope, passes, rasterAngle (and feedRadius,
 * crossRadius on a surface of revolution), then interval (L along the surface), horizontalStep,
 * stepDown, lead, tilt, note, error. Fed back to `--batch`, each row is answered again with the same
 * numbers. A cell outside the valid domain keeps its inputs, leaves the results empty and gives the
 * reason in `error`, worded in the file's unit as the batch words it. Pure; mm and degrees (lookupUnits.ts converts the file).
 */
import { csvColumnOf } from '../input/fields';
import { fromMm, type LengthUnit, toMm } from '../input/units';
import { scallopHeightLimits } from '../surfaces/validate';
import { threeAxisMessageInUnit } from '../threeAxis/errors';
import type { ThreeAxisPasses } from '../threeAxis/slopedPlane';
import { slopePosture } from '../threeAxis/slopePosture';
import { solveThreeAxis } from '../threeAxis/solve';
import { type RawThreeAxisInput, validateThreeAxis } from '../threeAxis/validate';
import { csvNumber, csvText } from './csvWrite';
import { type LookupTable, series125 } from './lookupTable';

/** The tool and strategy of a three-axis table (mm, degrees). */
export interface ThreeAxisLookupCase {
  readonly toolRadiusMm: number;
  readonly cornerRadiusMm: number;
  readonly passes: ThreeAxisPasses;
  /** Raster passes: psi in plan from the fall line, degrees; null for waterline. */
  readonly rasterAngleDeg: number | null;
  /** Waterline on a surface of revolution: its signed radii, mm (null: straight); both null on a plane. */
  readonly revolution: { readonly feedRadiusMm: number | null; readonly crossRadiusMm: number | null } | null;
}

/** The grid: slopes (degrees) and scallop heights (mm), each ascending. */
export interface ThreeAxisLookupGrid {
  readonly slopesDeg: readonly number[];
  readonly scallopHeightsMm: readonly number[];
}

/** Slopes of the grid: 0 to 85 degrees in steps of 5 (waterline from 5: a flat floor has no levels). */
export function threeAxisLookupSlopesDeg(passes: ThreeAxisPasses): number[] {
  return Array.from({ length: 18 }, (_, i) => 5 * i).filter((s) => passes === 'raster' || s > 0);
}

/** The smallest scallop height of the grid, as a fraction of the tool radius (then rounded down to 1-2-5). */
const SMALLEST_H_PER_R = 1e-4;

/**
 * The grid for a case: the slopes of threeAxisLookupSlopesDeg, the scallop heights on the 1-2-5
 * series in `unit` from about 1e-4 R up to the largest height limit over the slopes' postures on
 * the plane (capped at R; a surface of revolution's own limits refuse cells above theirs).
 */
export function threeAxisLookupGrid(c: ThreeAxisLookupCase, unit: LengthUnit = 'mm'): ThreeAxisLookupGrid {
  const slopesDeg = threeAxisLookupSlopesDeg(c.passes);
  let limit = 0;
  for (const slope of slopesDeg) {
    const p = slopePosture(slope, c.passes === 'waterline' ? 90 : (c.rasterAngleDeg ?? 0));
    const tool = { toolRadiusMm: c.toolRadiusMm, cornerRadiusMm: c.cornerRadiusMm };
    const l = scallopHeightLimits({ ...tool, leadAngleDeg: p.leadDeg, tiltAngleDeg: p.tiltDeg }).limitMm;
    if (Number.isFinite(l)) limit = Math.max(limit, l);
  }
  const top = Math.min(c.toolRadiusMm, limit > 0 ? limit : c.toolRadiusMm);
  const heights = series125(fromMm(SMALLEST_H_PER_R * c.toolRadiusMm, unit), fromMm(top, unit));
  return { slopesDeg, scallopHeightsMm: heights.map((h) => toMm(h, unit)) };
}

/** The input columns of a case's table, in the batch's echo order. */
function inputColumns(c: ThreeAxisLookupCase): string[] {
  const base = [csvColumnOf('R'), csvColumnOf('Rcr'), csvColumnOf('h'), csvColumnOf('slope')];
  const strategy = [csvColumnOf('passes'), csvColumnOf('rasterAngle')];
  const radii = c.revolution === null ? [] : [csvColumnOf('feedRadius'), csvColumnOf('crossRadius')];
  return [...base, ...strategy, ...radii];
}

/** The result columns of three-axis rows (the batch's). */
export const THREE_AXIS_LOOKUP_RESULTS = ['interval', 'horizontalStep', 'stepDown', 'lead', 'tilt', 'note', 'error'];

/** The programmed step of each grid cell and the batch's other three-axis results (see the module comment). */
export function threeAxisLookupTable(
  c: ThreeAxisLookupCase,
  grid: ThreeAxisLookupGrid,
  unit: LengthUnit = 'mm',
): LookupTable {
  const lines = [[...inputColumns(c), ...THREE_AXIS_LOOKUP_RESULTS].join(',')];
  let empty = 0;
  const n = (v: number | null) => (v === null ? '' : csvNumber(v));
  for (const slope of grid.slopesDeg)
    for (const h of grid.scallopHeightsMm) {
      const raw: RawThreeAxisInput = {
        R: c.toolRadiusMm,
        Rcr: c.cornerRadiusMm,
        slope,
        passes: c.passes,
        rasterAngle: c.rasterAngleDeg ?? undefined,
        feedRadius: c.revolution?.feedRadiusMm ?? undefined,
        crossRadius: c.revolution?.crossRadiusMm ?? undefined,
      };
      const radii = c.revolution === null ? [] : [n(c.revolution.feedRadiusMm), n(c.revolution.crossRadiusMm)];
      const echo = [n(c.toolRadiusMm), n(c.cornerRadiusMm), n(h), n(slope), c.passes, n(c.rasterAngleDeg), ...radii];
      const v = validateThreeAxis(raw, 'h', h);
      const r = v.ok ? solveThreeAxis(v.value) : v;
      if (!r.ok) {
        empty++;
        // Worded as the batch words the row read back from the file in `unit` (the h as written there).
        const typedH = csvNumber(Number(fromMm(h, unit).toPrecision(12)));
        const reason = r.errors
          .map((e) => threeAxisMessageInUnit(e, c.passes, unit, e.field === 'h' ? typedH : String(e.got)))
          .join(' ');
        lines.push([...echo, '', '', '', '', '', '', csvText(reason)].join(','));
        continue;
      }
      const a = r.value;
      const note = a.noScallop ? 'no scallop: a flat end on a flat floor, L = 2R for any h' : '';
      lines.push(
        [
          ...echo,
          n(a.intervalMm),
          n(a.horizontalStepMm),
          n(a.stepDownMm),
          n(a.leadDeg),
          n(a.tiltDeg),
          csvText(note),
          '',
        ].join(','),
      );
    }
  return { csv: `${lines.join('\n')}\n`, rows: lines.length - 1, emptyCells: empty };
}
