/**
 * Calculator state as the user typed it, its URL form, and unit conversion. Pure (no DOM):
 * tested in Node. Field values are kept as text so an invalid entry is never lost.
 */

import { FIELDS, type FieldId, fieldOfPageKey, PAGE_FIELD_KEYS, urlParamOf } from '../core/input/fields';
import { toMm } from '../core/input/units';
import type { SurfaceAxis } from '../core/surfaces/cylinder';
import type { SolveMode } from '../worker/protocol';
import { choice, convertFields, fieldText, formatField, isLengthField, parseField } from './fieldText';
import { FINISH_KEYS, finishSearch } from './finishFields';
import { repeatedParamNotices } from './linkRepeats';
import { parseMachine, threeAxisNeeded, threeAxisSearch } from './machineState';
import type { CalculatorState, FieldKey, SurfaceKind, Target, ToolSize, Unit } from './stateTypes';
import { parseLinkRadii, RADIUS_PARAM, signedRadiusOf } from './surfaceState';
import { dropToolName, toolNameOfLink, writeToolName } from './toolName';
import { DEFAULT_FIELDS_MM } from './unitDefaults';

export { choice, convertField, fieldText, formatField, isLengthField, parseField, withDecimalPoint } from './fieldText';
export { PRESETS, type Preset, presetOf } from './toolPresets';

export type { CalculatorState, FieldKey, SurfaceKind, Target, ToolSize, Unit };

/** True when the tool size field holds the diameter D. */
export function sizeIsDiameter(state: CalculatorState): boolean {
  return state.size === 'D';
}

export { DEFAULT_FIELDS_IN, DEFAULT_FIELDS_MM } from './unitDefaults';

/** The page's text fields, in the form's order (the field registry's). */
export const FIELD_KEYS: readonly FieldKey[] = PAGE_FIELD_KEYS;

/** The URL query parameter of a registry field. */
const param = (id: FieldId): string => urlParamOf(id);

/**
 * The URL parameters that give a number of the tool or the problem (R or D, Rcr, rho, tilt, h, ra,
 * L): one of them in a link makes the others it needs "missing" (the surface has its own defaults).
 * A target Sa is not one: it asks of the teeth, as z and fz do, so `target=sa&sa=0.0008&z=4` leaves
 * the tool at its defaults silently, as `z=4&fz=0.1` does.
 */
const GIVEN_PARAMS: readonly string[] = Object.values(FIELDS).flatMap((f) =>
  (f.group === 'tool' || f.group === 'quantity' || f.group === 'alias') && f.url !== null && f !== FIELDS.targetSa
    ? [f.url]
    : [],
);

/** A field's value in mm (lengths) or degrees (angles), or its text when it is not a number. */
export function fieldInMm(state: CalculatorState, key: FieldKey): number | string {
  const v = parseField(state.fields[key]);
  if (v === null) return state.fields[key];
  const size = key === 'R' && sizeIsDiameter(state) ? 0.5 : 1;
  return isLengthField(key) ? toMm(v * size, state.unit) : v;
}

/** The tool radius in the user's unit as typed (half the field in diameter mode), or null when not a number. */
export function radiusField(state: CalculatorState): number | null {
  const v = parseField(state.fields.R);
  return v === null ? null : sizeIsDiameter(state) ? v / 2 : v;
}

/** The state with its tool size field given as `size`: the text doubled or halved (invalid text kept). */
export function withSize(state: CalculatorState, size: ToolSize): CalculatorState {
  if ((state.size ?? 'R') === size) return state;
  const v = parseField(state.fields.R);
  const R = v === null ? state.fields.R : formatField(size === 'D' ? 2 * v : v / 2);
  return { ...state, size, fields: { ...state.fields, R } };
}

/**
 * The state in unit `to`: untouched defaults become `to`'s own defaults, the values the user set
 * (typed, a preset or a tool: `edited`) convert without loss, and back as typed (fieldText.ts convertFields).
 */
export function convertState(state: CalculatorState, to: Unit): CalculatorState {
  return { ...state, unit: to, ...convertFields(state, to) };
}

