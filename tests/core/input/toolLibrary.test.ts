/** A Fusion 360 tool library read into tools: good files, mixed units, what cannot be read, hostile input. */
import { describe, expect, it } from 'vitest';
import { FIELDS } from '../../../src/core/input/fields';
import {
  checkTool,
  cleanToolName,
  LIBRARY_MAX_CHARS,
  LIBRARY_MAX_TOOLS,
  parseFusionLibrary,
  TOOL_NAME_MAX_CHARS,
} from '../../../src/core/input/toolLibrary';

/** A Fusion 360 library entry (the fields of its JSON export the page reads, and a few it does not). */
function entry(type: string, unit: string, geometry: Record<string, unknown>, description = `${type} tool`) {
  return { type, unit, description, guid: 'x', 'product-id': 'P-1', geometry: { LCF: 20, OAL: 60, ...geometry } };
}

const library = (data: unknown[]) => JSON.stringify({ data, version: 16 });

/** The double next to `x` towards -Infinity / +Infinity (x > 0). */
const ulpStep = (x: number, by: -1 | 1) => {
  const bits = new BigInt64Array(new Float64Array([x]).buffer);
  bits[0] = (bits[0] as bigint) + BigInt(by);
  return new Float64Array(bits.buffer)[0] as number;
};
const nextDown = (x: number) => ulpStep(x, -1);
const nextUp = (x: number) => ulpStep(x, 1);

describe('a Fusion 360 tool library', () => {
  it('reads bull nose, ball and flat end mills in mm and inches (mixed in one file)', () => {
    const read = parseFusionLibrary(
      library([
        entry('bull nose end mill', 'millimeters', { DC: 10, RE: 1, NOF: 4 }, 'D10 R1 bull'),
        entry('ball end mill', 'millimeters', { DC: 6, RE: 3, NOF: 2 }),
        entry('ball end mill', 'inches', { DC: 0.25 }, '1/4 ball'),
        entry('flat end mill', 'inches', { DC: 0.5, NOF: 3 }, '1/2 flat'),
        entry('bull nose end mill', 'inches', { DC: 0.375, RE: 0.03 }, '3/8 x .030'),
      ]),
    );
    expect(read.problems).toEqual([]);
    expect(read.tools).toEqual([
      { name: 'D10 R1 bull', unit: 'mm', diameterMm: 10, cornerRadiusMm: 1, flutes: 4 },
      { name: 'ball end mill tool', unit: 'mm', diameterMm: 6, cornerRadiusMm: 3, flutes: 2 },
      { name: '1/4 ball', unit: 'in', diameterMm: 6.35, cornerRadiusMm: 3.175, flutes: null },
      { name: '1/2 flat', unit: 'in', diameterMm: 12.7, cornerRadiusMm: 0, flutes: 3 },
      { name: '3/8 x .030', unit: 'in', diameterMm: 9.525, cornerRadiusMm: 0.762, flutes: null },
    ]);
  });

  it('names the tool and the field of what it cannot read, and keeps the rest', () => {
    const read = parseFusionLibrary(
      library([
        entry('bull nose end mill', 'millimeters', { RE: 1 }, 'no diameter'),
        entry('bull nose end mill', 'millimeters', { DC: 6, RE: 4 }, 'corner too big'),
        entry('bull nose end mill', 'millimeters', { DC: 6 }, 'no corner'),
        entry('bull nose end mill', 'millimeters', { DC: '6', RE: 1 }, 'text diameter'),
        entry('bull nose end mill', 'feet', { DC: 6, RE: 1 }, 'odd unit'),
        entry('drill', 'millimeters', { DC: 5 }, 'Drill 5'),
        entry('bull nose end mill', 'millimeters', { DC: -6, RE: 1 }, 'negative'),
        { type: 'flat end mill', unit: 'millimeters', description: 'no geometry' },
        42,
        entry('flat end mill', 'millimeters', { DC: 8 }, 'good one'),
      ]),
    );
    expect(read.tools.map((t) => t.name)).toEqual(['good one']);
    expect(read.problems).toEqual([
      'Tool 1 "no diameter": geometry.DC (the diameter) is missing.',
      'Tool 2 "corner too big": geometry.RE (the corner radius) must be from 0 to D/2 = 3 mm (got 4 mm).',
      'Tool 3 "no corner": geometry.RE (the corner radius) is missing.',
      'Tool 4 "text diameter": geometry.DC (the diameter) is missing or not a number.',
      'Tool 5 "odd unit": unit "feet" is not millimeters or inches.',
      'Tool 6 "Drill 5": type "drill" is not a flat, bull nose or ball end mill; skipped.',
      'Tool 7 "negative": geometry.DC (the diameter) must be from 0.002 to 2000 mm (got -6 mm).',
      'Tool 8 "no geometry": geometry is missing.',
      'Tool 9: not a tool (an object with type, unit and geometry).',
    ]);
  });

  it('a ball end whose RE rounds D/2 in the last digit is a ball end', () => {
    const read = parseFusionLibrary(library([entry('ball end mill', 'inches', { DC: 0.1, RE: 0.05000000000000001 })]));
    expect(read.tools[0]?.cornerRadiusMm).toBe(read.tools[0] ? read.tools[0].diameterMm / 2 : Number.NaN);
  });

  it.each([
    ['not JSON', 'this is not json {', /not JSON/],
    ['an empty file', '', /not JSON/],
    ['JSON without data', '{"tools": []}', /no "data" list/],
    ['a list', '[1, 2]', /no "data" list/],
    ['null', 'null', /no "data" list/],
    ['a huge file', ' '.repeat(LIBRARY_MAX_CHARS + 1), /over 20 MB/],
  ])('%s: no tools, one line', (_, text, line) => {
    const read = parseFusionLibrary(text);
    expect(read.tools).toEqual([]);
    expect(read.problems).toHaveLength(1);
    expect(read.problems[0]).toMatch(line);
  });

  it('a library of more tools than it reads: the first ones, and a line', () => {
    const many = Array.from({ length: LIBRARY_MAX_TOOLS + 3 }, (_, i) =>
      entry('flat end mill', 'millimeters', { DC: 1 + (i % 10) }),
    );
    const read = parseFusionLibrary(library(many));
    expect(read.tools).toHaveLength(LIBRARY_MAX_TOOLS);
    expect(read.problems).toEqual([`Only the first ${LIBRARY_MAX_TOOLS} of ${LIBRARY_MAX_TOOLS + 3} tools were read.`]);
  });

  it('a library of exactly LIBRARY_MAX_TOOLS tools is read whole, with no line (one more gets the line)', () => {
    const make = (count: number) =>
      library(Array.from({ length: count }, (_, i) => entry('flat end mill', 'millimeters', { DC: 1 + (i % 10) })));
    const atCap = parseFusionLibrary(make(LIBRARY_MAX_TOOLS));
    expect(atCap.tools).toHaveLength(LIBRARY_MAX_TOOLS);
    expect(atCap.problems).toEqual([]);
    const over = parseFusionLibrary(make(LIBRARY_MAX_TOOLS + 1));
    expect(over.tools).toHaveLength(LIBRARY_MAX_TOOLS);
    expect(over.problems).toEqual([`Only the first ${LIBRARY_MAX_TOOLS} of ${LIBRARY_MAX_TOOLS + 1} tools were read.`]);
  });

  it('hostile names are kept as plain text: markup as typed, control characters out, long names cut', () => {
    const hostile = '<img src=x onerror="alert(1)">\u0000\u001b[31m';
    const read = parseFusionLibrary(
      library([
        entry('flat end mill', 'millimeters', { DC: 6 }, hostile),
        entry('flat end mill', 'millimeters', { DC: 6 }, 'x'.repeat(1_000_000)),
        { ...entry('flat end mill', 'millimeters', { DC: 6 }), description: { toString: 1 }, 'product-id': '' },
      ]),
    );
    expect(read.tools[0]?.name).toBe('<img src=x onerror="alert(1)"> [31m');
    expect(read.tools[1]?.name).toHaveLength(TOOL_NAME_MAX_CHARS);
    expect(read.tools[1]?.name.endsWith('\u2026')).toBe(true);
    expect(read.tools[2]?.name).toBe('tool 3');
  });
});

