/**
 * Feed rate and spindle speed as another way to give fz (issue 29; core/finish/feedRate.ts and
 * finishInput.ts): fz = F / (n z), each bad value named in one line in the user's unit, and fz
 * with F or n refused (one way only).
 */
import { describe, expect, it } from 'vitest';
import { describeFinishError, validateFinish } from '../../../src/core/finish/index';
import { seededRandom } from '../../../src/core/math/seededRandom';

const R = 3;

function messages(raw: Parameters<typeof validateFinish>[0], unit: 'mm' | 'in' = 'mm'): string[] {
  const v = validateFinish(raw, R);
  return v.ok ? [] : v.errors.map((e) => describeFinishError(e, unit));
}

describe('fz from the feed rate and the spindle speed', () => {
  it('seed 2931: the fz F and n give, times n z, is F again (stratified over z, F and n)', () => {
    const random = seededRandom(2931);
    for (let z = 1; z <= 12; z++)
      for (let k = 0; k < 20; k++) {
        const n = 100 * 10 ** (random() * 2.6); // 100 to 40,000 rpm
        const fzWanted = 1e-5 * 10 ** (random() * 5.4); // 1e-5 mm to 2.5 mm (< R)
        const F = fzWanted * n * z;
        const v = validateFinish({ flutes: z, feedRate: F, spindleSpeed: n }, R);
        if (!v.ok) throw new Error(JSON.stringify(v.errors));
        // Independent of the division: the feed per minute is the teeth per minute times the bite.
        expect(Math.abs(v.value.feedPerToothMm * n * z - F)).toBeLessThanOrEqual(4e-16 * F);
      }
  });

  it('a shop example: 960 mm/min at 12,000 rpm with 4 teeth is 0.02 mm per tooth', () => {
    const v = validateFinish({ flutes: '4', feedRate: '960', spindleSpeed: '12000' }, R);
    expect(v.ok && v.value.feedPerToothMm).toBe(0.02);
  });

  it('says 0, negative and not-a-number in one line each, in mm/min or in/min and rpm', () => {
    expect(messages({ flutes: 4, feedRate: '0', spindleSpeed: 1000 })).toEqual([
      'Feed rate F must be greater than 0 mm/min (got 0).',
    ]);
    expect(messages({ flutes: 4, feedRate: '-3', spindleSpeed: 1000 }, 'in')).toEqual([
      'Feed rate F must be greater than 0 in/min (got -3).',
    ]);
    expect(messages({ flutes: 4, feedRate: 500, spindleSpeed: '-1' })).toEqual([
      'Spindle speed n must be greater than 0 rpm (got -1).',
    ]);
    expect(messages({ flutes: 4, feedRate: 'fast', spindleSpeed: 'x' })).toEqual([
      'Feed rate F must be a number (got "fast").',
      'Spindle speed n must be a number (got "x").',
    ]);
    expect(messages({ flutes: 4, feedRate: 500 })).toEqual(['Spindle speed n is missing: enter a number.']);
  });

  it('refuses fz with F or n, and an fz from them out of fz limits (said as that fz, in the unit)', () => {
    expect(messages({ flutes: 4, fz: 0.1, feedRate: 500, spindleSpeed: 1000 })).toEqual([
      'Give the feed per tooth fz, or the feed rate F and the spindle speed n, not both.',
    ]);
    expect(messages({ flutes: 4, fz: 0.1, spindleSpeed: 1000 })).toHaveLength(1);
    expect(messages({ flutes: 2, feedRate: 8000, spindleSpeed: 1000 })).toEqual([
      'Feed per tooth fz = F / (n z) = 4 mm must be at most the tool radius R = 3 mm.',
    ]);
    expect(messages({ flutes: 2, feedRate: 25.4 * 8000, spindleSpeed: 1000 }, 'in')).toEqual([
      'Feed per tooth fz = F / (n z) = 4 in must be at most the tool radius R = 0.11811 in.',
    ]);
    expect(messages({ flutes: 4, feedRate: 1e-3, spindleSpeed: 1000 })).toEqual([
      'Feed per tooth fz = F / (n z) = 2.5e-7 mm must be at least 1e-6 mm.',
    ]);
    // Bad teeth: said on the teeth alone (no fz from them).
    expect(messages({ flutes: 2.5, feedRate: 500, spindleSpeed: 1000 })).toHaveLength(1);
  });
});