/** The keys of `state.edited` with `keys` added (the same array when nothing is new). */
function editedWith(state: CalculatorState, keys: readonly FieldKey[]): readonly FieldKey[] {
  const before = state.edited ?? [];
  const added = keys.filter((k) => !before.includes(k));
  return added.length === 0 ? before : [...before, ...added];
}

export function defaultState(unit: Unit = 'mm', mode: SolveMode = 'forward'): CalculatorState {
  const mm: CalculatorState = {
    unit: 'mm',
    mode,
    pattern: 'one-way',
    target: 'h',
    surface: 'plane',
    surfaceAxis: 'feed',
    feedSide: 'straight',
    crossSide: 'straight',
    machine: '5axis',
    passes: 'raster',
    fields: DEFAULT_FIELDS_MM,
  };
  return unit === 'mm' ? mm : convertState(mm, unit);
}

/** A state with one field's text replaced. */
export function withField(state: CalculatorState, key: FieldKey, text: string): CalculatorState {
  return dropToolName({ ...state, fields: { ...state.fields, [key]: text }, edited: editedWith(state, [key]) }, [key]);
}

/** A state with fields set from values in mm and degrees (presets, the paper's conditions). */
export function withValues(
  state: CalculatorState,
  values: Partial<Readonly<Record<FieldKey, number>>>,
): CalculatorState {
  const fields = { ...state.fields };
  for (const key of FIELD_KEYS) {
    const v = values[key];
    if (v !== undefined) fields[key] = fieldText(key, key === 'R' && sizeIsDiameter(state) ? 2 * v : v, state.unit);
  }
  const set = FIELD_KEYS.filter((k) => values[k] !== undefined);
  return dropToolName({ ...state, fields, edited: editedWith(state, set) }, set);
}

export interface ParsedUrl {
  readonly state: CalculatorState;
  /** Messages for the visible notice: values that were missing or invalid and replaced. */
  readonly notices: readonly string[];
  readonly embed: boolean;
  readonly view: string | null;
  /** `present=` as the link gives it (app.ts takes `1`, says so of anything else), or null. */
  readonly present: string | null;
  /** True when the address asks nothing of the calculator (preferences.ts: a bare visit). */
  readonly bare: boolean;
}

/** The address parameters that set the page, not the question: they leave a visit "bare". */
const PAGE_SETTING_PARAMS: ReadonlySet<string> = new Set(['theme', 'present', 'view', 'lang']);

/** True when the address asks nothing of the calculator (no parameter beyond the page settings). */
export function isBareVisit(search: string): boolean {
  for (const key of new URLSearchParams(search).keys()) if (!PAGE_SETTING_PARAMS.has(key)) return false;
  return true;
}

/**
 * Reads the state from a query string (`?R=3&Rcr=1&rho=5&h=0.05&unit=mm`, plus `tilt=`,
 * `pattern=zigzag`, `surfaceRadius=&surfaceAxis=`, `mode=inverse&L=`, `target=ra&ra=`, `embed=1`). A present but invalid value, and a missing one
 * when others are given, falls back to its default with a notice (tilt and pattern have defaults
 * and are never missing); a parameter given more than once is read from its first value, with a
 * notice naming the values ignored (linkRepeats.ts). Cross-field rules are left to the
 * calculator's own validation, which shows them next to the fields.
 */
