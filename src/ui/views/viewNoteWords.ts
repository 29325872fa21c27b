/**
 * The teaching views' neutral lines for a page question, in English (issue 30): as written, typed by
 * the catalogues' ViewNoteWords so Japanese and German give every one. Loaded with the views.
 */
import type { ViewNoteWords } from '../i18n/catalogue';

export const EN_VIEW_NOTES: ViewNoteWords = {
  curved: {
    tables: "The paper's tables hold its own conditions, on a plane",
    stepper: "The paper's procedure, step by step, solves a plane or a cylinder",
    formulas: "The paper's formulas take a plane or a cylinder",
    surface: 'The machined-surface simulation runs on a plane or a cylinder',
  },
  curvedAnswered:
    'This doubly curved point is answered by the results above, the Profile (its section across the feed) and the L against each radius chart.',
  question: (slope, psi) => `slope ${slope}°, ${psi === null ? 'waterline' : `raster ${psi}°`}`,
  tables:
    "The paper's tables: its own five-axis conditions (a lead on a plane), kept for reference; they are not the three-axis question on screen.",
  revolution: (q) =>
    `Waterline passes on a surface of revolution (${q}) change their spacing from level to level, so this view, which draws congruent passes, has nothing to draw: the Step against slope chart and the 3D scene show them.`,
  equivalent: (q, lead, tilt, surface) =>
    `The upright tool over ${q} is the tool at lead ${lead} deg, tilt ${tilt} deg on a plane, one-way: ${surface ? "its passes simulated in the plane's own frame." : "drawn in the plane's own frame (lengths along it, h along its normal)."}`,
};
