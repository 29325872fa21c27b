/**
 * The shop sheet (issue 21): for one tool, pattern and surface, the exact step-over over a matrix of
 * scallop heights (rows) by lead angles (columns; five-axis, at the tilt on screen) or surface slopes
 * (columns; three-axis, the step as programmed: the horizontal step Lxy of raster passes, the
 * step-down dz of waterline passes). Every cell is the core's own answer, validated as the page and
 * the command line validate it (validateForward and exactForward on a plane or a cylinder; the
 * doubly curved solver at a doubly curved point; solveThreeAxis in three-axis machining): no
 * maths of its own. A cell that cannot be answered keeps its reason as a mark ({@link SheetMark})
 * and the core's message, worded in the user's unit. Pure; mm and degrees inside.
 */

import type { Surface } from '../domain/surface';
import type { PassPattern } from '../domain/tool';
import { PASS_FIELDS } from '../input/fields';
import { describeInputError, type InputError } from '../input/inputErrors';
import { rawOf } from '../input/raw';
import { formatInputNumber, fromMm, type LengthUnit, unitSymbol } from '../input/units';
import {
  doublyCurvedGouges,
  doublyCurvedSolver,
  forwardWith,
  type PrincipalRadii,
} from '../surfaces/doublyCurved/index';
import { exactForward } from '../surfaces/solve';
import { validateForward } from '../surfaces/validate';
import { solveThreeAxis } from '../threeAxis/solve';
import type { ThreeAxisInputError, ThreeAxisProblem } from '../threeAxis/validate';

/**
 * Why a cell has no step-over:
 *  - `wall`: h at or above this posture's limit (a flank or the shank leaves a wall, not a scallop);
 *  - `gouge`: the tool gouges the surface at this posture;
 *  - `range`: the posture (lead, tilt) or slope is outside what this tool and strategy admit there.
 */
export type SheetMark = 'wall' | 'gouge' | 'range';

/** The letter of each mark on the sheet, and its legend (the CSV writes the words). */
export const SHEET_MARKS: Readonly<Record<SheetMark, { readonly letter: string; readonly legend: string }>> = {
  wall: {
    letter: 'W',
    legend: "h at or above this posture's limit: a flank or the shank leaves a wall, not a scallop",
  },
  gouge: { letter: 'G', legend: 'the tool gouges the surface at this posture' },
  range: { letter: 'X', legend: 'outside the range this tool admits here (lead, tilt or slope)' },
};

/** One cell: the step-over (mm), or why there is none. */
export type SheetCell =
  | {
      readonly ok: true;
      /** The step-over, mm: L (five-axis), Lxy (raster) or dz (waterline). */
      readonly stepMm: number;
      /** True for a flat end lying flat: no scallop at any step-over up to 2R (L = 2R). */
      readonly noScallop: boolean;
    }
  | { readonly ok: false; readonly mark: SheetMark; readonly reason: string; readonly refusal: SheetRefusal };

/**
 * What a refused cell's reason is made of, so that a page can word it in its own language: the
 * validation's errors (a plane or a cylinder), a three-axis solver's, or a doubly curved point's own
 * checks (the lead out of range, the tool gouging the point, h at or above the limit `limitMm`), or
 * waterline passes without a step-down.
 */
export type SheetRefusal =
  | { readonly kind: 'input'; readonly errors: readonly InputError[] }
  | { readonly kind: 'three-axis'; readonly errors: readonly ThreeAxisInputError[] }
  | { readonly kind: 'lead-range' }
  | { readonly kind: 'curved-gouge' }
  | { readonly kind: 'curved-wall'; readonly limitMm: number }
  | { readonly kind: 'no-step-down' };

/** What the sheet is for: a five-axis posture (columns: leads) or three-axis passes (columns: slopes). */
export type SheetCase =
  | {
      readonly kind: 'five-axis';
      readonly toolRadiusMm: number;
      readonly cornerRadiusMm: number;
      readonly tiltAngleDeg: number;
      readonly pattern: PassPattern;
      /** A plane or a cylinder. */
      readonly surface: Surface;
    }
  | {
      readonly kind: 'doubly-curved';
      readonly toolRadiusMm: number;
      readonly cornerRadiusMm: number;
      readonly tiltAngleDeg: number;
      readonly pattern: PassPattern;
      readonly radii: PrincipalRadii;
    }
  | {
      readonly kind: 'three-axis';
      /** The validated problem on screen: its tool, strategy and surface; its slope, quantity and value are the sheet's. */
      readonly problem: ThreeAxisProblem;
    };

