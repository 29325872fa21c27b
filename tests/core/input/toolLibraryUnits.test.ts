/**
 * Each library tool keeps its own unit (issue 28 point 3): an inch tool stays an inch tool (its
 * lengths exact in mm), a name that tries to hide or reorder text is cleaned, and a unit that is
 * a property of every object is not a unit.
 */
import { describe, expect, it } from 'vitest';
import { checkTool, cleanToolName, parseFusionLibrary, TOOL_NAME_MAX_CHARS } from '../../../src/core/input/toolLibrary';

const library = (data: unknown[]) => JSON.stringify({ data });
const tool = (unit: string, geometry: Record<string, unknown>, description: string, type = 'bull nose end mill') => ({
  type,
  unit,
  description,
  geometry,
});

describe("a library tool's unit", () => {
  it('inches and millimeters each kept with the tool, mixed in one file; lengths exact in mm', () => {
    const read = parseFusionLibrary(
      library([
        tool('inches', { DC: 0.5, RE: 0.03 }, 'Harvey 1/2 R.030'),
        tool('millimeters', { DC: 12.7, RE: 0.762 }, 'the same in mm'),
        tool('Inches', { DC: 0.375, RE: 0.06 }, 'upper case'),
      ]),
    );
    expect(read.problems).toEqual([]);
    expect(read.tools.map((t) => [t.name, t.unit, t.diameterMm, t.cornerRadiusMm])).toEqual([
      ['Harvey 1/2 R.030', 'in', 12.7, 0.762],
      ['the same in mm', 'mm', 12.7, 0.762],
      ['upper case', 'in', 9.525, 1.524],
    ]);
  });

  it('a checked tool is in mm unless said otherwise', () => {
    expect(checkTool('a', 6, 1, null)).toMatchObject({ ok: true, tool: { unit: 'mm' } });
    expect(checkTool('a', 12.7, 0.762, 3, 'in')).toMatchObject({ ok: true, tool: { unit: 'in' } });
  });

  it.each(['constructor', '__proto__', 'toString', 'hasOwnProperty', 'feet', ''])(
    'a unit "%s" is not millimeters or inches (one line, the others kept)',
    (unit) => {
      const read = parseFusionLibrary(
        library([tool(unit, { DC: 6, RE: 1 }, 'odd'), tool('millimeters', { DC: 6, RE: 1 }, 'good')]),
      );
      expect(read.tools.map((t) => t.name)).toEqual(['good']);
      expect(read.problems).toEqual([`Tool 1 "odd": unit "${unit}" is not millimeters or inches.`]);
    },
  );

  it.each(['constructor', '__proto__', 'valueOf'])('a type "%s" is not an end mill', (type) => {
    const read = parseFusionLibrary(library([tool('millimeters', { DC: 6, RE: 1 }, 'odd', type)]));
    expect(read.tools).toEqual([]);
    expect(read.problems[0]).toMatch(/is not a flat, bull nose or ball end mill; skipped\.$/);
  });
});

describe('a hostile name', () => {
  it('loses the characters that reorder or hide text, keeps markup as plain text', () => {
    // U+202E turns the rest of a line right to left: "gpj.exe" would read "exe.jpg".
    expect(cleanToolName('safe\u202Egpj.exe')).toBe('safe gpj.exe');
    expect(cleanToolName('a\u200Bb\u2066c\u2069d\uFEFFe\u0085f')).toBe('a b c d e f');
    expect(cleanToolName('<b onmouseover="x()">1/2"</b>')).toBe('<b onmouseover="x()">1/2"</b>');
  });

  it(`is cut at ${TOOL_NAME_MAX_CHARS} characters, whatever its length`, () => {
    const name = cleanToolName('x'.repeat(1_000_000));
    expect(name).toHaveLength(TOOL_NAME_MAX_CHARS);
    expect(name.endsWith('\u2026')).toBe(true);
  });
});
