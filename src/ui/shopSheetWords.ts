/**
 * The shop sheet's words in English (issue 30): the sheet as written, typed by the catalogues'
 * SheetWords so Japanese and German (i18n/jaSheet.ts, deSheet.ts) give every one of them. Loaded
 * with the sheet (its first click), not with the first result. The marks' legends are the core's.
 */
import { SHEET_MARKS } from '../core/output/shopSheet';
import type { SheetWords } from './i18n/catalogue';

/** What a cell gives, in words. */
const STEP_WORDS = {
  interval: 'step-over L between adjacent passes, along the surface',
  horizontalStep: 'horizontal step Lxy between adjacent raster passes, as programmed',
  stepDown: 'step-down dz between adjacent waterline levels, as programmed',
} as const;

/** The sheet's words in English. */
export const EN_SHEET: SheetWords = {
  title: (step, u) => `Shop sheet: ${step} (${u})`,
  tool: (d, r, rcr) => `Tool: D ${d} (R ${r}), corner radius Rcr ${rcr}`,
  fiveAxis: (tilt, pattern, surface) => `Five-axis, tilt ${tilt} deg; ${pattern} passes; on ${surface}`,
  threeAxis: (passes, angle, surface) =>
    `Three-axis, the tool upright; ${passes} passes${angle === null ? '' : ` at ${angle} deg from the fall line`}; on ${surface}`,
  surface: (s) => {
    if (s.kind === 'plane') return 'a plane';
    if (s.kind === 'sloped-plane') return 'a sloped plane';
    if (s.kind === 'cylinder')
      return `a ${s.concave ? 'concave' : 'convex'} cylinder, Rs ${s.radius}, axis ${s.axis === 'feed' ? 'along the feed' : 'across the feed'}`;
    if (s.kind === 'doubly-curved') return `a doubly curved point, Rf ${s.feed}, Rc ${s.cross} (negative: concave)`;
    return `a surface of revolution, Rf ${s.feed ?? 'straight'}, Rc ${s.cross ?? 'straight'} (negative: concave)`;
  },
  axes: (u, columns, step) =>
    `Rows: scallop height h (${u}). Columns: ${columns === 'lead' ? 'lead angle rho (deg)' : 'surface slope (deg)'}. Cells: ${STEP_WORDS[step]} (${u}).`,
  made: (date) => `Exact solution, path-interval calculator, ${date}.`,
  region: 'Step-over table',
  caption: (step, u, columns) => `${step} (${u}) by scallop height h (${u}, rows) and ${columns} (degrees, columns)`,
  column: { lead: 'lead', slope: 'slope' },
  deg: 'deg',
  yourH: ' (your h)',
  where: (h, columns, deg) => `h ${h}, ${columns} ${deg} deg`,
  markLabel: (letter, where) => `${letter} at ${where}: show the reason`,
  markReason: (letter, where) => `${letter} at ${where}: `,
  marks: {
    wall: `${SHEET_MARKS.wall.legend}.`,
    gouge: `${SHEET_MARKS.gouge.legend}.`,
    range: `${SHEET_MARKS.range.legend}.`,
  },
  noScallop: 'no scallop: a flat end lying flat cuts flat at any step-over up to 2R.',
  ownRow: (h) => `Bold row: your scallop height h = ${h}.`,
  hintHover: 'Hover or click a mark for its full reason; the calculator answers any single case.',
  hintTouch: 'Tap a mark for its full reason; the calculator answers any single case.',
  heightsLabel: (u, max) => `Scallop heights h (${u}), up to ${max}, separated by spaces (your h is added)`,
  heightsError: (u, max, got) =>
    `Scallop heights: give 1 to ${max} scallop heights above 0 ${u}, separated by spaces${got === null ? '' : ` (got ${got})`}.`,
  csv: 'Download CSV',
  print: 'Print',
  close: 'Close',
  saved: (name) => `Saved ${name}.`,
};
