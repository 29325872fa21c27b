/**
 * What the teaching views say over a doubly curved point (issue 28 leftovers): the Profile (its
 * section across the feed) and the chart (L against each radius) draw it; the others solve a plane
 * or a cylinder only, and say so neutrally, with where the point's answer is, instead of a warning.
 * Pure (no DOM).
 */
import type { FIELDS } from '../../core/input/fields';
import type { ViewNoteWords } from '../i18n/catalogue';
import { EN_VIEW_NOTES } from './viewNoteWords';

/** A view's id (common.ts ViewId; not imported from there: this module is pure, tested without a DOM). */
type ViewId = Exclude<(typeof FIELDS.view.values)[number], 'result'>;

/**
 * The neutral line over a view for a doubly curved point: null for a view that draws it (the
 * Profile, the chart), else what the view works on and where the point is answered (in `words`'
 * language).
 */
export function curvedViewNote(view: ViewId, words: ViewNoteWords = EN_VIEW_NOTES): string | null {
  if (view !== 'tables' && view !== 'stepper' && view !== 'formulas' && view !== 'surface') return null;
  return `${words.curved[view]}. ${words.curvedAnswered}`;
}
