/**
 * The results table's notes in a catalogue's language (issue 30). results.ts, resultsText.ts and
 * resultsOther.ts write them in English, sentences joined by spaces (a row's note is also its hover
 * title); each sentence is read back here against that English and worded from the catalogue, the
 * procedures' names in the language, lengths with the locale's decimal sign. A sentence not known
 * (a reason the page has not seen) is kept English, marked so by language.ts. Pure (no DOM);
 * tests/ui/i18n/tableNotes.test.ts makes the page's notes and reads each back. Loaded with the
 * language code.
 */
import { CURVATURE_ROWS, type CurvatureRowKey, PROCEDURES, type ProcedureKey } from '../../core/procedures/procedures';
import { gapReasonIn } from '../views/gapReasons';
import type { Catalogue } from './catalogue';
import { localDecimal } from './langChoice';

/** The notes' sentences: each ends with a full stop before a capital (names such as "et al." never do). */
export function noteSentences(text: string): string[] {
  return text === '' ? [] : text.split(/(?<=\.) (?=[A-Z])/);
}

/** A row's English name (a procedure's, a cylinder's or a doubly curved point's row) in `c`'s language, or null. */
function nameIn(english: string, c: Catalogue): string | null {
  const p = c.procedures;
  for (const key of Object.keys(PROCEDURES) as ProcedureKey[]) {
    if (english === PROCEDURES[key].shortLabel) return p.names[key].shortLabel;
    if (english === PROCEDURES[key].label) return p.names[key].label;
  }
  for (const key of Object.keys(CURVATURE_ROWS) as CurvatureRowKey[]) {
    const row = CURVATURE_ROWS[key];
    if (english === row.shortLabel) return p.rows[key].shortLabel;
    if (english === row.label) return p.rows[key].label;
    if (english === `${row.shortLabel} (1/rho = 1/Reff + 1/Rc)`)
      return `${p.rows[key].shortLabel} (1/rho = 1/Reff + 1/Rc)`;
  }
  return p.curved[english as keyof Catalogue['procedures']['curved']] ?? null;
}

/** The English sentences written whole (results.ts, resultsOther.ts, resultsText.ts CROSS_AXIS_NOTE, the worker), by their words' key. */
export const WHOLE_NOTES: ReadonlyArray<
  readonly [string, 'noScallop' | 'cylinder' | 'crossAxis' | 'curved' | 'curvedInverse' | 'planeBeyond']
> = [
  ['No scallop: a flat end lying flat leaves none at any step-over up to its diameter, so L = 2R.', 'noScallop'],
  [
    'On a cylinder the procedures above are applied as on a plane (they ignore the curvature); the rows below them give the exact answer for a plane at the same input (the curvature ignored) and the usual correction 1/rho = 1/Reff + 1/Rs of each procedure with an effective radius, each beside the exact answer on the cylinder.',
    'cylinder',
  ],
  [
    "With the cylinder's axis across the feed its section across the feed is a straight line (1/Rs = 0 there), so the correction leaves rho = Reff and each corrected row equals its procedure's row above.",
    'crossAxis',
  ],
  [
    'Each row beside the exact answer: the plane (both curvatures ignored), each cylinder (one radius ignored) and the usual correction 1/rho = 1/Reff + 1/Rc of each procedure with an effective radius, with its deviation from exact and the scallop its own L really leaves at this point.',
    'curved',
  ],
  ['The comparison rows are given for the forward problem (a scallop height to the step-over).', 'curvedInverse'],
  ['Plane: the step-over is at or beyond the widest one the tool allows on a plane.', 'planeBeyond'],
];

const LEAD_ONLY = /^With tilt, (.+) are lead-only models: applied with the lead angle alone, the tilt ignored\.$/;
const BEYOND =
  /^(.+?): (h|L\/2) = (.+?) is (?:above the widest point of|wider than) its (circle|ellipse|combined circle) \((Reff|its height Rlong sin\(rho\)|its half-width Rlong|rho) = (.+)\)\.$/;
