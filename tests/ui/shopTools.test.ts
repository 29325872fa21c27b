/** Tools as the shop has them: inch presets, the size as a diameter on a fresh page, R= links kept. */
import { describe, expect, it } from 'vitest';
import { buildRequest } from '../../src/ui/request';
import { defaultState, PRESETS, parseUrl, presetOf, toSearch, withSize, withValues } from '../../src/ui/state';

describe('tool presets in inches', () => {
  it.each([
    ['D1/4 in, corner R0.030 in', 0.25, 0.03],
    ['D3/8 in, corner R0.060 in', 0.375, 0.06],
    ['D1/2 in, corner R0.125 in', 0.5, 0.125],
    ['D1/2 in, ball end', 0.5, 0.25],
  ])('%s fills D = %f in and Rcr = %f in, and is named again', (label, d, rcr) => {
    const preset = PRESETS.find((p) => p.label === label);
    if (!preset) throw new Error(`no preset ${label}`);
    expect(preset.sizedIn).toBe('in');
    const s = withValues(withSize(defaultState('in'), 'D'), { R: preset.R, Rcr: preset.Rcr });
    expect(Number(s.fields.R)).toBe(d);
    expect(Number(s.fields.Rcr)).toBe(rcr);
    expect(presetOf(s)?.label).toBe(label);
    expect(buildRequest(s).ok).toBe(true);
  });

  it('1/4, 3/8 and 1/2 in are all offered, beside the metric ones', () => {
    const inch = PRESETS.filter((p) => p.sizedIn === 'in').map((p) => p.label.split(',')[0]);
    expect(new Set(inch)).toEqual(new Set(['D1/4 in', 'D3/8 in', 'D1/2 in']));
    expect(PRESETS.filter((p) => p.sizedIn === 'mm').length).toBeGreaterThanOrEqual(5);
  });

  it("each has a short button name (toolChips.ts), unique, naming its label's diameter", () => {
    const chips = PRESETS.map((p) => p.chip);
    expect(new Set(chips).size).toBe(chips.length);
    for (const p of PRESETS) {
      expect(p.chip.length, p.chip).toBeLessThanOrEqual(9);
      const diameter = p.chip.split(' ')[0] ?? '';
      expect(p.label.startsWith(p.sizedIn === 'in' ? `D${diameter} in` : `${diameter},`), p.chip).toBe(true);
    }
  });
});

describe('the tool size as a diameter by default', () => {
  it('a fresh page shows D (the default tool D6), in mm and in inches', () => {
    const fresh = parseUrl('');
    expect(fresh.state.size).toBe('D');
    expect(fresh.state.fields.R).toBe('6');
    expect(fresh.notices).toEqual([]);
    const inch = parseUrl('?unit=in');
    expect(inch.state.size).toBe('D');
    expect(inch.state.fields.R).toBe('0.25'); // the inch page's default tool, D 1/4 in
    expect(toSearch(fresh.state)).toMatch(/^\?D=6&/);
  });

  it('a link with R= still gives the radius; one without R or D but with others names R missing', () => {
    const r = parseUrl('?R=3&Rcr=1&rho=5&h=0.05');
    expect(r.state.size ?? 'R').toBe('R');
    expect(r.state.fields.R).toBe('3');
    const missing = parseUrl('?Rcr=1&rho=5&h=0.05');
    expect(missing.state.size ?? 'R').toBe('R');
    expect(missing.notices.join(' ')).toMatch(/R is missing/);
    const d = parseUrl('?D=10&Rcr=1&rho=5&h=0.05');
    expect(d.state.size).toBe('D');
    expect(d.state.fields.R).toBe('10');
    expect(d.notices).toEqual([]);
  });
});