/** The sheet: its rows (h, mm), its columns (lead or slope, degrees) and cells[row][column]. */
export interface ShopSheet {
  readonly scallopHeightsMm: readonly number[];
  /** What the columns are: lead angles (five-axis) or surface slopes (three-axis), degrees. */
  readonly columnKind: 'lead' | 'slope';
  readonly columnsDeg: readonly number[];
  /** What a cell gives: L (five-axis), Lxy (raster) or dz (waterline). */
  readonly step: 'interval' | 'horizontalStep' | 'stepDown';
  readonly cells: readonly (readonly SheetCell[])[];
}

/** Lead angles of the sheet's columns by default, degrees (0 <= rho < 90: all valid leads). */
export const SHEET_LEADS_DEG: readonly number[] = [0, 2, 5, 10, 15, 20, 30];

/** Slopes of a raster sheet's columns by default, degrees (a flat floor to steep walls). */
export const SHEET_RASTER_SLOPES_DEG: readonly number[] = [0, 10, 20, 30, 45, 60, 75];

/** Slopes of a waterline sheet's columns by default, degrees (waterline needs a slope: no 0). */
export const SHEET_WATERLINE_SLOPES_DEG: readonly number[] = [5, 10, 20, 30, 45, 60, 75];

/** Scallop heights of the rows by default, in the user's unit (mm: 1 um to 0.1 mm; in: 0.1 to 5 thou). */
export const SHEET_HEIGHTS: Readonly<Record<'mm' | 'in', readonly number[]>> = {
  mm: [0.001, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1],
  in: [0.0001, 0.0002, 0.0005, 0.001, 0.002, 0.005],
};

/** The passes of a three-axis problem (a surface of revolution is cut in waterline). */
export function passesOf(problem: ThreeAxisProblem): 'raster' | 'waterline' {
  return problem.surface === 'revolution' ? 'waterline' : problem.case.passes;
}

/** The default columns of a case: leads, or the slopes of its strategy. */
export function sheetColumnsDeg(c: SheetCase): readonly number[] {
  if (c.kind !== 'three-axis') return SHEET_LEADS_DEG;
  return passesOf(c.problem) === 'waterline' ? SHEET_WATERLINE_SLOPES_DEG : SHEET_RASTER_SLOPES_DEG;
}

/** The mark of an error code (the core's and the three-axis solvers'). */
export function markOfCode(code: string): SheetMark {
  if (code === 'gouging' || code === 'shank-gouging' || code === 'radius-gouging') return 'gouge';
  if (code === 'flank-wall' || code === 'shank-cuts' || code === 'too-large') return 'wall';
  return 'range';
}

/** A scallop height as the sheet's row gives it, in `unit` (for a reason's "got"). */
function heightText(hMm: number, unit: LengthUnit): string {
  return formatInputNumber(fromMm(hMm, unit));
}

/**
 * A solver's message (mm) in `unit`: every `<number> mm` converted, and the value quoted by
 * `(got ...)` replaced by `typed` when given. Angles stay in degrees.
 */
export function messageInUnit(message: string, unit: LengthUnit, typed?: string): string {
  const withTyped = typed === undefined ? message : message.replace(/\(got [^)]*\)/, `(got ${typed})`);
  if (unit === 'mm') return withTyped;
  return withTyped.replace(
    /(-?\d+(?:\.\d+)?(?:e[+-]?\d+)?) mm\b/gi,
    (_m, n: string) => `${formatInputNumber(fromMm(Number(n), unit))} ${unitSymbol(unit)}`,
  );
}

/** A plane's or a cylinder's cell: validated and solved as the batch does a record. */
function fiveAxisCell(
  c: Extract<SheetCase, { kind: 'five-axis' }>,
  leadDeg: number,
  hMm: number,
  unit: LengthUnit,
): SheetCell {
  const raw = { ...rawOf({ ...c, leadAngleDeg: leadDeg }, PASS_FIELDS), h: hMm };
  const v = validateForward(raw);
  if (!v.ok) {
    const first = v.errors[0];
    const typed = heightText(hMm, unit);
    const reason = v.errors.map((e) => describeInputError(e, unit, e.field === 'h' ? { typed } : {})).join(' ');
    return { ok: false, mark: markOfCode(first?.code ?? ''), reason, refusal: { kind: 'input', errors: v.errors } };
  }
  const e = exactForward(v.value);
  return { ok: true, stepMm: e.intervalMm, noScallop: e.noScallop };
}