describe('a tool checked against the calculator', () => {
  it('D within twice the tool radius limits, corner 0 to D/2, flutes 1 to 99', () => {
    expect(checkTool('a', 6, 1, 4)).toEqual({
      ok: true,
      tool: { name: 'a', unit: 'mm', diameterMm: 6, cornerRadiusMm: 1, flutes: 4 },
    });
    expect(checkTool('a', 6, 3, null).ok).toBe(true);
    expect(checkTool('a', 6, 3.0001, null)).toMatchObject({ ok: false, field: 'corner radius' });
    expect(checkTool('a', 6, -0.1, null)).toMatchObject({ ok: false, field: 'corner radius' });
    expect(checkTool('a', Number.POSITIVE_INFINITY, 1, null)).toMatchObject({ ok: false, field: 'D' });
    expect(checkTool('a', Number.NaN, 1, null)).toMatchObject({ ok: false, field: 'D' });
    expect(checkTool('a', 2001, 1, null)).toMatchObject({ ok: false, field: 'D' });
    expect(checkTool('a', 6, 1, 2.5)).toMatchObject({ ok: false, field: 'flutes' });
    expect(checkTool('a', 6, 1, 0)).toMatchObject({ ok: false, field: 'flutes' });
    expect(cleanToolName('  two\n\tlines  ')).toBe('two lines');
  });

  it('D at the ends of its range: 2 x 0.001 mm and 2 x 1000 mm are tools, one ulp beyond is refused', () => {
    const [minD, maxD] = [2 * (FIELDS.R.range.min as number), 2 * (FIELDS.R.range.max as number)];
    expect([minD, maxD]).toEqual([0.002, 2000]);
    for (const d of [minD, maxD]) expect(checkTool('end', d, 0, null), `D = ${d}`).toMatchObject({ ok: true });
    // The library reads the same ends (its message names the range).
    const ends = parseFusionLibrary(
      library([
        entry('flat end mill', 'millimeters', { DC: minD }, 'smallest'),
        entry('flat end mill', 'millimeters', { DC: maxD }, 'largest'),
      ]),
    );
    expect(ends.problems).toEqual([]);
    expect(ends.tools.map((t) => t.diameterMm)).toEqual([minD, maxD]);
    const below = nextDown(minD);
    const above = nextUp(maxD);
    expect(checkTool('end', below, 0, null)).toEqual({
      ok: false,
      field: 'D',
      why: `must be from 0.002 to 2000 mm (got ${below} mm)`,
    });
    expect(checkTool('end', above, 0, null)).toMatchObject({ ok: false, field: 'D' });
  });
});
