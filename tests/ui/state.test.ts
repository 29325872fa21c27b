import { describe, expect, it } from 'vitest';
import { convertState, defaultState, parseUrl, toSearch } from '../../src/ui/state';

describe('URL state and units', () => {
  it('round-trips a state through the query string', () => {
    const parsed = parseUrl('?R=6&Rcr=2&rho=10&h=0.1&unit=mm');
    expect(parsed.notices).toEqual([]);
    expect(parsed.state.fields).toMatchObject({ R: '6', Rcr: '2', rho: '10', h: '0.1' });
    expect(parseUrl(toSearch(parsed.state)).state).toEqual(parsed.state);
  });

  it('records inverse mode with L, and embed', () => {
    const p = parseUrl('?R=3&Rcr=1&rho=5&L=2.5&mode=inverse&unit=in&embed=1');
    expect(p.state.mode).toBe('inverse');
    expect(p.state.unit).toBe('in');
    expect(p.embed).toBe(true);
    expect(toSearch(p.state)).toBe('?R=3&Rcr=1&rho=5&mode=inverse&L=2.5&unit=in');
  });

  it('invalid or missing values fall back to defaults with a notice each; no parameters, no notice', () => {
    const p = parseUrl('?R=abc&Rcr=1&rho=5&unit=furlong');
    expect(p.state.fields.R).toBe('3');
    expect(p.notices.join(' ')).toMatch(/unit="furlong"/);
    expect(p.notices.join(' ')).toMatch(/R="abc"/);
    expect(p.notices.join(' ')).toMatch(/h is missing/);
    expect(parseUrl('').notices).toEqual([]);
    expect(parseUrl('?R=1e999').notices.join(' ')).toMatch(/not a number/);
  });

  it('converts between mm and inch, keeps angles and invalid text as they are', () => {
    const inch = convertState({ ...defaultState(), fields: { ...defaultState().fields, h: 'x' } }, 'in');
    expect(inch.fields.R).toBe('0.11811');
    expect(inch.fields.rho).toBe('5');
    expect(inch.fields.h).toBe('x');
    expect(Number(convertState(inch, 'mm').fields.R)).toBeCloseTo(3, 4);
  });
});
