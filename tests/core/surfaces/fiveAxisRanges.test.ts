/**
 * The five-axis posture's angle ranges are stated once (input/angleRanges.ts): the page's and
 * command line's validation (surfaces/validate.ts) and the five-axis mode of the one question
 * (question.ts) accept and refuse the same angles, at the bounds, just inside and outside them, and
 * at stratified random angles (seed 2727); the field registry's rho and tilt ranges say the same.
 */
import { describe, expect, it } from 'vitest';
import { FIELDS, type FieldRange } from '../../../src/core/input/fields';
import { seededRandom } from '../../../src/core/math/seededRandom';
import { validateQuestion } from '../../../src/core/surfaces/question';
import { validateForward } from '../../../src/core/surfaces/validate';

/** True when `v` lies inside a field registry range (its bounds included or not as it says). */
function inRange(range: FieldRange | undefined, v: number): boolean {
  if (range === undefined) throw new Error('no range');
  const aboveMin = range.min === null || (range.minIncluded ? v >= range.min : v > range.min);
  const belowMax = range.max === null || (range.maxIncluded ? v <= range.max : v < range.max);
  return aboveMin && belowMax;
}

const accepts = {
  validate: (rho: number, tilt: number) => {
    const v = validateForward({ R: 5, Rcr: 1, rho, tilt, h: 1e-4 });
    return v.ok || !v.errors.some((e) => e.field === 'rho' || e.field === 'tilt');
  },
  question: (rho: number, tilt: number) => {
    const v = validateQuestion({
      tool: { toolRadiusMm: 5, cornerRadiusMm: 1 },
      mode: { kind: 'fiveAxis', leadAngleDeg: rho, tiltAngleDeg: tilt } as { kind: string },
      surface: { kind: 'plane' },
      pattern: 'one-way',
      target: { quantity: 'h', mm: 1e-4 },
    });
    return v.ok || !v.errors.some((e) => e.field === 'rho' || e.field === 'tilt');
  },
};

describe('five-axis angle ranges: one rule for the validation, the mode and the field registry (seed 2727)', () => {
  it('the bounds: 0 <= rho < 90, -90 < tilt < 90, the same both ways', () => {
    const eps = 1e-9;
    const cases: Array<[number, number, boolean]> = [
      [0, 0, true],
      [90 - eps, 0, true],
      [90, 0, false],
      [-eps, 0, false],
      [0, 90 - eps, true],
      [0, -90 + eps, true],
      [0, 90, false],
      [0, -90, false],
    ];
    for (const [rho, tilt, ok] of cases) {
      expect(accepts.validate(rho, tilt), `validate rho ${rho} tilt ${tilt}`).toBe(ok);
      expect(accepts.question(rho, tilt), `question rho ${rho} tilt ${tilt}`).toBe(ok);
    }
  });

  it('stratified random angles from -180 to 180 degrees: both agree (seed 2727)', () => {
    const next = seededRandom(2727);
    for (let i = 0; i < 400; i++) {
      // Ten strata across [-180, 180) for each angle.
      const rho = -180 + 36 * (i % 10) + 36 * next();
      const tilt = -180 + 36 * (Math.floor(i / 10) % 10) + 36 * next();
      const expected = inRange(FIELDS.rho.range, rho) && inRange(FIELDS.tilt.range, tilt);
      expect(accepts.validate(rho, tilt), `validate ${rho} ${tilt}`).toBe(expected);
      expect(accepts.question(rho, tilt), `question ${rho} ${tilt}`).toBe(expected);
    }
  });
});
