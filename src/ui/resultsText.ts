/**
 * The results' words: a procedure's note, a comparison row's note, what L and the heights mean on a
 * cylinder; lengths in the user's unit. Pure.
 */

import type { LengthUnit } from '../core/input/units';
import { CURVATURE_ROWS, type CurvatureRowKey, PROCEDURES, type ProcedureKey } from '../core/procedures/procedures';
import type { Surface } from '../core/surfaces/cylinder';
import type { ProcedureNote } from '../worker/protocol';
import { formatLenUnit } from './format';

/** A note that a row's answer lies beyond its model (a circle or an ellipse, and its limit). */
type BeyondModelNote = Extract<ProcedureNote, { kind: 'beyond-model' }>;

/**
 * A row's note in words, lengths in the user's unit: `model` names the model the value lies beyond
 * and opens the bracket of its limit; `scallopWhere` ends the wall's phrase.
 */
function noteWords(
  label: string,
  note: ProcedureNote,
  unit: LengthUnit,
  model: (note: BeyondModelNote) => string,
  scallopWhere: string,
): string {
  switch (note.kind) {
    case 'reason':
      return note.text;
    case 'beyond-model': {
      const what = note.quantity === 'h' ? 'h' : 'L/2';
      const where = note.quantity === 'h' ? 'above the widest point of' : 'wider than';
      return `${label}: ${what} = ${formatLenUnit(note.valueMm, unit, 'height')} is ${where} its ${model(note)} = ${formatLenUnit(note.limitMm, unit)}).`;
    }
    case 'wall':
      return `${label}: its step-over L = ${formatLenUnit(note.intervalMm, unit)} is not below the widest step-over that leaves a scallop${scallopWhere} (${formatLenUnit(note.maxIntervalMm, unit)}): passes this far apart leave a wall.`;
  }
}

/** A procedure's note in words, lengths in the user's unit. */
export function noteText(key: ProcedureKey, note: ProcedureNote, unit: LengthUnit): string {
  const model = (n: BeyondModelNote): string => {
    const limit =
      n.shape === 'circle' ? 'Reff' : n.quantity === 'h' ? 'its height Rlong sin(rho)' : 'its half-width Rlong';
    return `${n.shape} (${limit}`;
  };
  return noteWords(PROCEDURES[key].shortLabel, note, unit, model, '');
}

/** A comparison row's note in words (the plane's answer, or a procedure corrected for the curvature). */
export function curvatureNoteText(key: CurvatureRowKey, note: ProcedureNote, unit: LengthUnit): string {
  return noteWords(CURVATURE_ROWS[key].shortLabel, note, unit, () => 'combined circle (rho', ' on this cylinder');
}

/** What L and the heights mean on the surface of a request, in words (empty on a plane). */
export function surfaceMeaning(surface: Surface, unit: LengthUnit): string {
  if (surface.kind === 'plane') return '';
  const side = surface.radiusMm > 0 ? 'convex' : 'concave';
  const r = formatLenUnit(Math.abs(surface.radiusMm), unit);
  return surface.axis === 'feed'
    ? `On this ${side} cylinder (radius ${r}, axis along the feed: the passes run along it), L and the flank widths are arc lengths on the surface between the CC paths, and every height is measured radially, from the cylinder.`
    : `On this ${side} cylinder (radius ${r}, axis across the feed: the passes go around it and step along its axis), L and the flank widths are measured along the axis, and every height radially, from the cylinder.`;
}

/** What a doubly curved point's L and heights mean, in words (its radii, mm, signed: negative concave). */
export function curvedMeaning(feedRadiusMm: number, crossRadiusMm: number, unit: LengthUnit): string {
  const r = (mm: number) => `${mm < 0 ? 'concave' : 'convex'} ${formatLenUnit(Math.abs(mm), unit)}`;
  return `At this doubly curved point (Rf ${r(feedRadiusMm)} along the feed, Rc ${r(crossRadiusMm)} across it), L and the flank reaches are arc lengths along the surface across the feed between the CC paths, and every height is measured radially, in the cross-feed plane through the contact.`;
}

/**
 * Why, on a cylinder whose axis runs across the feed, each corrected row equals its procedure's own
 * row: the correction combines the effective radius with the surface's radius in the section across
 * the feed (compare.ts, approximations.ts combinedRadiusMm), and that section of such a cylinder is a
 * straight line, so 1/Rs = 0 and rho = Reff.
 */
export const CROSS_AXIS_NOTE =
  "With the cylinder's axis across the feed its section across the feed is a straight line (1/Rs = 0 there), so the correction leaves rho = Reff and each corrected row equals its procedure's row above.";
