/**
 * The page's remembered choices (issue 28, point 1): the machine (five-axis or three-axis) and the
 * unit, kept in the browser's localStorage across visits, as the saved tools are. A bare visit (an
 * address that asks no question of its own) starts from them; a link that gives the calculator any
 * value, and an embed, show what they say (a link without `machine=` is a five-axis link, without
 * `unit=` a millimetre one), so the preferences never change what a shared link means. Whatever the
 * storage holds is read as untrusted: only the known words count. A storage that throws (disabled,
 * private mode, full) is as if empty. Pure apart from the storage handed in and the memory of what
 * was last read from or written to it (so that a keystroke or a drag step that changes neither the
 * machine nor the unit writes nothing: a localStorage write is synchronous).
 */
import type { ToolStorage } from './savedTools';
import { defaultState, withSize } from './state';
import type { CalculatorState, Machine, Unit } from './stateTypes';

/** The storage key (versioned: a later form gets another key). */
export const PREFERENCES_KEY = 'path-interval.preferences.v1';

/** The remembered choices; null where none was made (or the stored value is not one). */
export interface PagePreferences {
  readonly machine: Machine | null;
  readonly unit: Unit | null;
}

const NONE: PagePreferences = { machine: null, unit: null };

/** What each storage holds, as last read or written here: the text writePreferences would write. */
const HELD = new WeakMap<ToolStorage, string>();

/** The stored text of a machine and a unit. */
const textOf = (machine: Machine | null, unit: Unit | null) => JSON.stringify({ machine, unit });

/** The remembered choices in `storage` (null: no storage), or none. */
export function readPreferences(storage: ToolStorage | null): PagePreferences {
  let text: string | null = null;
  try {
    text = storage?.getItem(PREFERENCES_KEY) ?? null;
  } catch {
    return NONE;
  }
  if (storage) HELD.delete(storage);
  if (text === null) return NONE;
  let json: unknown;
  try {
    json = JSON.parse(text);
  } catch {
    return NONE;
  }
  if (typeof json !== 'object' || json === null) return NONE;
  const o = json as Record<string, unknown>;
  const prefs: PagePreferences = {
    machine: o.machine === '5axis' || o.machine === '3axis' ? o.machine : null,
    unit: o.unit === 'mm' || o.unit === 'in' ? o.unit : null,
  };
  if (storage && text === textOf(prefs.machine, prefs.unit)) HELD.set(storage, text);
  return prefs;
}

/**
 * Remembers the state's machine and unit, writing only when they differ from what the storage was
 * last read or written holding; false when the storage refused (the page goes on).
 */
export function writePreferences(storage: ToolStorage | null, state: CalculatorState): boolean {
  if (storage === null) return false;
  const text = textOf(state.machine, state.unit);
  if (HELD.get(storage) === text) return true;
  try {
    storage.setItem(PREFERENCES_KEY, text);
    HELD.set(storage, text);
    return true;
  } catch {
    return false;
  }
}

/**
 * The state a visit starts from: on a bare visit (parseUrl's `bare`: its state is the default one), the
 * remembered unit's own defaults on the remembered machine; otherwise the parsed state as is.
 */
export function withPreferences(state: CalculatorState, bare: boolean, prefs: PagePreferences): CalculatorState {
  if (!bare) return state;
  const inUnit =
    prefs.unit === null || prefs.unit === state.unit
      ? state
      : withSize(defaultState(prefs.unit, state.mode), state.size ?? 'R');
  return prefs.machine === null ? inUnit : { ...inUnit, machine: prefs.machine };
}