export function parseUrl(search: string): ParsedUrl {
  const params = new URLSearchParams(search);
  const notices: string[] = repeatedParamNotices(params);
  const unit = choice(params, 'unit', notices, { inch: 'in' });
  const mode = choice(params, 'mode', notices);
  const pattern = choice(params, 'pattern', notices);
  const target = choice(params, 'target', notices);
  const { machine, passes } = parseMachine(params, notices);
  const defaults = defaultState(unit, mode).fields;
  const fields = { ...defaults };
  const anyGiven = GIVEN_PARAMS.some((p) => params.has(p));
  const size = sizeFromUrl(params, anyGiven, notices);
  const needed: FieldKey[] =
    machine === '3axis'
      ? threeAxisNeeded(mode, target, passes)
      : ['R', 'Rcr', 'rho', mode === 'forward' ? target : 'L'];
  const surface = parseSurface(params, defaults.Rs, notices);
  if (surface.radiusText !== null) fields.Rs = surface.radiusText;
  const radii = parseLinkRadii(params, notices);
  if (radii.texts.Rf !== null) fields.Rf = radii.texts.Rf;
  if (radii.texts.Rc !== null) fields.Rc = radii.texts.Rc;
  if (radii.given && surface.kind !== 'plane' && machine === '5axis')
    notices.push(
      `${param('surfaceRadius')} and ${RADIUS_PARAM.Rf} or ${RADIUS_PARAM.Rc} are both in the link; using ${RADIUS_PARAM.Rf} and ${RADIUS_PARAM.Rc} (a link gives the surface one way).`,
    );
  for (const key of FIELD_KEYS) {
    // In the link as signed radii (parseSurface, parseLinkRadii).
    if (key === 'Rs' || key === 'Rf' || key === 'Rc') continue;
    const name = param(fieldOfPageKey(key));
    const text = params.get(name);
    if (text === null) {
      if (anyGiven && needed.includes(key) && !(key === 'R' && params.has(param('D'))))
        notices.push(`${name} is missing from the link; using the default ${defaults[key]}.`);
      continue;
    }
    const v = parseField(text);
    // The teeth and their feed are optional (empty by default): an empty one is simply not given,
    // and a bad one is left empty, said so.
    const optional = FINISH_KEYS.includes(key);
    if (v === null && optional && text.trim() !== '')
      notices.push(`${name}="${text.slice(0, 20)}" in the link is not a number; left empty.`);
    else if (v === null && !optional)
      notices.push(`${name}="${text.slice(0, 20)}" in the link is not a number; using the default ${defaults[key]}.`);
    else if (v !== null) fields[key] = text.trim();
  }
  // fz given wins over the feed rate and spindle speed (finishFields.ts finishKeyOff): said, not silent.
  if (fields.fz !== '' && fields.F + fields.n !== '')
    notices.push(`${param('fz')} is in the link: ${param('feedRate')} and ${param('spindleSpeed')} are not used.`);
  const toolName = toolNameOfLink(params);
  const embedText = params.get(param('embed'));
  const embed = embedText !== null && (FIELDS.embed.values as readonly string[]).includes(embedText);
  const state: CalculatorState = {
    unit,
    mode,
    pattern,
    target,
    surface: radii.given && machine === '5axis' ? 'curved' : surface.kind,
    surfaceAxis: surface.axis,
    feedSide: radii.feedSide,
    crossSide: radii.crossSide,
    machine,
    passes,
    fields,
    ...(toolName === undefined ? {} : { toolName }),
  };
  return {
    state:
      size === 'R' ? state : params.has(param('D')) ? diameterFromUrl(state, params, notices) : withSize(state, 'D'),
    notices,
    embed,
    view: params.get(param('view')),
    present: params.get(param('present')),
    bare: isBareVisit(search),
  };
}

/**
 * The tool size the link gives: `D=` (the diameter, as catalogues give it) without `R=` switches
 * the size field to D; with both, R wins and a notice says so (a link names one of them). A link
 * that gives no number of the tool or the problem (a fresh page) shows the diameter, as catalogues
 * and CAM tool libraries give it; one that gives others but neither R nor D keeps R (its notice
 * names R missing, as such links always read).
 */
function sizeFromUrl(params: URLSearchParams, anyGiven: boolean, notices: string[]): ToolSize {
  const [r, d] = [param('R'), param('D')];
  if (!params.has(d)) return anyGiven ? 'R' : 'D';
  if (!params.has(r)) return 'D';
  notices.push(`both ${r} and ${d} are in the link; using ${r}=${(params.get(r) ?? '').slice(0, 20)} (${d} ignored).`);
  return 'R';
}

