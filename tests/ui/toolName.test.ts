/**
 * A library tool on the page (issue 28 point 3): listed in its own unit, its name carried by the
 * state and the link (as hostile text: cleaned, cut, never markup) and dropped once D or the
 * corner radius is edited (a name that no longer fits the numbers is a stale label).
 */
import { describe, expect, it } from 'vitest';
import { checkTool, type LibraryTool, TOOL_NAME_MAX_CHARS } from '../../src/core/input/toolLibrary';
import { readSavedTools, savedToolsText } from '../../src/ui/savedTools';
import { convertState, defaultState, parseUrl, toSearch, withField, withSize, withValues } from '../../src/ui/state';
import { setShownToolName, shownToolName, shownToolNameLines, TOOL_NAME_PARAM, toolLabel } from '../../src/ui/toolName';

const inchTool: LibraryTool = {
  name: 'Harvey 1/2 R.030',
  unit: 'in',
  diameterMm: 12.7,
  cornerRadiusMm: 0.762,
  flutes: 3,
};
const mmTool: LibraryTool = { name: 'D10 R1', unit: 'mm', diameterMm: 10, cornerRadiusMm: 1, flutes: null };

/** The state after choosing `tool` on a page in `unit` (as app.ts does). */
function chosen(tool: LibraryTool, unit: 'mm' | 'in') {
  const s = withValues(withSize(defaultState(unit), 'D'), { R: tool.diameterMm / 2, Rcr: tool.cornerRadiusMm });
  return { ...s, toolName: tool.name };
}

describe('a library tool is listed in its own unit', () => {
  it('an inch tool in inches, a metric tool in mm, whatever the page', () => {
    expect(toolLabel(inchTool)).toBe('Harvey 1/2 R.030: D 0.5 in, corner R 0.03 in, 3 flutes');
    expect(toolLabel(mmTool)).toBe('D10 R1: D 10 mm, corner R 1 mm');
  });

  it('saved tools keep their unit; those saved before units were kept are mm', () => {
    const text = savedToolsText([inchTool, mmTool]);
    expect(readSavedTools(text).tools.map((t) => t.unit)).toEqual(['in', 'mm']);
    const old = JSON.stringify({ tools: [{ name: 'old', diameterMm: 6, cornerRadiusMm: 1, flutes: 2 }] });
    expect(readSavedTools(old).tools[0]?.unit).toBe('mm');
    const odd = JSON.stringify({ tools: [{ name: 'odd', unit: { in: 1 }, diameterMm: 6, cornerRadiusMm: 1 }] });
    expect(readSavedTools(odd).tools[0]?.unit).toBe('mm');
  });

  it("an inch tool chosen in mm, then the inch unit taken: the fields read the tool's own numbers", () => {
    const mm = chosen(inchTool, 'mm');
    expect([mm.fields.R, mm.fields.Rcr]).toEqual(['12.7', '0.762']);
    const inch = convertState(mm, 'in');
    expect([inch.fields.R, inch.fields.Rcr]).toEqual(['0.5', '0.03']);
    expect(inch.toolName).toBe(inchTool.name);
    // Untouched fields take the inch defaults (h 0.002 in), not 0.0019685.
    expect(inch.fields.h).toBe('0.002');
  });
});

describe("the tool's name in the state and the link", () => {
  it('Copy link carries it; the link opens with it', () => {
    const s = chosen(inchTool, 'in');
    const search = toSearch(s);
    expect(new URLSearchParams(search).get(TOOL_NAME_PARAM)).toBe(inchTool.name);
    const back = parseUrl(search);
    expect(back.notices).toEqual([]);
    expect(back.state.toolName).toBe(inchTool.name);
    expect(back.state.fields.R).toBe('0.5');
  });

  it('editing D or the corner radius drops it; other fields and the unit keep it', () => {
    const s = chosen(mmTool, 'mm');
    expect(withField(s, 'h', '0.01').toolName).toBe(mmTool.name);
    expect(withField(s, 'rho', '10').toolName).toBe(mmTool.name);
    expect(withSize(s, 'R').toolName).toBe(mmTool.name);
    expect(convertState(s, 'in').toolName).toBe(mmTool.name);
    expect(withField(s, 'R', '12').toolName).toBeUndefined();
    expect(withField(s, 'Rcr', '2').toolName).toBeUndefined();
    expect(withValues(s, { R: 4, Rcr: 1 }).toolName).toBeUndefined();
    expect(new URLSearchParams(toSearch(withField(s, 'Rcr', '2'))).has(TOOL_NAME_PARAM)).toBe(false);
  });

  it('a hostile name from a link is plain text: hidden characters out, cut, never empty', () => {
    const hostile = `<img src=x onerror=alert(1)>\u202E\u0000${'A'.repeat(500)}`;
    const p = parseUrl(`?D=12.7&Rcr=0.762&rho=5&h=0.05&unit=mm&tool=${encodeURIComponent(hostile)}`);
    expect(p.state.toolName?.startsWith('<img src=x onerror=alert(1)> A')).toBe(true);
    expect(p.state.toolName).toHaveLength(TOOL_NAME_MAX_CHARS);
    expect([...(p.state.toolName ?? '')].some((c) => c < ' ' || c === '\u202e')).toBe(false);
    expect(parseUrl('?D=6&Rcr=1&rho=5&h=0.05&tool=%20%00%E2%80%AE').state.toolName).toBeUndefined();
    expect(checkTool(p.state.toolName ?? '', 6, 1, null).ok).toBe(true);
  });
});

describe('the name for the shop sheet', () => {
  it('is the one the results show, as a title line, or none', () => {
    setShownToolName(inchTool.name);
    expect(shownToolName()).toBe(inchTool.name);
    expect(shownToolNameLines()).toEqual([`Tool name: ${inchTool.name}`]);
    setShownToolName(null);
    expect(shownToolNameLines()).toEqual([]);
  });
});
