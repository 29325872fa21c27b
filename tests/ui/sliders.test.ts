/** Slider ranges and steps in the user's unit: arrow keys move by round amounts of that unit. */
import { describe, expect, it } from 'vitest';
import { sliderRanges } from '../../src/ui/sliders';
import { parseUrl } from '../../src/ui/state';
import { answeredRanges } from '../support/pageAnswer';

describe('slider ranges', () => {
  it('steps are round numbers of the unit shown (not converted mm steps)', () => {
    const mm = sliderRanges(parseUrl('?R=3&Rcr=1&rho=5&h=0.05&unit=mm').state);
    expect([mm.R.step, mm.Rcr.step, mm.rho.step, mm.tilt.step, mm.h.step, mm.L.step]).toEqual([
      '0.01',
      '0.01',
      '0.1',
      '0.1',
      '0.001',
      '0.001',
    ]);
    const inch = sliderRanges(parseUrl('?R=0.25&Rcr=0.04&rho=5&h=0.002&unit=in').state);
    expect([inch.R.step, inch.Rcr.step, inch.h.step, inch.L.step]).toEqual(['0.001', '0.001', '0.0001', '0.0001']);
    // An inch value on the step grid: R = 0.25 in moves to 0.251 in, not to 0.25058101.
    const steps = (0.25 - Number(inch.R.min)) / Number(inch.R.step);
    expect(Math.abs(steps - Math.round(steps))).toBeLessThan(1e-9);
    for (const r of Object.values(inch)) {
      for (const v of [r.min, r.max, r.step]) expect(v).toMatch(/^-?\d+(\.\d{1,6})?$/);
      expect(Number(r.max)).toBeGreaterThan(Number(r.min));
    }
  });

  it('ranges follow the other values: Rcr up to R, h below the posture limit, L below the widest step-over', () => {
    const s = answeredRanges(parseUrl('?R=3&Rcr=1&rho=5&h=0.05&unit=mm').state);
    expect(s.Rcr.max).toBe('3');
    expect(Number(s.h.max)).toBeLessThan(2 * Math.sin((5 * Math.PI) / 180) + 1);
    expect(Number(s.L.max)).toBeLessThan(6);
    const tilted = answeredRanges(parseUrl('?R=3&Rcr=1&rho=5&tilt=40&h=0.05&unit=mm').state);
    expect(Number(tilted.h.max)).toBeLessThan(Number(s.h.max));
    expect(tilted.tilt).toEqual({ min: '-89.9', max: '89.9', step: '0.1' });
  });
});
