/**
 * The shop sheet's words and files (issue 21), pure (no DOM): the case of the question on screen,
 * the scallop heights the user lists, the title lines (tool, posture, pattern, surface, unit), the
 * cells as printed, and the CSV and its file name (the unit named in the header and the name).
 * The numbers are the core's (core/output/shopSheet.ts); lengths are shown in the user's unit at
 * the page's resolution (format.ts), the CSV keeps full precision.
 */
import { quotedEntry } from '../core/input/entryMessages';
import { formatInputNumber, formatSignificant, fromMm, type LengthUnit, toMm, unitSymbol } from '../core/input/units';
import { csvNumber } from '../core/output/csvWrite';
import {
  passesOf,
  SHEET_MARKS,
  type SheetCase,
  type SheetCell,
  type SheetMark,
  type ShopSheet,
} from '../core/output/shopSheet';
import { isCurvedRequest, type PageRequest } from '../worker/pageProtocol';
import { formatDeg, formatLen } from './format';
import type { SheetSurface, SheetWords } from './i18n/catalogue';
import { EN_SHEET } from './shopSheetWords';

/** At most this many scallop heights (rows): the sheet fits one printed page. */
export const MAX_SHEET_ROWS = 12;

/** The sheet's case for the question on screen (its tool, posture, pattern and surface; not its h). */
export function sheetCaseOf(request: PageRequest): SheetCase {
  if (request.mode === 'three-axis') return { kind: 'three-axis', problem: request.input };
  const i = request.input;
  const tool = {
    toolRadiusMm: i.toolRadiusMm,
    cornerRadiusMm: i.cornerRadiusMm,
    tiltAngleDeg: i.tiltAngleDeg,
    pattern: i.pattern,
  };
  if (isCurvedRequest(request))
    return {
      kind: 'doubly-curved',
      ...tool,
      radii: { feedRadiusMm: request.input.feedRadiusMm, crossRadiusMm: request.input.crossRadiusMm },
    };
  return { kind: 'five-axis', ...tool, surface: request.input.surface };
}

/**
 * The scallop height the question on screen gives (mm): the row the sheet adds for it (issue 28
 * point 10); null when the question gives a step-over or a target Ra instead.
 */
export function ownHeightMm(request: PageRequest): number | null {
  if (request.mode === 'three-axis') return request.input.quantity === 'h' ? request.input.mm : null;
  if (request.mode === 'forward' || request.mode === 'curved-forward') return request.input.scallopHeightMm;
  return null;
}

/**
 * The sheet's rows: the listed heights (in the user's unit) and the user's own `h` among them,
 * ascending, each once (compared at 12 significant digits); the own one's value in the unit, or null.
 */
export function sheetRows(
  listed: readonly number[],
  ownMm: number | null,
  unit: LengthUnit,
): { readonly values: number[]; readonly own: number | null } {
  const own = ownMm === null ? null : Number(fromMm(ownMm, unit).toPrecision(12));
  const values = [...new Set(own === null ? listed : [...listed, own])].sort((a, b) => a - b);
  return { values, own };
}

/** A number in the user's unit as a field shows it (up to 6 significant digits). */
function n(mm: number, unit: LengthUnit): string {
  return formatInputNumber(fromMm(mm, unit));
}

/** The heights list as the field shows it, in `unit` (space separated). */
export function heightsText(heights: readonly number[]): string {
  return heights.map((h) => formatInputNumber(h)).join(' ');
}

/**
 * The scallop heights the user lists (in `unit`, separated by spaces or semicolons; a decimal comma
 * reads as a point), in mm, ascending, each once; or a one-line message naming the rule.
 */
