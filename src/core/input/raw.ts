/**
 * Raw inputs (what validation reads: `{ R, Rcr, rho, ... }`, validate.ts's Raw*Input) built from
 * the field registry's names, so no caller spells the tool's field list again: from a channel (the
 * command line's options, a CSV record, the page's fields) by each field's name there, or back from
 * a validated input by each field's core property. Pure; values as given (mm and degrees).
 */
import { FIELDS, type FieldName } from './fields';

/** Raw values of `names`, keyed by field name; a field not given is absent (or undefined). */
export type RawFields<N extends FieldName> = { readonly [K in N]: unknown };

/** The raw values of `names`, each read by `read` (undefined: not given, the field's default or "missing"). */
export function rawFields<N extends FieldName>(names: readonly N[], read: (name: N) => unknown): RawFields<N> {
  const out: Record<string, unknown> = {};
  for (const name of names) out[name] = read(name);
  return out as RawFields<N>;
}

/** Each core path split into its keys, once. */
const PATH_KEYS = new Map<string, readonly string[]>();

/** A property of `input` at a registry core path (`toolRadiusMm`, `surface.radiusMm`); undefined when absent. */
function atPath(input: object, path: string): unknown {
  let keys = PATH_KEYS.get(path);
  if (keys === undefined) {
    keys = path.split('.');
    PATH_KEYS.set(path, keys);
  }
  let value: unknown = input;
  for (const key of keys) {
    if (value === null || typeof value !== 'object') return undefined;
    value = (value as Record<string, unknown>)[key];
  }
  return value;
}

/**
 * The raw fields of a validated input (a ToolInput, PassInput, ForwardInput...) read back by each
 * field's core property: validation gives the same input again. A field the input does not hold is
 * left out (a plane has no surface radius or axis).
 */
export function rawOf<N extends FieldName>(input: object, names: readonly N[]): RawFields<N> {
  const out: Record<string, unknown> = {};
  for (const name of names) {
    const path = FIELDS[name].core;
    const value = path === null ? undefined : atPath(input, path);
    if (value !== undefined) out[name] = value;
  }
  return out as RawFields<N>;
}

/**
 * True when `a` and `b` hold the same value of every field of `names`, read by each field's core
 * property (a field neither holds counts as the same: a plane has no surface radius).
 */
export function sameFields(a: object, b: object, names: readonly FieldName[]): boolean {
  for (const name of names) {
    const path = FIELDS[name].core;
    if (path !== null && atPath(a, path) !== atPath(b, path)) return false;
  }
  return true;
}