const WALL =
  /^(.+?): its step-over L = (.+?) is not below the widest step-over that leaves a scallop( on this cylinder)? \((.+)\): passes this far apart leave a wall\.$/;
const NOT_POSITIVE =
  /^its effective radius(?: \((.+?)\))? is not smaller than the concave (?:surface's radius|surface's|radius across the feed), so the combined radius(?: 1\/\(1\/Reff \+ 1\/Rs\))? is not positive$/;
const COMBINED_WIDEST = /^h is above the widest point of the combined circle \((.+)\)$/;
const LIMITS = {
  Reff: 'Reff',
  'its height Rlong sin(rho)': 'height',
  'its half-width Rlong': 'halfWidth',
  rho: 'rho',
} as const;

/** A row's reason after its name (without the full stop) in `c`'s language, or null when not known. */
function reasonIn(name: string, reason: string, c: Catalogue): string | null {
  const n = c.procedures.notes;
  const gap = gapReasonIn(reason, c.chart);
  if (gap !== null) return n.reason(name, gap);
  if (reason === 'h is at or above the flank limit of that surface') return n.flankLimit(name);
  const notPositive = NOT_POSITIVE.exec(reason);
  if (notPositive !== null)
    return n.notPositive(name, notPositive[1] === undefined ? null : localDecimal(notPositive[1], c));
  const widest = COMBINED_WIDEST.exec(reason);
  if (widest !== null) return n.combinedWidest(name, localDecimal(widest[1] ?? '', c));
  // A model's own reason after its own name (a doubly curved point's corrected row): "Sekine et al.: ...".
  const inner = /^(.+?): (.+)$/s.exec(reason);
  const innerName = inner === null ? null : nameIn(inner[1] ?? '', c);
  const innerReason = inner === null || innerName === null ? null : reasonIn(innerName, inner[2] ?? '', c);
  return innerReason === null ? null : n.reason(name, innerReason.replace(/[.。]$/, ''));
}

/** One sentence of the notes in `c`'s language, or null when it is not one the page writes. */
export function noteIn(english: string, c: Catalogue): string | null {
  const n = c.procedures.notes;
  const whole = WHOLE_NOTES.find(([text]) => text === english);
  if (whole !== undefined) return n[whole[1]];
  const lead = LEAD_ONLY.exec(english);
  if (lead !== null) {
    const names = (lead[1] ?? '').split(', ').map((e) => nameIn(e, c));
    return names.includes(null) ? null : n.leadOnly(names.join(c.question[', ']));
  }
  const beyond = BEYOND.exec(english);
  const beyondName = beyond === null ? null : nameIn(beyond[1] ?? '', c);
  if (beyond !== null && beyondName !== null) {
    const model = beyond[4] === 'combined circle' ? 'combined' : beyond[4] === 'ellipse' ? 'ellipse' : 'circle';
    return n.beyond(
      beyondName,
      beyond[2] === 'h' ? 'h' : 'L/2',
      localDecimal(beyond[3] ?? '', c),
      model,
      LIMITS[beyond[5] as keyof typeof LIMITS],
      localDecimal(beyond[6] ?? '', c),
    );
  }
  const wall = WALL.exec(english);
  const wallName = wall === null ? null : nameIn(wall[1] ?? '', c);
  if (wall !== null && wallName !== null)
    return n.wall(wallName, localDecimal(wall[2] ?? '', c), localDecimal(wall[4] ?? '', c), wall[3] !== undefined);
  const said = /^(.+?): (.+)\.$/s.exec(english);
  const name = said === null ? null : nameIn(said[1] ?? '', c);
  return said === null || name === null ? null : reasonIn(name, said[2] ?? '', c);
}

/** The notes (sentences joined by spaces) in `c`'s language: each sentence worded, or kept English (its flag true). */
export function notesIn(english: string, c: Catalogue): ReadonlyArray<readonly [string, boolean]> {
  return noteSentences(english).map((s) => {
    const local = noteIn(s, c);
    return local === null ? [s, true] : [local, false];
  });
}
