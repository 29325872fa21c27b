/**
 * The feed rate and spindle speed on the page (issue 29; src/ui/finishFields.ts, finishLazy.ts):
 * a link carries them, they give the finish question its fz (F / (n z), converted at the edge in
 * inch), and while fz is typed they are off (fz wins: left out of the question and the link).
 */
import { describe, expect, it } from 'vitest';
import { finishKeyOff, rateFzText } from '../../src/ui/finishFields';
import { finishInputs } from '../../src/ui/finishLazy';
import { parseUrl, toSearch, withField } from '../../src/ui/state';

describe('feed rate and spindle speed on the page', () => {
  it('a link carries F and rpm, and the question takes them in mm/min (inch: in/min converted)', () => {
    const mm = parseUrl('?R=3&Rcr=1&rho=5&h=0.05&unit=mm&z=4&F=960&rpm=12000');
    expect(mm.notices).toEqual([]);
    expect(toSearch(mm.state)).toContain('z=4&F=960&rpm=12000');
    expect(rateFzText(mm.state)).toBe('0.02');
    const asked = finishInputs(mm.state);
    expect([asked.values.fz, asked.values.feedRate, asked.values.spindleSpeed]).toEqual([undefined, 960, 12000]);
    const inch = parseUrl('?R=0.125&Rcr=0.03&rho=5&h=0.0002&unit=in&z=4&F=40&rpm=10000');
    expect(rateFzText(inch.state)).toBe('0.001');
    expect(finishInputs(inch.state).values.feedRate).toBeCloseTo(1016, 12);
    expect(finishInputs(inch.state).typed.feedRate).toBe('40');
  });

  it('shows no fz the finish would refuse: more than 64 teeth, or below 1 nm (65 teeth, n = 1e308)', () => {
    const rate = parseUrl('?R=3&Rcr=1&rho=5&h=0.05&unit=mm&z=4&F=960&rpm=12000').state;
    expect(rateFzText(withField(rate, 'z', '64'))).toBe('0.00125');
    expect(rateFzText(withField(rate, 'z', '65'))).toBe('');
    expect(rateFzText(withField(rate, 'n', '1e308'))).toBe('');
    expect(rateFzText(withField(rate, 'F', '0.048'))).toBe('1e-6');
    expect(rateFzText(withField(rate, 'F', '0.047'))).toBe('');
  });

  it('fz typed wins: F and n are off, left out of the question and the link; cleared, they count again', () => {
    const rate = parseUrl('?R=3&Rcr=1&rho=5&h=0.05&unit=mm&z=4&F=960&rpm=12000').state;
    const typed = withField(rate, 'fz', '0.05');
    expect(finishKeyOff(typed, 'F')).toBe(true);
    expect(finishKeyOff(typed, 'n')).toBe(true);
    expect(finishKeyOff(typed, 'z')).toBe(false);
    expect(rateFzText(typed)).toBeNull();
    const asked = finishInputs(typed);
    expect([asked.values.fz, asked.values.feedRate, asked.values.spindleSpeed]).toEqual([0.05, undefined, undefined]);
    expect(toSearch(typed)).not.toContain('F=');
    expect(toSearch(typed)).not.toContain('rpm=');
    const cleared = withField(typed, 'fz', '');
    expect(rateFzText(cleared)).toBe('0.02');
    expect(finishKeyOff(cleared, 'F')).toBe(false);
  });

  it('a link with fz and F or rpm says that fz wins (F and rpm are not used), and keeps fz alone', () => {
    const both = parseUrl('?R=3&Rcr=1&rho=5&h=0.05&unit=mm&z=4&fz=0.05&F=960&rpm=12000');
    expect(both.notices).toEqual(['fz is in the link: F and rpm are not used.']);
    expect(finishInputs(both.state).values.fz).toBe(0.05);
    expect(toSearch(both.state)).toContain('z=4&fz=0.05&unit=mm');
  });

  it('fz reads empty (read-only) for a half-given, zero or fractional-teeth pair (the worker then names the field)', () => {
    const base = parseUrl('?R=3&Rcr=1&rho=5&h=0.05&unit=mm&z=4&F=960').state;
    expect(rateFzText(base)).toBe('');
    expect(rateFzText(withField(base, 'n', '0'))).toBe('');
    expect(rateFzText(withField(withField(base, 'n', '100'), 'z', '2.5'))).toBe('');
    expect(rateFzText(withField(withField(base, 'n', '100'), 'z', ''))).toBe('');
    expect(rateFzText(withField(base, 'F', ''))).toBeNull();
    expect(finishInputs(withField(base, 'n', '0')).values.spindleSpeed).toBe(0);
  });
});
