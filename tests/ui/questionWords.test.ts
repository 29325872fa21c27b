/**
 * Issue 28, point 1: every answer names its question in words, the machine first. The words are
 * read back against the state they describe (each part from its own field), not against the code.
 */
import { describe, expect, it } from 'vitest';
import { questionWords } from '../../src/ui/questionWords';
import { type CalculatorState, defaultState, parseUrl, withField } from '../../src/ui/state';

const withMachine = (s: CalculatorState, patch: Partial<CalculatorState>): CalculatorState => ({ ...s, ...patch });

describe('questionWords', () => {
  it("the default (the paper's Tool 1): five-axis, its lead and tilt, one-way, plane", () => {
    expect(questionWords(defaultState())).toBe('5-axis, lead 5°, tilt 0°, one-way, plane');
  });

  it('three-axis: the flat floor, a slope with its raster angle, waterline with and without radii', () => {
    const three = withMachine(defaultState(), { machine: '3axis', passes: 'raster' });
    expect(questionWords(withField(three, 'slope', '0'))).toBe('3-axis, flat floor');
    expect(questionWords(withField(withField(three, 'slope', '30'), 'psi', '30'))).toBe(
      '3-axis, slope 30°, raster 30°',
    );
    const water = withMachine(three, { passes: 'waterline', feedSide: 'straight', crossSide: 'straight' });
    expect(questionWords(water)).toBe('3-axis, waterline, slope 30°');
    const bowl = withMachine(water, { feedSide: 'concave', crossSide: 'concave' });
    expect(questionWords(bowl)).toBe(
      '3-axis, waterline, slope 30°, along the feed concave 80 mm, across concave 40 mm',
    );
  });

  it('five-axis surfaces: cylinders by side, radius, unit and axis; the curved point by its radii', () => {
    const inch = defaultState('in');
    const cyl = withMachine(withField(inch, 'Rs', '2'), { surface: 'concave', surfaceAxis: 'cross' });
    expect(questionWords(withField(cyl, 'tilt', '-0'))).toBe(
      '5-axis, lead 5°, tilt 0°, one-way, concave cylinder 2 in across the feed',
    );
    const zig = withMachine(defaultState(), {
      pattern: 'zigzag',
      surface: 'curved',
      feedSide: 'convex',
      crossSide: 'straight',
    });
    expect(questionWords(zig)).toBe(
      '5-axis, lead 5°, tilt 0°, zigzag, curved point: along the feed convex 80 mm, across straight',
    );
  });

  it('a link carries the machine into the words (a three-axis link is never named five-axis)', () => {
    const parsed = parseUrl('?machine=3axis&slope=30&rasterAngle=30&R=6.35&Rcr=0.762&h=0.01&unit=mm');
    expect(questionWords(parsed.state)).toBe('3-axis, slope 30°, raster 30°');
  });

  it('a field that is not a number is "?", never NaN or Infinity', () => {
    const bad = withField(withField(defaultState(), 'rho', 'abc'), 'tilt', '1e999');
    expect(questionWords(bad)).toBe('5-axis, lead ?°, tilt ?°, one-way, plane');
  });
});