export function parseHeights(
  text: string,
  unit: LengthUnit,
  words: SheetWords = EN_SHEET,
): { readonly ok: true; readonly mm: number[] } | { readonly ok: false; readonly message: string } {
  const u = unitSymbol(unit);
  const message = (got: string | null) => ({ ok: false, message: words.heightsError(u, MAX_SHEET_ROWS, got) }) as const;
  const tokens = text.split(/[\s;]+/).filter((t) => t !== '');
  if (tokens.length === 0) return message(null);
  const values: number[] = [];
  for (const t of tokens) {
    const v = /^[+]?(\d+[.,]?\d*|[.,]\d+)([eE][+-]?\d+)?$/.test(t) ? Number(t.replace(',', '.')) : Number.NaN;
    if (!(Number.isFinite(v) && v > 0)) return message(`"${quotedEntry(t)}"`);
    values.push(v);
  }
  const unique = [...new Set(values)].sort((a, b) => a - b);
  if (unique.length > MAX_SHEET_ROWS) return message(String(unique.length));
  return { ok: true, mm: unique.map((v) => toMm(v, unit)) };
}

/** What a cell gives, as the title and the CSV name it: L, Lxy or dz. */
export function stepSymbol(sheet: ShopSheet): string {
  return sheet.step === 'interval' ? 'L' : sheet.step === 'horizontalStep' ? 'Lxy' : 'dz';
}

/** The surface of a case, for the words of its title line (lengths in the user's unit). */
function sheetSurface(c: SheetCase, unit: LengthUnit): SheetSurface {
  const len = (mm: number) => `${n(mm, unit)} ${unitSymbol(unit)}`;
  if (c.kind === 'doubly-curved')
    return { kind: 'doubly-curved', feed: len(c.radii.feedRadiusMm), cross: len(c.radii.crossRadiusMm) };
  if (c.kind === 'three-axis') {
    const p = c.problem;
    if (p.surface === 'plane') return { kind: 'sloped-plane' };
    const r = (mm: number | null) => (mm === null ? null : len(mm));
    return { kind: 'revolution', feed: r(p.case.feedRadiusMm), cross: r(p.case.crossRadiusMm) };
  }
  const s = c.surface;
  if (s.kind !== 'cylinder') return { kind: 'plane' };
  return { kind: 'cylinder', concave: s.radiusMm < 0, radius: len(Math.abs(s.radiusMm)), axis: s.axis };
}

/**
 * The title lines of a sheet: the tool (D and R, Rcr), the machining and posture, the pattern or
 * strategy and the surface, what the rows, columns and cells are and their unit, and `date`.
 */
export function sheetTitleLines(
  c: SheetCase,
  sheet: ShopSheet,
  unit: LengthUnit,
  date: string,
  words: SheetWords = EN_SHEET,
): string[] {
  const u = unitSymbol(unit);
  const len = (mm: number) => `${n(mm, unit)} ${u}`;
  const tool = c.kind === 'three-axis' ? c.problem.case : c;
  const surface = words.surface(sheetSurface(c, unit));
  let machining: string;
  if (c.kind === 'three-axis') {
    const p = c.problem;
    const passes = passesOf(p);
    const angle = passes === 'raster' && p.surface === 'plane' ? formatDeg(p.case.rasterAngleDeg) : null;
    machining = words.threeAxis(passes, angle, surface);
  } else {
    machining = words.fiveAxis(formatDeg(c.tiltAngleDeg), c.pattern, surface);
  }
  return [
    words.tool(len(2 * tool.toolRadiusMm), len(tool.toolRadiusMm), len(tool.cornerRadiusMm)),
    machining,
    words.axes(u, sheet.columnKind, sheet.step),
    words.made(date),
  ];
}

/** The no-scallop star, as the cells and the legend show it. */
export const NO_SCALLOP_STAR = '*';

/**
 * The significant digits of every inch cell: one count for the whole sheet, so that a column reads
 * alike from 0.0004266 to 0.4449 (at the page's fixed 10 µin resolution a step-down of 0.0004266
 * sat beside 0.01054 and 0.44489). 4 digits: 1 part in 1000 to 10000, far finer than a CAM step.
 */
export const INCH_CELL_DIGITS = 4;

/**
 * A cell as the sheet prints it, or its mark's letter: in mm the step at the page's resolution
 * (format.ts, 0.1 µm); in inch to {@link INCH_CELL_DIGITS} significant digits.
 */
