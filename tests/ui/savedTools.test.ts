/** Saved tools in the browser's storage: kept, replaced by name, and corrupt or refusing storage tolerated. */
import { describe, expect, it } from 'vitest';
import {
  readSavedTools,
  SAVED_TOOLS_KEY,
  SAVED_TOOLS_MAX,
  SavedTools,
  type ToolStorage,
} from '../../src/ui/savedTools';

const tool = (name: string, diameterMm = 6, cornerRadiusMm = 1, flutes: number | null = 4) => ({
  name,
  unit: 'mm' as const,
  diameterMm,
  cornerRadiusMm,
  flutes,
});

function memory(initial: string | null = null): ToolStorage & { data: Map<string, string> } {
  const data = new Map<string, string>();
  if (initial !== null) data.set(SAVED_TOOLS_KEY, initial);
  return { data, getItem: (k) => data.get(k) ?? null, setItem: (k, v) => void data.set(k, v) };
}

describe('saved tools', () => {
  it('are kept in the storage and read back by another page', () => {
    const storage = memory();
    const a = new SavedTools(storage);
    expect(a.tools).toEqual([]);
    expect(a.save(tool('D6 R1'))).toBe(true);
    expect(a.save(tool('D10 R2', 10, 2, 3))).toBe(true);
    expect(a.save(tool('D6 R1', 6, 0.5, 2))).toBe(true); // same name: replaced
    const b = new SavedTools(storage);
    expect(b.tools).toEqual([tool('D6 R1', 6, 0.5, 2), tool('D10 R2', 10, 2, 3)]);
    expect(b.problem).toBeNull();
    b.remove('D10 R2');
    expect(new SavedTools(storage).tools).toEqual([tool('D6 R1', 6, 0.5, 2)]);
  });

  it.each([
    ['not JSON', '{{{', /not JSON/],
    ['not a list', '{"tools": 5}', /could not be read/],
    ['null', 'null', /could not be read/],
  ])('corrupt storage (%s): an empty list and a line', (_, text, line) => {
    const s = new SavedTools(memory(text));
    expect(s.tools).toEqual([]);
    expect(s.problem).toMatch(line);
  });

  it('drops hostile or impossible entries, keeps the good ones', () => {
    const text = JSON.stringify({
      tools: [
        tool('good'),
        tool('corner too big', 6, 4),
        { name: 5, diameterMm: 6, cornerRadiusMm: 1 },
        tool('', 6, 1),
        { name: 'no numbers' },
        null,
        'string',
        { ...tool('nan'), diameterMm: 'NaN' },
        tool('<b>bold</b>'),
      ],
    });
    const read = readSavedTools(text);
    expect(read.tools.map((t) => t.name)).toEqual(['good', '<b>bold</b>']);
    expect(read.problem).toBe('7 saved tools could not be read and were left out.');
  });

  it('keeps at most SAVED_TOOLS_MAX, the newest first', () => {
    const s = new SavedTools(memory());
    for (let i = 0; i < SAVED_TOOLS_MAX + 5; i++) s.save(tool(`t${i}`));
    expect(s.tools).toHaveLength(SAVED_TOOLS_MAX);
    expect(s.tools[0]?.name).toBe(`t${SAVED_TOOLS_MAX + 4}`);
  });

  it('more saved tools than the cap: the newest SAVED_TOOLS_MAX kept, the rest said to be over it (not unreadable)', () => {
    const many = (count: number) => JSON.stringify({ tools: Array.from({ length: count }, (_, i) => tool(`t${i}`)) });
    const read = readSavedTools(many(30_000));
    expect(read.tools).toHaveLength(SAVED_TOOLS_MAX);
    expect(read.tools.at(-1)?.name).toBe(`t${SAVED_TOOLS_MAX - 1}`);
    expect(read.problem).toBe('29800 saved tools were over the limit of 200 and left out (the 200 newest are kept).');
    expect(readSavedTools(many(SAVED_TOOLS_MAX + 1)).problem).toBe(
      '1 saved tool was over the limit of 200 and left out (the 200 newest are kept).',
    );
    // Exactly at the cap: all kept, nothing to say.
    const atCap = readSavedTools(many(SAVED_TOOLS_MAX));
    expect(atCap.tools).toHaveLength(SAVED_TOOLS_MAX);
    expect(atCap.problem).toBeNull();
  });

  it('unreadable entries and entries over the cap are counted apart; an unreadable one does not take a kept place', () => {
    const list = [
      tool('bad', 6, 4),
      null,
      ...Array.from({ length: SAVED_TOOLS_MAX }, (_, i) => tool(`t${i}`)),
      tool('also bad', -1),
      ...Array.from({ length: 4 }, (_, i) => tool(`old${i}`)),
    ];
    const read = readSavedTools(JSON.stringify({ tools: list }));
    expect(read.tools.map((t) => t.name)).toEqual(Array.from({ length: SAVED_TOOLS_MAX }, (_, i) => `t${i}`));
    expect(read.problem).toBe(
      '2 saved tools could not be read and were left out. ' +
        '5 saved tools were over the limit of 200 and left out (the 200 newest are kept).',
    );
    expect(readSavedTools(JSON.stringify({ tools: [tool('ok'), 'x'] })).problem).toBe(
      '1 saved tool could not be read and was left out.',
    );
  });

  it('a storage that throws (disabled, full) keeps the list in memory with a line', () => {
    const throwing: ToolStorage = {
      getItem: () => {
        throw new Error('SecurityError');
      },
      setItem: () => {
        throw new Error('QuotaExceededError');
      },
    };
    const s = new SavedTools(throwing);
    expect(s.problem).toMatch(/does not let the page keep saved tools/);
    expect(s.save(tool('a'))).toBe(false);
    expect(s.tools.map((t) => t.name)).toEqual(['a']);
    expect(s.problem).toMatch(/did not keep the tool/);
    expect(new SavedTools(null).problem).toMatch(/does not let/);
  });
});
