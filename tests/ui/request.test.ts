/** The edge: what was typed, in the user's unit, becomes one validated request in mm. */
import { describe, expect, it } from 'vitest';
import { buildRequest, fieldMessages, stateMessages } from '../../src/ui/request';
import { type CalculatorState, convertState, defaultState, parseUrl, withField } from '../../src/ui/state';
import { answeredMessages } from '../support/pageAnswer';

const state = (search: string): CalculatorState => parseUrl(search).state;

describe('requests from the fields', () => {
  it('forward and inverse requests carry validated core inputs in mm, with tilt and pattern', () => {
    const f = buildRequest(state('?R=3&Rcr=1&rho=5&tilt=-7.5&pattern=zigzag&h=0.05&unit=mm'));
    expect(f).toEqual({
      ok: true,
      request: {
        mode: 'forward',
        input: {
          toolRadiusMm: 3,
          cornerRadiusMm: 1,
          leadAngleDeg: 5,
          tiltAngleDeg: -7.5,
          pattern: 'zigzag',
          surface: { kind: 'plane' },
          scallopHeightMm: 0.05,
        },
      },
    });
    const i = buildRequest(state('?R=3&Rcr=1&rho=5&mode=inverse&L=2.5&unit=mm'));
    expect(i.ok && i.request.mode === 'inverse' && i.request.input.intervalMm).toBe(2.5);
  });

  it('inch fields are converted once, here: lengths times 25.4, angles untouched', () => {
    const r = buildRequest(state('?R=0.25&Rcr=0.04&rho=5&tilt=3&h=0.002&unit=in'));
    if (!r.ok || r.request.mode !== 'forward') throw new Error('valid');
    expect(r.request.input.toolRadiusMm).toBe(0.25 * 25.4);
    expect(r.request.input.cornerRadiusMm).toBe(0.04 * 25.4);
    expect(r.request.input.scallopHeightMm).toBe(0.002 * 25.4);
    expect(r.request.input.leadAngleDeg).toBe(5);
    expect(r.request.input.tiltAngleDeg).toBe(3);
  });

  it('errors are worded in the user unit, quote the text as typed, and carry no float noise', () => {
    const s = state('?R=0.11811&Rcr=0.2&rho=5&h=0.002&unit=in');
    const r = buildRequest(s);
    if (r.ok) throw new Error('Rcr > R');
    const m = fieldMessages(s, r.errors);
    expect(m.get('Rcr')).toBe(
      'Corner radius Rcr must not exceed the tool radius R = 0.11811 in (got 0.2); Rcr = R is a ball end mill.',
    );
    const t = withField(defaultState(), 'tilt', 'abc');
    const rt = buildRequest(t);
    if (rt.ok) throw new Error('tilt abc');
    expect(fieldMessages(t, rt.errors).get('tilt')).toMatch(/Tilt angle beta must be a number \(got "abc"\)/);
    // L beyond the diameter: the worker's refusal (the widest step-over is a solve), worded as the page's own.
    const wide = state('?R=3&Rcr=1&rho=5&mode=inverse&L=7&unit=mm');
    expect(answeredMessages(wide).get('L')).toMatch(/Step-over L must be below the tool diameter 2R = 6 mm \(got 7\)/);
  });

  it('a length too large for a double once in mm (1e308 in) names its limit in inch', () => {
    const s = withField(state('?R=0.125&Rcr=0.03&rho=5&h=0.002&unit=in'), 'R', '1e308');
    const built = buildRequest(s);
    expect(stateMessages(s, built, null).get('R')).toBe('Tool radius R must be at most 39.3701 in (got 1e308).');
  });

  it('text in an optional teeth-and-feed field is named on it and the step-over is still asked', () => {
    for (const key of ['z', 'fz', 'runout', 'F', 'n'] as const) {
      const feed = key === 'F' || key === 'n' ? 'F=960&rpm=12000' : 'fz=0.05';
      const s = withField(state(`?R=3&Rcr=1&rho=5&h=0.05&unit=mm&z=3&${feed}`), key, 'abc');
      const built = buildRequest(s);
      expect(built.ok, key).toBe(true);
      expect(stateMessages(s, built, null).get(key), key).toMatch(/must be a number \(got "abc"\)/);
    }
  });

  it('a unit switch keeps an edited question (to 1e-12) and the field texts free of float noise', () => {
    const edited = withField(defaultState(), 'Rcr', '1');
    const inch = convertState(edited, 'in');
    expect(inch.fields.Rcr).toBe('0.03937007874016');
    const a = buildRequest(edited);
    const b = buildRequest(inch);
    if (!a.ok || !b.ok || a.request.mode !== 'forward' || b.request.mode !== 'forward') throw new Error('valid');
    expect(Math.abs(b.request.input.cornerRadiusMm - a.request.input.cornerRadiusMm)).toBeLessThan(1e-12);
  });
});