export function cellText(cell: SheetCell, unit: LengthUnit): string {
  if (!cell.ok) return SHEET_MARKS[cell.mark].letter;
  const value =
    unit === 'in'
      ? formatSignificant(fromMm(cell.stepMm, unit), { digits: INCH_CELL_DIGITS, exponentBelow: 0 })
      : formatLen(cell.stepMm, unit);
  return `${value}${cell.noScallop ? NO_SCALLOP_STAR : ''}`;
}

/** The marks a sheet uses, in the legend's order (W, G, X), and whether a cell has no scallop. */
export function marksUsed(sheet: ShopSheet): { marks: SheetMark[]; noScallop: boolean } {
  const used = new Set<SheetMark>();
  let noScallop = false;
  for (const row of sheet.cells)
    for (const cell of row) {
      if (!cell.ok) used.add(cell.mark);
      else if (cell.noScallop) noScallop = true;
    }
  return { marks: (['wall', 'gouge', 'range'] as const).filter((m) => used.has(m)), noScallop };
}

/** The words a refused cell is written as in the CSV (no letter to look up). */
const CSV_MARK: Readonly<Record<SheetMark, string>> = {
  wall: 'wall: h at or above the limit',
  gouge: 'gouges',
  range: 'out of range',
};

/**
 * The sheet as CSV: a header naming every unit (`h_mm`, then `L_mm_lead_5_deg` or
 * `Lxy_in_slope_30_deg` per column), one row per scallop height; a cell is the step in `unit` in
 * full precision, or the words of its mark. Heights given in inches are written as given (12
 * significant digits).
 */
export function sheetCsv(sheet: ShopSheet, unit: LengthUnit): string {
  const u = unitSymbol(unit);
  const step = stepSymbol(sheet);
  const head = [`h_${u}`, ...sheet.columnsDeg.map((d) => `${step}_${u}_${sheet.columnKind}_${csvNumber(d)}_deg`)];
  const rows = sheet.scallopHeightsMm.map((h, i) => {
    const cells = (sheet.cells[i] ?? []).map((c) => (c.ok ? csvNumber(fromMm(c.stepMm, unit)) : CSV_MARK[c.mark]));
    return [csvNumber(Number(fromMm(h, unit).toPrecision(12))), ...cells].join(',');
  });
  return `${[head.join(','), ...rows].join('\n')}\n`;
}

/**
 * The CSV's file name: the tool, the pattern or strategy, the surface, the posture or raster angle
 * and the unit, lengths in the unit: `shop-sheet_R3_Rcr1_one-way_plane_tilt0_mm.csv`,
 * `shop-sheet_R0.25_Rcr0.0625_raster_psi30_plane_in.csv`.
 */
export function sheetFileName(c: SheetCase, unit: LengthUnit): string {
  const u = unitSymbol(unit);
  const tool = c.kind === 'three-axis' ? c.problem.case : c;
  const parts = [`R${n(tool.toolRadiusMm, unit)}`, `Rcr${n(tool.cornerRadiusMm, unit)}`];
  if (c.kind === 'three-axis') {
    const p = c.problem;
    if (p.surface === 'plane')
      parts.push(p.case.passes === 'raster' ? `raster_psi${formatDeg(p.case.rasterAngleDeg)}` : 'waterline', 'plane');
    else {
      const r = (mm: number | null) => (mm === null ? 'straight' : n(mm, unit));
      parts.push('waterline', `Rf${r(p.case.feedRadiusMm)}_Rc${r(p.case.crossRadiusMm)}`);
    }
  } else {
    const surface =
      c.kind === 'doubly-curved'
        ? `Rf${n(c.radii.feedRadiusMm, unit)}_Rc${n(c.radii.crossRadiusMm, unit)}`
        : c.surface.kind === 'cylinder'
          ? `Rs${n(c.surface.radiusMm, unit)}_${c.surface.axis}`
          : 'plane';
    parts.push(c.pattern, surface, `tilt${formatDeg(c.tiltAngleDeg)}`);
  }
  return `shop-sheet_${parts.join('_')}_${u}.csv`;
}
