/** The CAM programmer's quick lookup, in Node: size switch, presets, decimal comma, readable units, typing gate. */
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { formatLenUnit, formatSignedLenUnit } from '../../src/ui/format';
import { buildRequest, fieldMessages } from '../../src/ui/request';
import { sliderRanges } from '../../src/ui/sliders';
import {
  defaultState,
  parseField,
  parseUrl,
  presetOf,
  toSearch,
  withField,
  withSize,
  withValues,
} from '../../src/ui/state';
import { TYPING_PAUSE_MS, TypingGate } from '../../src/ui/typing';
import { answeredMessages } from '../support/pageAnswer';

describe('tool size as catalogues give it', () => {
  it('the diameter D = 2R is asked as the radius R: D10 gives the answer of R = 5', () => {
    const d = withField(withSize(defaultState(), 'D'), 'R', '10');
    const r = withField(defaultState(), 'R', '5');
    const a = buildRequest(d);
    const b = buildRequest(r);
    expect(a.ok && a.request.mode === 'forward' && a.request.input.toolRadiusMm).toBe(5);
    expect(a.ok && b.ok && a.request).toEqual(b.ok && b.request);
  });

  it('switching converts the field (3 -> 6 -> 3) and keeps text that is not a number', () => {
    const d = withSize(defaultState(), 'D');
    expect(d.fields.R).toBe('6');
    expect(withSize(d, 'R').fields.R).toBe('3');
    expect(withSize(withField(defaultState(), 'R', 'abc'), 'D').fields.R).toBe('abc');
  });

  it('the URL holds the switch as D= or R=; with both, R wins and a notice says so', () => {
    const d = withSize(defaultState(), 'D');
    expect(toSearch(d)).toMatch(/^\?D=6&/);
    const back = parseUrl(toSearch(d));
    expect(back.state.size).toBe('D');
    expect(back.state.fields.R).toBe('6');
    expect(back.notices).toEqual([]);
    const both = parseUrl('?R=3&D=10&Rcr=1&rho=5&h=0.05');
    expect(both.state.size ?? 'R').toBe('R');
    expect(both.state.fields.R).toBe('3');
    expect(both.notices.join(' ')).toMatch(/both R and D are in the link; using R=3 \(D ignored\)/);
    const bad = parseUrl('?D=x&Rcr=1&rho=5&h=0.05');
    expect(bad.state.size).toBe('D');
    expect(bad.state.fields.R).toBe('6');
    expect(bad.notices.join(' ')).toMatch(/D="x" in the link is not a number; using the default 6/);
  });

  it('errors on the size name D with limits converted: Rcr must be at most D/2 = 3 mm', () => {
    const d = withField(withSize(defaultState(), 'D'), 'Rcr', '4');
    const built = buildRequest(d);
    expect(built.ok).toBe(false);
    if (built.ok) return;
    expect(fieldMessages(d, built.errors).get('Rcr')).toMatch(
      /^Corner radius Rcr must be at most D\/2 = 3 mm \(got 4\)/,
    );
    const tiny = withField(withSize(defaultState(), 'D'), 'R', '0.001');
    const t = buildRequest(tiny);
    if (t.ok) throw new Error('D = 0.001 mm is below the smallest tool');
    expect(fieldMessages(tiny, t.errors).get('R')).toBe('Tool diameter D must be at least 0.002 mm (got 0.001).');
    // L beyond the diameter: the worker's refusal (the widest step-over is a solve), on the field as the page's own.
    const inverse = withField(withSize({ ...defaultState(), mode: 'inverse' }, 'D'), 'L', '7');
    expect(answeredMessages(inverse).get('L')).toMatch(/below the tool diameter D = 6 mm \(got 7\)/);
  });

  it('the slider runs over diameters in D mode', () => {
    expect(Number(sliderRanges(withSize(defaultState(), 'D')).R.max)).toBe(
      2 * Number(sliderRanges(defaultState()).R.max),
    );
  });

  it('presets are named by diameter and corner radius; an edit away from them is "custom"', () => {
    expect(presetOf(defaultState())?.label).toBe('D6, corner R1 (paper Tool 1)');
    expect(presetOf(withSize(defaultState(), 'D'))?.label).toBe('D6, corner R1 (paper Tool 1)');
    // The inch page's own default tool (unitDefaults.ts), not the paper's converted.
    expect(presetOf(defaultState('in'))?.label).toBe('D1/4 in, corner R0.030 in');
    expect(presetOf(withField(defaultState(), 'Rcr', '1.1'))).toBeNull();
    const d10 = withValues(withSize(defaultState(), 'D'), { R: 5, Rcr: 1 });
    expect(d10.fields.R).toBe('10');
    expect(presetOf(d10)?.label).toBe('D10, corner R1');
  });
});

describe('number entry like people type', () => {
  it('a decimal comma reads as a decimal point; other commas do not', () => {
    expect(parseField('0,05')).toBe(0.05);
    expect(parseField(' ,5 ')).toBe(0.5);
    expect(parseField('1,000.5')).toBeNull();
    expect(parseField('1,2,3')).toBeNull();
    const s = withField(defaultState(), 'h', '0,05');
    const built = buildRequest(s);
    expect(built.ok && built.request.mode === 'forward' && built.request.input.scallopHeightMm).toBe(0.05);
  });

  describe('the typing gate', () => {
    beforeEach(() => vi.useFakeTimers());
    afterEach(() => vi.useRealTimers());

    it('commits a held-back text after a pause with no keystroke, or at once on release', () => {
      const commit = vi.fn();
      const gate = new TypingGate(commit);
      gate.hold();
      vi.advanceTimersByTime(TYPING_PAUSE_MS - 50);
      gate.hold(); // another keystroke restarts the pause
      vi.advanceTimersByTime(TYPING_PAUSE_MS - 50);
      expect(commit).not.toHaveBeenCalled();
      expect(gate.holding).toBe(true);
      vi.advanceTimersByTime(50);
      expect(commit).toHaveBeenCalledTimes(1);
      expect(gate.holding).toBe(false);
      gate.hold();
      expect(gate.release()).toBe(true);
      expect(gate.release()).toBe(false);
      vi.advanceTimersByTime(2 * TYPING_PAUSE_MS);
      expect(commit).toHaveBeenCalledTimes(1);
    });
  });
});

describe('lengths in the unit they read best in', () => {
  it('below 0.1 mm in um, below 0.01 in in thou, at the same resolution and 4 significant digits', () => {
    expect(formatLenUnit(2.887184825934, 'mm')).toBe('2.8872 mm');
    expect(formatLenUnit(0.1, 'mm')).toBe('0.1000 mm');
    expect(formatLenUnit(0.05, 'mm', 'height')).toBe('50.00 \u00b5m');
    expect(formatLenUnit(0.0124171, 'mm', 'fine')).toBe('12.417 \u00b5m');
    expect(formatLenUnit(8.942e-5, 'mm')).toBe('0.08942 \u00b5m');
    expect(formatLenUnit(0.2 * 25.4, 'in')).toBe('0.20000 in');
    expect(formatLenUnit(0.0002 * 25.4, 'in', 'height')).toBe('0.2000 thou');
    expect(formatLenUnit(0.005 * 25.4, 'in')).toBe('5.000 thou');
    expect(formatLenUnit(0, 'mm')).toBe('0.0000 mm');
    expect(formatSignedLenUnit(-0.0312, 'mm')).toBe('-31.20 \u00b5m');
    expect(formatSignedLenUnit(1.2, 'mm')).toBe('+1.2000 mm');
    expect(formatLenUnit(null, 'mm')).toBe('\u2014');
  });
});
