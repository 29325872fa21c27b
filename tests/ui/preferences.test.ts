/**
 * Issue 28, point 1: the machine (and the unit) remembered across visits; a bare visit starts from
 * them, a link and an embed never change meaning; the storage is untrusted and may throw.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { PREFERENCES_KEY, readPreferences, withPreferences, writePreferences } from '../../src/ui/preferences';
import type { ToolStorage } from '../../src/ui/savedTools';
import { defaultState, isBareVisit, parseUrl } from '../../src/ui/state';

function memory(): ToolStorage & { map: Map<string, string> } {
  const map = new Map<string, string>();
  return { map, getItem: (k) => map.get(k) ?? null, setItem: (k, v) => void map.set(k, v) };
}
const throwing: ToolStorage = {
  getItem: () => {
    throw new Error('denied');
  },
  setItem: () => {
    throw new Error('full');
  },
};

describe('page preferences', () => {
  it('a shop that chose three-axis in inches starts there on its next bare visit', () => {
    const storage = memory();
    expect(writePreferences(storage, { ...defaultState('in'), machine: '3axis' })).toBe(true);
    const prefs = readPreferences(storage);
    expect(prefs).toEqual({ machine: '3axis', unit: 'in' });
    const start = withPreferences(parseUrl('').state, true, prefs);
    expect(start.machine).toBe('3axis');
    expect(start.unit).toBe('in');
    expect(start.fields).toEqual(parseUrl('?unit=in').state.fields);
    // Page settings alone keep a visit bare.
    expect(withPreferences(parseUrl('?theme=dark').state, parseUrl('?theme=dark').bare, prefs).machine).toBe('3axis');
  });

  it('a link keeps its meaning: a five-axis link (no machine=) stays five-axis, in its own unit', () => {
    const prefs = { machine: '3axis', unit: 'in' } as const;
    const search = '?R=3&Rcr=1&rho=5&h=0.05';
    const s = withPreferences(parseUrl(search).state, parseUrl(search).bare, prefs);
    expect(s.machine).toBe('5axis');
    expect(s.unit).toBe('mm');
    for (const q of ['?embed=1', '?machine=5axis', '?unit=mm', '?view=profile&embed=1'])
      expect(isBareVisit(q)).toBe(false);
  });

  it('a first visit keeps the teacher default (five-axis, mm)', () => {
    const s = withPreferences(parseUrl('').state, parseUrl('').bare, readPreferences(memory()));
    expect([s.machine, s.unit]).toEqual(['5axis', 'mm']);
    expect(s).toEqual(parseUrl('').state);
  });

  it('hostile or broken storage: only the known words count; a throwing storage is empty (seed 2801)', () => {
    expect(readPreferences(throwing)).toEqual({ machine: null, unit: null });
    expect(writePreferences(throwing, defaultState())).toBe(false);
    expect(readPreferences(null)).toEqual({ machine: null, unit: null });
    fc.assert(
      fc.property(fc.oneof(fc.string(), fc.json()), (text) => {
        const storage = memory();
        storage.map.set(PREFERENCES_KEY, text);
        const p = readPreferences(storage);
        expect([null, '5axis', '3axis']).toContain(p.machine);
        expect([null, 'mm', 'in']).toContain(p.unit);
      }),
      { seed: 2801, numRuns: 300 },
    );
  });
});

describe('page preferences: written only when they change (no synchronous write per keystroke or drag step)', () => {
  function counting() {
    const inner = memory();
    const writes: string[] = [];
    const storage: ToolStorage = {
      getItem: (k) => inner.getItem(k),
      setItem: (k, v) => {
        writes.push(v);
        inner.setItem(k, v);
      },
    };
    return { storage, writes };
  }

  it('a drag that changes neither the machine nor the unit writes once; each change writes once more', () => {
    const { storage, writes } = counting();
    const mm = defaultState('mm');
    for (let i = 0; i < 50; i++)
      expect(writePreferences(storage, { ...mm, fields: { ...mm.fields, h: `0.0${i}` } })).toBe(true);
    expect(writes).toHaveLength(1);
    expect(writePreferences(storage, { ...mm, unit: 'in' })).toBe(true);
    expect(writePreferences(storage, { ...mm, unit: 'in' })).toBe(true);
    expect(writePreferences(storage, { ...mm, machine: '3axis' })).toBe(true);
    expect(writes).toHaveLength(3);
    expect(readPreferences(storage)).toEqual({ machine: '3axis', unit: 'mm' });
  });

  it('what a visit read is not written again; a refused write is tried again at the next change-free step', () => {
    const { storage, writes } = counting();
    storage.setItem(PREFERENCES_KEY, JSON.stringify({ machine: '3axis', unit: 'in' }));
    writes.length = 0;
    expect(readPreferences(storage)).toEqual({ machine: '3axis', unit: 'in' });
    expect(writePreferences(storage, { ...defaultState('in'), machine: '3axis' })).toBe(true);
    expect(writes).toEqual([]);
    // Another form in the storage (not one this page writes) is written over at the first step.
    storage.setItem(PREFERENCES_KEY, '{"unit":"in","machine":"3axis","x":1}');
    writes.length = 0;
    readPreferences(storage);
    writePreferences(storage, { ...defaultState('in'), machine: '3axis' });
    expect(writes).toHaveLength(1);
    let full = true;
    const stored: string[] = [];
    const flaky: ToolStorage = {
      getItem: () => null,
      setItem: (_, v) => {
        if (full) throw new Error('full');
        stored.push(v);
      },
    };
    expect(writePreferences(flaky, defaultState())).toBe(false);
    full = false;
    expect(writePreferences(flaky, defaultState())).toBe(true);
    expect(stored).toHaveLength(1);
  });
});
