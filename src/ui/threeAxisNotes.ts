/**
 * What the page says where three-axis machining is not answered (plain text, no DOM, so that the
 * tests can import it without the workers).
 */

/** Why the lookup table is not offered in three-axis machining, and what answers it instead. */
export const THREE_AXIS_TABLE_NOTE =
  'The lookup table is not offered for three-axis machining here: the command line answers a table of ' +
  'three-axis rows (path-interval --batch, columns slope, passes, rasterAngle, horizontalStep, stepDown).';
