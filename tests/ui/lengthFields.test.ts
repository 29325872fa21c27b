/** The page's length fields read written lengths (1/2", 12.7 mm) as plain numbers in the page's unit. */
import { describe, expect, it } from 'vitest';
import { plainLengths } from '../../src/ui/lengthFields';
import { buildRequest } from '../../src/ui/request';
import { defaultState, toSearch, withField, withSize } from '../../src/ui/state';

describe('written lengths in the page', () => {
  it('1/2" in inch mode and 12.7 mm in mm mode ask what 0.5 in and 12.7 mm ask', () => {
    const inch = plainLengths(withField(withSize(defaultState('in'), 'D'), 'R', '1/2"'));
    expect(inch.fields.R).toBe('0.5');
    const mm = plainLengths(withField(withSize(defaultState('mm'), 'D'), 'R', '12.7 mm'));
    expect(mm.fields.R).toBe('12.7');
    const a = buildRequest(inch);
    const b = buildRequest(mm);
    expect(a.ok && a.request.mode === 'forward' && a.request.input.toolRadiusMm).toBe(6.35);
    expect(b.ok && b.request.mode === 'forward' && b.request.input.toolRadiusMm).toBe(6.35);
  });

  it('converts across units and fractions: 1/32" corner in mm, 50 um scallop, 0.2 thou in inches', () => {
    let s = withField(defaultState('mm'), 'Rcr', '1/32"');
    s = withField(s, 'h', '50 \u00b5m');
    expect(plainLengths(s).fields.Rcr).toBe('0.79375');
    expect(plainLengths(s).fields.h).toBe('0.05');
    expect(plainLengths(withField(defaultState('in'), 'h', '0.2 thou')).fields.h).toBe('0.0002');
    expect(plainLengths(withField(defaultState('in'), 'h', '200 uin')).fields.h).toBe('0.0002');
  });

  it('leaves angles, plain numbers and text that is not a length as typed (their usual messages)', () => {
    const s = withField(withField(withField(defaultState(), 'rho', '1/2'), 'Rcr', '1/0'), 'h', '0.05');
    const plain = plainLengths(s);
    expect(plain.fields.rho).toBe('1/2');
    expect(plain.fields.Rcr).toBe('1/0');
    const built = buildRequest(plain);
    expect(built.ok).toBe(false);
  });

  it('a plain state is returned as is (no new object: the page compares)', () => {
    const s = defaultState();
    expect(plainLengths(s)).toBe(s);
  });

  it('the link of a written length holds the plain number', () => {
    const s = plainLengths(withField(defaultState('in'), 'Rcr', '1/16'));
    expect(toSearch(s)).toMatch(/Rcr=0\.0625&/);
  });
});
