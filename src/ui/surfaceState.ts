/**
 * The doubly curved point as the page holds it (issue 19; shared/notes/doubly-curved-and-3-axis.md,
 * section 1): the two principal radii, each a magnitude in its field (`Rf` along the feed, `Rc`
 * across it) and a side, convex, concave or straight, and the presets that set the sides (dome,
 * bowl, saddle, sphere, the two cylinders, the plane; for three-axis waterline passes on a surface
 * of revolution: dome, bowl, boss, fillet). In a link each radius is one signed number in the link's
 * unit (`feedRadius=-40`: concave), left out when straight. Pure (no DOM).
 */

import { FIELDS } from '../core/input/fields';

/** One principal radius's side: convex (> 0), concave (< 0), or straight (infinite). */
export type RadiusSide = 'straight' | 'convex' | 'concave';

/** The sides a radius takes, in the order the page offers them. */
export const RADIUS_SIDES: readonly RadiusSide[] = ['convex', 'concave', 'straight'];

/** The two radii's keys: the page's fields (magnitudes) and their sides in the state. */
export type RadiusKey = 'Rf' | 'Rc';

/** What the presets and the links read of a state: the two radii's texts and sides. */
export interface CurvedFields {
  readonly fields: Readonly<Record<RadiusKey, string>>;
  readonly feedSide: RadiusSide;
  readonly crossSide: RadiusSide;
}

/** The side of each radius key in a state. */
export function sideOf(state: CurvedFields, key: RadiusKey): RadiusSide {
  return key === 'Rf' ? state.feedSide : state.crossSide;
}

/**
 * The presets of a five-axis doubly curved point, by the sides they set: a plane (both straight),
 * the cylinder along the feed (Rf straight) and across it (Rc straight), a dome (both convex), a
 * sphere (both convex and equal), a bowl (both concave), a saddle (convex along the feed, concave
 * across).
 */
export const CURVED_PRESETS = [
  'dome',
  'bowl',
  'saddle',
  'sphere',
  'cylinder-along',
  'cylinder-across',
  'plane',
] as const;
export type CurvedPreset = (typeof CURVED_PRESETS)[number];

/**
 * The presets of waterline passes on a surface of revolution (section 2b): a sloped plane, a dome
 * (convex both ways), a bowl (concave both ways, equal radii: a spherical bowl), a boss (convex
 * around, a straight meridian: a cone or a cylinder), a pocket fillet (concave both ways, the
 * meridian's radius the smaller).
 */
export const WATERLINE_PRESETS = ['dome', 'bowl', 'boss', 'fillet', 'plane'] as const;
export type WaterlinePreset = (typeof WATERLINE_PRESETS)[number];

/** The presets' names on the page. */
export const PRESET_LABELS: Readonly<Record<CurvedPreset | WaterlinePreset, string>> = {
  dome: 'dome (convex both ways)',
  bowl: 'bowl (concave both ways)',
  saddle: 'saddle (convex along, concave across)',
  sphere: 'sphere (Rc = Rf, convex)',
  'cylinder-along': 'cylinder, axis along the feed (Rf straight)',
  'cylinder-across': 'cylinder, axis across the feed (Rc straight)',
  plane: 'plane (both straight)',
  boss: 'boss (convex around, straight meridian)',
  fillet: 'pocket fillet (concave, Rc the smaller)',
};

