/**
 * The h, L and Ra sliders' maxima follow the question on screen: a doubly curved point's limits
 * (not the plane's or a cylinder's), three-axis machining's largest h at the slope, as the worker's
 * reply gives them (issue 27 point 4: the page solves nothing). Checked the way
 * the user meets them: the slider's top is a value the page answers, just above it a value the
 * field refuses (the limit the field's message states), and the maxima differ from the plane's.
 */
import { describe, expect, it } from 'vitest';
import { doublyCurvedLimits } from '../../src/core/surfaces/doublyCurved';
import { buildRequest } from '../../src/ui/request';
import { type CalculatorState, type FieldKey, parseUrl, withField } from '../../src/ui/state';
import { answered, answeredRanges } from '../support/pageAnswer';

/** The slider's top is answered and 0.2 % (and a step) above it is refused (the top is 0.999 of the limit, snapped). */
function expectTopIsTheLimit(state: CalculatorState, key: FieldKey): void {
  const range = answeredRanges(state)[key];
  const top = Number(range.max);
  const step = Number(range.step);
  expect(answered(withField(state, key, range.max)), `${key} = ${range.max}`).toBe(true);
  const above = String(top / 0.998 + step);
  expect(answered(withField(state, key, above)), `${key} = ${above}`).toBe(false);
}

describe('the sliders at a doubly curved point and in three-axis machining', () => {
  const dome = parseUrl('?R=3&Rcr=1&rho=5&feedRadius=80&crossRadius=40&h=0.05&unit=mm').state;
  const plane = parseUrl('?R=3&Rcr=1&rho=5&h=0.05&unit=mm').state;

  it('h, L and Ra below the doubly curved limits', () => {
    const limit = doublyCurvedLimits({
      toolRadiusMm: 3,
      cornerRadiusMm: 1,
      leadAngleDeg: 5,
      tiltAngleDeg: 0,
      feedRadiusMm: 80,
      crossRadiusMm: 40,
    }).limitMm;
    expect(limit).toBeLessThan(2);
    expect(Number(answeredRanges(dome).h.max)).toBeLessThan(limit);
    expect(answeredRanges(dome).h.max).not.toBe(answeredRanges(plane).h.max);
    expectTopIsTheLimit(dome, 'h');
    const inverse = { ...withField(dome, 'L', '1'), mode: 'inverse' as const };
    expect(answeredRanges(inverse).L.max).not.toBe(answeredRanges({ ...plane, mode: 'inverse' }).L.max);
    expectTopIsTheLimit(inverse, 'L');
    const ra = { ...withField(dome, 'ra', '0.001'), target: 'ra' as const };
    expect(answeredRanges(ra).ra.max).not.toBe(answeredRanges({ ...plane, target: 'ra' }).ra.max);
    expectTopIsTheLimit(ra, 'ra');
  });

  it('a straight radius: the cylinder the point is (not the hidden cylinder field)', () => {
    const across = parseUrl('?R=3&Rcr=1&rho=5&feedRadius=20&h=0.05&unit=mm').state;
    const cylinder = parseUrl('?R=3&Rcr=1&rho=5&surfaceRadius=20&surfaceAxis=cross&h=0.05&unit=mm').state;
    expect(answeredRanges({ ...across, mode: 'inverse' }).L.max).toBe(
      answeredRanges({ ...cylinder, mode: 'inverse' }).L.max,
    );
  });

  it('three-axis: h below the largest at the slope (raster, waterline on a plane and on a surface of revolution)', () => {
    for (const url of [
      '?R=3&Rcr=1&machine=3axis&slope=60&rasterAngle=45&h=0.05&unit=mm',
      '?R=3&Rcr=1&machine=3axis&slope=70&passes=waterline&h=0.05&unit=mm',
      '?R=3&Rcr=1&machine=3axis&slope=30&passes=waterline&feedRadius=50&crossRadius=40&h=0.05&unit=mm',
    ]) {
      const s = parseUrl(url).state;
      expect(buildRequest(s).ok, url).toBe(true);
      expectTopIsTheLimit(s, 'h');
    }
  });
});
