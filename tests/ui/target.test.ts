/** The target choice (h or Ra) in the state, the URL and the request. */
import { describe, expect, it } from 'vitest';
import { formatInputNumber } from '../../src/core/input/units';
import { maxRaMm } from '../../src/core/roughness/roughness';
import { buildRequest } from '../../src/ui/request';
import { convertState, parseUrl, toSearch, withField } from '../../src/ui/state';
import { answeredMessages, answeredRanges } from '../support/pageAnswer';

describe('target Ra in the page state', () => {
  it('target=ra&ra= round-trips; h stays the default target and out of the URL', () => {
    const p = parseUrl('?R=3&Rcr=1&rho=5&target=ra&ra=0.01&unit=mm');
    expect(p.notices).toEqual([]);
    expect(p.state.target).toBe('ra');
    expect(p.state.fields.ra).toBe('0.01');
    expect(toSearch(p.state)).toBe('?R=3&Rcr=1&rho=5&target=ra&ra=0.01&unit=mm');
    expect(parseUrl(toSearch(p.state)).state).toEqual(p.state);
    expect(toSearch(parseUrl('?R=3&Rcr=1&rho=5&h=0.05').state)).not.toMatch(/target|ra=/);
    expect(parseUrl('?R=3&Rcr=1&rho=5&target=rz&h=0.05').notices.join(' ')).toMatch(/target="rz"/);
    expect(parseUrl('?R=3&Rcr=1&rho=5&target=ra').notices.join(' ')).toMatch(/ra is missing/);
  });

  it('the request asks for the Ra in mm; inch is converted once', () => {
    const mm = buildRequest(parseUrl('?R=3&Rcr=1&rho=5&target=ra&ra=0.01&unit=mm').state);
    expect(mm.ok && mm.request.mode === 'ra' && mm.request.input.targetRaMm).toBe(0.01);
    const inch = buildRequest(convertState(parseUrl('?R=3&Rcr=1&rho=5&target=ra&ra=0.0254&unit=mm').state, 'in'));
    expect(inch.ok && inch.request.mode === 'ra' && inch.request.input.targetRaMm).toBeCloseTo(0.0254, 12);
  });

  it('an Ra beyond the maximum: the worker refuses it, the message on the Ra field names the limit in the user unit', () => {
    const state = withField(parseUrl('?R=3&Rcr=1&rho=5&target=ra&ra=1&unit=mm').state, 'ra', '0.5');
    // The page validates the fields only; the largest Ra needs a solve, which the worker makes.
    expect(buildRequest(state).ok).toBe(true);
    const max = maxRaMm({ toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 }, 'one-way');
    const text = answeredMessages(state).get('ra') ?? '';
    expect(text).toContain(`Roughness Ra must be below ${formatInputNumber(max)} mm (got 0.5)`);
  });

  it('the Ra slider stays below the maximum', () => {
    const state = parseUrl('?R=3&Rcr=1&rho=5&target=ra&ra=0.01&unit=mm').state;
    const max = maxRaMm({ toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 }, 'one-way');
    const r = answeredRanges(state).ra;
    expect(Number(r.max)).toBeLessThan(max);
    expect(Number(r.max)).toBeGreaterThan(0.9 * max);
    expect(Number(r.min)).toBeGreaterThan(0);
  });
});