/** The magnitude of a radius's text (a leading sign dropped), or null when it is not a plain number. */
function magnitude(text: string): number | null {
  const t = text.trim().replace(/^[+-]/, '');
  if (!/^(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/.test(t)) return null;
  const v = Number(t);
  return Number.isFinite(v) ? v : null;
}

/** True when both radii's texts hold the same magnitude. */
function sameMagnitude(state: CurvedFields): boolean {
  const f = magnitude(state.fields.Rf);
  return f !== null && f === magnitude(state.fields.Rc);
}

/** The five-axis preset the sides (and, for a sphere, the equal radii) make, or null ("custom" never: every pair is one). */
export function curvedPresetOf(state: CurvedFields): CurvedPreset {
  const { feedSide: f, crossSide: c } = state;
  if (f === 'straight') return c === 'straight' ? 'plane' : 'cylinder-along';
  if (c === 'straight') return 'cylinder-across';
  if (f === 'convex' && c === 'convex') return sameMagnitude(state) ? 'sphere' : 'dome';
  if (f === 'concave' && c === 'concave') return 'bowl';
  return 'saddle';
}

/** The waterline preset the sides and radii make, or null when none does (a saddle, a bowl wider than deep...). */
export function waterlinePresetOf(state: CurvedFields): WaterlinePreset | null {
  const { feedSide: f, crossSide: c } = state;
  if (f === 'straight' && c === 'straight') return 'plane';
  if (f === 'convex' && c === 'convex') return 'dome';
  if (f === 'convex' && c === 'straight') return 'boss';
  if (f === 'concave' && c === 'concave') {
    if (sameMagnitude(state)) return 'bowl';
    const rf = magnitude(state.fields.Rf);
    const rc = magnitude(state.fields.Rc);
    return rf !== null && rc !== null && rc < rf ? 'fillet' : null;
  }
  return null;
}

/** A magnitude's text scaled by `factor` (6 significant digits), or the text kept when it is not a number. */
function scaled(text: string, factor: number): string {
  const v = magnitude(text);
  return v === null ? text : String(Number((v * factor).toPrecision(6)));
}

/**
 * The sides (and texts) a preset sets. A dome keeps the radii unless they are equal (then Rc is
 * halved, or it would be the sphere); a sphere copies Rf into Rc; a cylinder keeps the curved
 * radius's side when it was curved (convex otherwise). Waterline (`waterline` true: three-axis
 * waterline passes on a surface of revolution): a bowl copies Rf into Rc (a spherical bowl), a
 * fillet takes Rc as an eighth of Rf unless it is already the smaller.
 */
export function withCurvedPreset<S extends CurvedFields>(
  state: S,
  preset: CurvedPreset | WaterlinePreset,
  waterline = false,
): S {
  const curved = (side: RadiusSide): RadiusSide => (side === 'straight' ? 'convex' : side);
  const fields = { ...state.fields };
  let feedSide: RadiusSide;
  let crossSide: RadiusSide;
  switch (preset) {
    case 'plane':
      [feedSide, crossSide] = ['straight', 'straight'];
      break;
    case 'dome':
      [feedSide, crossSide] = ['convex', 'convex'];
      if (sameMagnitude(state)) fields.Rc = scaled(state.fields.Rf, 0.5);
      break;
    case 'sphere':
      [feedSide, crossSide] = ['convex', 'convex'];
      fields.Rc = state.fields.Rf;
      break;
    case 'bowl':
      [feedSide, crossSide] = ['concave', 'concave'];
      if (waterline) fields.Rc = state.fields.Rf;
      break;
    case 'saddle':
      [feedSide, crossSide] = ['convex', 'concave'];
      break;
    case 'cylinder-along':
      [feedSide, crossSide] = ['straight', curved(state.crossSide)];
      break;
    case 'cylinder-across':
      [feedSide, crossSide] = [curved(state.feedSide), 'straight'];
      break;
    case 'boss':
      [feedSide, crossSide] = ['convex', 'straight'];
      break;
    case 'fillet': {
      [feedSide, crossSide] = ['concave', 'concave'];
      const rf = magnitude(state.fields.Rf);
      const rc = magnitude(state.fields.Rc);
      if (!(rf !== null && rc !== null && rc < rf)) fields.Rc = scaled(state.fields.Rf, 1 / 8);
      break;
    }
  }
  return { ...state, fields, feedSide, crossSide };
}

/** The signed text of a radius as a link writes it (a minus when concave), or null when straight. */
export function signedRadiusOf(state: CurvedFields, key: RadiusKey): string | null {
  const side = sideOf(state, key);
  if (side === 'straight') return null;
  const t = state.fields[key].trim().replace(/^\+/, '');
  if (side === 'convex' || t.startsWith('-')) return t;
  return `-${t}`;
}

/** The URL parameter of each radius key. */
export const RADIUS_PARAM: Readonly<Record<RadiusKey, string>> = {
  Rf: FIELDS.feedRadius.url,
  Rc: FIELDS.crossRadius.url,
};

/** The radii a link gives: each side, its magnitude's text (null: not in the link), and whether either was given. */
export interface LinkRadii {
  readonly feedSide: RadiusSide;
  readonly crossSide: RadiusSide;
  readonly texts: Readonly<Record<RadiusKey, string | null>>;
  readonly given: boolean;
}

/**
 * The radii of a link: `feedRadius=` and `crossRadius=`, signed in the link's unit (> 0 convex,
 * < 0 concave; empty or `plane`: straight); a radius that is not a number is straight, with a
 * notice naming its parameter.
 */
export function parseLinkRadii(params: URLSearchParams, notices: string[]): LinkRadii {
  const sides: Record<RadiusKey, RadiusSide> = { Rf: 'straight', Rc: 'straight' };
  const texts: Record<RadiusKey, string | null> = { Rf: null, Rc: null };
  let given = false;
  for (const key of ['Rf', 'Rc'] as const) {
    const name = RADIUS_PARAM[key];
    const text = params.get(name);
    if (text === null) continue;
    given = true;
    const t = text.trim();
    if (t === '' || t === 'plane') continue;
    const v = magnitude(t);
    if (v === null) {
      notices.push(`${name}="${text.slice(0, 20)}" in the link is not a number; using a straight line (no curvature).`);
      continue;
    }
    sides[key] = t.startsWith('-') ? 'concave' : 'convex';
    texts[key] = t.replace(/^[+-]/, '');
  }
  return { feedSide: sides.Rf, crossSide: sides.Rc, texts, given };
}
