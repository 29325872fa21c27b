/**
 * Calculator state as the user typed it, its URL form, and unit conversion. Pure (no DOM):
 * tested in Node. Field values are kept as text so an invalid entry is never lost.
 */
import type { SolveMode } from '../worker/protocol';

export type Unit = 'mm' | 'in';
export type FieldKey = 'R' | 'Rcr' | 'rho' | 'h' | 'L';

export interface CalculatorState {
  readonly unit: Unit;
  readonly mode: SolveMode;
  /** Text of each field in the current unit (rho in degrees). */
  readonly fields: Readonly<Record<FieldKey, string>>;
}

export const MM_PER_INCH = 25.4;

/** Defaults in mm: the paper's Tool 1, condition 1 (L is its exact step-over, rounded). */
export const DEFAULT_FIELDS_MM: Readonly<Record<FieldKey, string>> = {
  R: '3',
  Rcr: '1',
  rho: '5',
  h: '0.05',
  L: '2.9',
};

export const LENGTH_FIELDS: readonly FieldKey[] = ['R', 'Rcr', 'h', 'L'];
export const FIELD_KEYS: readonly FieldKey[] = ['R', 'Rcr', 'rho', 'h', 'L'];

/** Formats a number for a field: at most 6 significant digits, no exponent for usual sizes. */
export function formatField(value: number): string {
  if (!Number.isFinite(value)) return '';
  return String(Number(value.toPrecision(6)));
}

const NUMBER = /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/;

/** Parses a field's text; null when it is not a plain finite number. */
export function parseField(text: string): number | null {
  const t = text.trim();
  if (!NUMBER.test(t)) return null;
  const v = Number(t);
  return Number.isFinite(v) ? v : null;
}

/** Converts one field's text between units (angles unchanged, invalid text kept as is). */
export function convertField(key: FieldKey, text: string, from: Unit, to: Unit): string {
  if (from === to || key === 'rho') return text;
  const v = parseField(text);
  if (v === null) return text;
  return formatField(from === 'mm' ? v / MM_PER_INCH : v * MM_PER_INCH);
}

export function convertState(state: CalculatorState, to: Unit): CalculatorState {
  const fields = { ...state.fields };
  for (const key of FIELD_KEYS) fields[key] = convertField(key, state.fields[key], state.unit, to);
  return { ...state, unit: to, fields };
}

export function defaultState(unit: Unit = 'mm', mode: SolveMode = 'forward'): CalculatorState {
  const mm: CalculatorState = { unit: 'mm', mode, fields: DEFAULT_FIELDS_MM };
  return unit === 'mm' ? mm : convertState(mm, unit);
}

/** Converts a field's value to mm (or degrees for rho). */
export function toMm(key: FieldKey, value: number, unit: Unit): number {
  return unit === 'in' && key !== 'rho' ? value * MM_PER_INCH : value;
}

export interface ParsedUrl {
  readonly state: CalculatorState;
  /** Messages for the visible notice: values that were missing or invalid and replaced. */
  readonly notices: readonly string[];
  readonly embed: boolean;
  readonly view: string | null;
}

/**
 * Reads the state from a query string (`?R=3&Rcr=1&rho=5&h=0.05&unit=mm`, plus `mode=inverse&L=`,
 * `embed=1`). A present but invalid value, and a missing one when others are given, falls back
 * to its default with a notice. Cross-field rules are left to the calculator's own validation,
 * which shows them next to the fields.
 */
export function parseUrl(search: string): ParsedUrl {
  const params = new URLSearchParams(search);
  const notices: string[] = [];
  const unitText = params.get('unit');
  let unit: Unit = 'mm';
  if (unitText === 'in' || unitText === 'inch') unit = 'in';
  else if (unitText !== null && unitText !== 'mm') notices.push(`unit="${unitText}" is not mm or in; using mm.`);
  const modeText = params.get('mode');
  let mode: SolveMode = 'forward';
  if (modeText === 'inverse') mode = 'inverse';
  else if (modeText !== null && modeText !== 'forward')
    notices.push(`mode="${modeText}" is not forward or inverse; using forward.`);
  const defaults = defaultState(unit, mode).fields;
  const fields = { ...defaults };
  const needed: FieldKey[] = ['R', 'Rcr', 'rho', mode === 'forward' ? 'h' : 'L'];
  const anyGiven = FIELD_KEYS.some((k) => params.has(k));
  for (const key of FIELD_KEYS) {
    const text = params.get(key);
    if (text === null) {
      if (anyGiven && needed.includes(key))
        notices.push(`${key} is missing from the link; using the default ${defaults[key]}.`);
      continue;
    }
    const v = parseField(text);
    if (v === null)
      notices.push(`${key}="${text.slice(0, 20)}" in the link is not a number; using the default ${defaults[key]}.`);
    else fields[key] = text.trim();
  }
  const embed = params.get('embed') === '1' || params.get('embed') === 'true';
  return { state: { unit, mode, fields }, notices, embed, view: params.get('view') };
}

/** The query string that records a state (values as typed, in the current unit). */
export function toSearch(state: CalculatorState, extra: Readonly<Record<string, string>> = {}): string {
  const params = new URLSearchParams();
  params.set('R', state.fields.R);
  params.set('Rcr', state.fields.Rcr);
  params.set('rho', state.fields.rho);
  if (state.mode === 'forward') params.set('h', state.fields.h);
  else {
    params.set('mode', 'inverse');
    params.set('L', state.fields.L);
  }
  params.set('unit', state.unit);
  for (const [k, v] of Object.entries(extra)) params.set(k, v);
  return `?${params.toString()}`;
}

/** Presets: the paper's tools and a few common catalogue sizes (mm). */
export const PRESETS: ReadonlyArray<{ readonly label: string; readonly R: number; readonly Rcr: number }> = [
  { label: 'Paper Tool 1 (R 3, Rcr 1)', R: 3, Rcr: 1 },
  { label: 'Paper Tool 2 (R 6, Rcr 2)', R: 6, Rcr: 2 },
  { label: 'D6 R0.5 (R 3, Rcr 0.5)', R: 3, Rcr: 0.5 },
  { label: 'D10 R1 (R 5, Rcr 1)', R: 5, Rcr: 1 },
  { label: 'D16 R3 (R 8, Rcr 3)', R: 8, Rcr: 3 },
  { label: '1/2 in, 0.060 in corner', R: 6.35, Rcr: 1.524 },
];