/** The state of a link that gives the diameter D: the size field holds D (its default 2R when D is not a number). */
function diameterFromUrl(state: CalculatorState, params: URLSearchParams, notices: string[]): CalculatorState {
  const given = withSize(state, 'D');
  const text = params.get(param('D')) ?? '';
  if (parseField(text) !== null) return { ...given, fields: { ...given.fields, R: text.trim() } };
  notices.push(
    `${param('D')}="${text.slice(0, 20)}" in the link is not a number; using the default ${given.fields.R}.`,
  );
  return given;
}

/**
 * The surface in a link: `surfaceRadius=` signed in the link's unit (> 0 convex, < 0 concave; the
 * field keeps its magnitude as written) and `surfaceAxis=feed|cross`; neither for a plane. An
 * invalid radius falls back to a plane, an invalid axis to feed, each with a notice.
 */
function parseSurface(
  params: URLSearchParams,
  defaultRadius: string,
  notices: string[],
): { kind: SurfaceKind; axis: SurfaceAxis; radiusText: string | null } {
  const axis: SurfaceAxis = choice(params, 'surfaceAxis', notices);
  const name = param('surfaceRadius');
  const text = params.get(name);
  if (text === null || text.trim() === '' || text.trim() === 'plane') return { kind: 'plane', axis, radiusText: null };
  const v = parseField(text);
  if (v === null) {
    notices.push(
      `${name}="${text.slice(0, 20)}" in the link is not a number; using a plane (a cylinder's radius defaults to ${defaultRadius}).`,
    );
    return { kind: 'plane', axis, radiusText: null };
  }
  const t = text.trim();
  return { kind: v < 0 ? 'concave' : 'convex', axis, radiusText: /^[+-]/.test(t) ? t.slice(1) : t };
}

/** The signed surface radius as the link writes it: the field's text, with a minus when concave. */
export function signedRadiusText(state: CalculatorState): string {
  const t = state.fields.Rs.trim();
  if (state.surface !== 'concave' || t.startsWith('-')) return t;
  return `-${t.startsWith('+') ? t.slice(1) : t}`;
}

/**
 * The query string that records a state (values as typed, in the current unit). The defaults of
 * the posture, no tilt and one-way passes, are left out, so the paper's links stay as they were; so
 * is the surface for a plane (a cylinder writes its signed radius and its axis).
 */
export function toSearch(state: CalculatorState, extra: Readonly<Record<string, string>> = {}): string {
  const params = new URLSearchParams();
  const set = (id: FieldId, value: string) => params.set(param(id), value);
  set(sizeIsDiameter(state) ? 'D' : 'R', state.fields.R);
  set('Rcr', state.fields.Rcr);
  writeToolName(params, state);
  if (state.machine === '3axis') {
    for (const [name, value] of [...threeAxisSearch(state), ...finishSearch(state)]) params.set(name, value);
    for (const [k, v] of Object.entries(extra)) params.set(k, v);
    return `?${params.toString()}`;
  }
  set('rho', state.fields.rho);
  if (state.fields.tilt.trim() !== '0') set('tilt', state.fields.tilt);
  if (state.pattern !== 'one-way') set('pattern', state.pattern);
  if (state.surface === 'curved')
    for (const key of ['Rf', 'Rc'] as const) {
      const signed = signedRadiusOf(state, key);
      if (signed !== null) params.set(RADIUS_PARAM[key], signed);
    }
  else if (state.surface !== 'plane') {
    set('surfaceRadius', signedRadiusText(state));
    set('surfaceAxis', state.surfaceAxis);
  }
  if (state.mode === 'forward' && state.target === 'ra') {
    set('target', 'ra');
    set('ra', state.fields.ra);
  } else if (state.mode === 'forward' && state.target === 'sa') {
    set('target', 'sa');
    set('targetSa', state.fields.sa);
  } else if (state.mode === 'forward') set('h', state.fields.h);
  else {
    set('mode', 'inverse');
    set('interval', state.fields.L);
  }
  for (const [name, value] of finishSearch(state)) params.set(name, value);
  set('unit', state.unit);
  for (const [k, v] of Object.entries(extra)) params.set(k, v);
  return `?${params.toString()}`;
}
