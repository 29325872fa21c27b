/**
 * The lookup table of a doubly curved point (issue 19, "Page": the lookup table's columns): the
 * exact step-over of one tool, pass pattern and pair of principal radii over the grid of scallop
 * heights x lead angles x tilts, as CSV in the batch's layout with the surface given by its two
 * signed radii (`feedRadius`, `crossRadius`, mm) in place of `surfaceRadius` and `surfaceAxis`.
 * The exact answer is the registry's model's (core surfaces/doublyCurvedPoint.ts). The result
 * columns are the batch's: `exact` (L/2), `interval` (L, arc length across the feed),
 * the flank reaches, the contact offset and zigzag's other cusp; the plane procedures' columns stay
 * empty (they ignore the curvature: the page's comparison rows say by how much). A cell whose
 * posture gouges the point, or whose h is at or above that posture's limit, keeps its inputs and
 * gives its reason in `error`. Mm and degrees.
 */

import { CSV_REQUIRED_COLUMNS, csvColumnOf } from '../../core/input/fields';
import { formatSignificant, fromMm, type LengthUnit, unitSymbol } from '../../core/input/units';
import type { PassPattern } from '../../core/input/validate';
import { csvNumber, csvText, RESULT_COLUMNS } from '../../core/output/csvWrite';
import type { LookupGrid, LookupTable } from '../../core/output/lookupTable';
import {
  curvedRadiusInRange,
  doublyCurvedGouges,
  MAX_PRINCIPAL_RADIUS_MM,
  MIN_PRINCIPAL_RADIUS_MM,
  type PrincipalRadii,
} from '../../core/surfaces/doublyCurved';
import { curvedForward, curvedLimits, curvedPoint } from '../../core/surfaces/doublyCurvedPoint';

/** The input columns: R, Rcr, rho, h, tilt, pattern, then the two radii. */
export const CURVED_INPUT_COLUMNS = [
  ...CSV_REQUIRED_COLUMNS,
  csvColumnOf('h'),
  csvColumnOf('tilt'),
  csvColumnOf('pattern'),
  csvColumnOf('feedRadius'),
  csvColumnOf('crossRadius'),
] as const;

/** The header of a doubly curved table. */
export const CURVED_LOOKUP_HEADER = [...CURVED_INPUT_COLUMNS, ...RESULT_COLUMNS].join(',');

/** Why these radii cannot be tabulated (a straight one is a cylinder's table), or null. */
export function badRadii(radii: PrincipalRadii): string | null {
  if (curvedRadiusInRange(radii.feedRadiusMm) && curvedRadiusInRange(radii.crossRadiusMm)) return null;
  return `both radii of a doubly curved point must be from ${MIN_PRINCIPAL_RADIUS_MM} mm to ${MAX_PRINCIPAL_RADIUS_MM} mm in size (got ${radii.feedRadiusMm} and ${radii.crossRadiusMm}).`;
}

const mm = (v: number) => formatSignificant(v, { digits: 8, trimZeros: true, exponentBelow: 1e-5 });

/**
 * The table of a validated tool (R, Rcr mm), pattern and pair of curved radii over a grid; a
 * refused cell's reason worded in `unit` (the numbers stay mm: lookupUnits.ts converts the file).
 */
export function curvedLookupTable(
  tool: { readonly toolRadiusMm: number; readonly cornerRadiusMm: number },
  pattern: PassPattern,
  radii: PrincipalRadii,
  grid: LookupGrid,
  unit: LengthUnit = 'mm',
): LookupTable {
  const lines = [CURVED_LOOKUP_HEADER];
  let empty = 0;
  const emptyResults = ','.repeat(RESULT_COLUMNS.length - 1);
  for (const tilt of grid.tiltAnglesDeg)
    for (const rho of grid.leadAnglesDeg) {
      const posture = { ...tool, leadAngleDeg: rho, tiltAngleDeg: tilt };
      const gouges = doublyCurvedGouges(posture, radii);
      const point = gouges ? null : curvedPoint(posture, radii, pattern);
      const limitMm = point === null ? 0 : curvedLimits(point).limitMm;
      for (const h of grid.scallopHeightsMm) {
        const echo = [tool.toolRadiusMm, tool.cornerRadiusMm, rho, h, tilt]
          .map(csvNumber)
          .concat([pattern, csvNumber(radii.feedRadiusMm), csvNumber(radii.crossRadiusMm)])
          .join(',');
        let reason: string | null = null;
        if (point === null)
          reason =
            'The tool gouges this doubly curved point at this posture: the swept tool reaches inside the surface away from the contact.';
        else if (!(h < limitMm))
          reason = `Scallop height h must be below ${mm(fromMm(Math.max(0, limitMm), unit))} ${unitSymbol(unit)} at this point and posture (got ${csvNumber(Number(fromMm(h, unit).toPrecision(12)))}).`;
        if (reason !== null || point === null) {
          empty++;
          lines.push(`${echo},${emptyResults}${csvText(reason ?? '')}`);
          continue;
        }
        const e = curvedForward(point, h);
        const cells: Record<(typeof RESULT_COLUMNS)[number], string> = {
          exact: csvNumber(e.intervalMm / 2),
          sekine: '',
          redonnet: '',
          bedi: '',
          interval: csvNumber(e.intervalMm),
          halfWidthRight: csvNumber(e.halfWidthRightMm),
          halfWidthLeft: csvNumber(e.halfWidthLeftMm),
          contactOffset: csvNumber(e.contactOffsetMm),
          otherCuspHeight: e.otherCuspHeightMm === null ? '' : csvNumber(e.otherCuspHeightMm),
          osculating: '',
          cornerBall: '',
          note: '',
          error: '',
        };
        lines.push(`${echo},${RESULT_COLUMNS.map((c) => cells[c]).join(',')}`);
      }
    }
  return { csv: `${lines.join('\n')}\n`, rows: lines.length - 1, emptyCells: empty };
}