/** A three-axis cell: the problem at this slope and h, solved forward; the step as programmed. */
function threeAxisCell(problem: ThreeAxisProblem, slopeDeg: number, hMm: number, unit: LengthUnit): SheetCell {
  const p = { ...problem, case: { ...problem.case, slopeDeg }, quantity: 'h', mm: hMm } as ThreeAxisProblem;
  const r = solveThreeAxis(p);
  if (!r.ok) {
    const first = r.errors[0];
    const typed = heightText(hMm, unit);
    const reason = r.errors.map((e) => messageInUnit(e.message, unit, e.field === 'h' ? typed : undefined)).join(' ');
    return {
      ok: false,
      mark: markOfCode(first?.code ?? ''),
      reason,
      refusal: { kind: 'three-axis', errors: r.errors },
    };
  }
  const a = r.value;
  const stepMm = a.passes === 'waterline' ? a.stepDownMm : a.horizontalStepMm;
  if (stepMm === null)
    return {
      ok: false,
      mark: 'range',
      reason: 'Waterline passes have no step-down here.',
      refusal: { kind: 'no-step-down' },
    };
  return { ok: true, stepMm, noScallop: a.noScallop };
}

/**
 * The sheet of a case over `scallopHeightsMm` (rows, mm, each > 0) and `columnsDeg` (leads, or
 * slopes in three-axis machining; degrees; default {@link sheetColumnsDeg}), the reasons worded in
 * `unit`. A doubly curved point's columns share one solver per lead (as its lookup table does).
 */
export function shopSheet(
  c: SheetCase,
  scallopHeightsMm: readonly number[],
  unit: LengthUnit = 'mm',
  columnsDeg: readonly number[] = sheetColumnsDeg(c),
): ShopSheet {
  const columns = columnsDeg.map((deg) => cellsOfColumn(c, deg, scallopHeightsMm, unit));
  const cells = scallopHeightsMm.map((_, row) => columns.map((column) => column[row] as SheetCell));
  const step =
    c.kind !== 'three-axis' ? 'interval' : passesOf(c.problem) === 'waterline' ? 'stepDown' : 'horizontalStep';
  return { scallopHeightsMm, columnKind: c.kind === 'three-axis' ? 'slope' : 'lead', columnsDeg, step, cells };
}

/** The cells of one column (a lead or a slope), top to bottom. */
function cellsOfColumn(c: SheetCase, deg: number, heightsMm: readonly number[], unit: LengthUnit): SheetCell[] {
  if (c.kind === 'five-axis') return heightsMm.map((h) => fiveAxisCell(c, deg, h, unit));
  if (c.kind === 'three-axis') return heightsMm.map((h) => threeAxisCell(c.problem, deg, h, unit));
  const posture = {
    toolRadiusMm: c.toolRadiusMm,
    cornerRadiusMm: c.cornerRadiusMm,
    leadAngleDeg: deg,
    tiltAngleDeg: c.tiltAngleDeg,
  };
  if (!(deg >= 0 && deg < 90))
    return heightsMm.map(() => ({
      ok: false,
      mark: 'range',
      reason: 'Lead angle rho must be at least 0 and below 90 degrees.',
      refusal: { kind: 'lead-range' },
    }));
  if (doublyCurvedGouges(posture, c.radii))
    return heightsMm.map(() => ({
      ok: false,
      mark: 'gouge',
      reason:
        'The tool gouges this doubly curved point at this posture: the swept tool reaches inside the surface away from the contact.',
      refusal: { kind: 'curved-gouge' },
    }));
  const solver = doublyCurvedSolver(posture, c.radii);
  const limitMm = solver.limits().limitMm;
  return heightsMm.map((h): SheetCell => {
    if (!(h < limitMm))
      return {
        ok: false,
        mark: 'wall',
        reason: `Scallop height h must be below ${formatInputNumber(fromMm(limitMm, unit))} ${unitSymbol(unit)} at this point and posture (got ${heightText(h, unit)}).`,
        refusal: { kind: 'curved-wall', limitMm },
      };
    return { ok: true, stepMm: forwardWith(solver, c.pattern, h).intervalMm, noScallop: false };
  });
}
