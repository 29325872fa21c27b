/**
 * What the teaching views say over a doubly curved point (issue 28 leftovers): the Profile (its
 * section across the feed) and the chart (L against each radius) draw it; the others solve a plane
 * or a cylinder only, and say so neutrally, with where the point's answer is, instead of a warning.
 * Pure (no DOM).
 */
import type { FIELDS } from '../../core/input/fields';

/** A view's id (common.ts ViewId; not imported from there: this module is pure, tested without a DOM). */
type ViewId = Exclude<(typeof FIELDS.view.values)[number], 'result'>;

/** What each view that does not draw a doubly curved point works on. */
const WORKS_ON: Readonly<Partial<Record<ViewId, string>>> = {
  tables: "The paper's tables hold its own conditions, on a plane",
  stepper: "The paper's procedure, step by step, solves a plane or a cylinder",
  formulas: "The paper's formulas take a plane or a cylinder",
  surface: 'The machined-surface simulation runs on a plane or a cylinder',
};

/**
 * The neutral line over a view for a doubly curved point: null for a view that draws it (the
 * Profile, the chart), else what the view works on and where the point is answered.
 */
export function curvedViewNote(view: ViewId): string | null {
  const works = WORKS_ON[view];
  if (works === undefined) return null;
  return `${works}. This doubly curved point is answered by the results above, the Profile (its section across the feed) and the L against each radius chart.`;
}
