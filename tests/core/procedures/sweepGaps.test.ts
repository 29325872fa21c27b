import { describe, expect, it } from 'vitest';
import { forwardInput } from '../../../src/core/input/validate';
import { bediHalfInterval } from '../../../src/core/procedures/approximations';
import { EXACT_NO_ANSWER, noAnswerReason, sweepGaps } from '../../../src/core/procedures/sweepGaps';
import { stepOverSweep } from '../../../src/core/procedures/teaching';

const tool = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 };

describe('where a procedure has no answer along a sweep, and why', () => {
  it('groups consecutive samples with one reason; a new reason or an answer ends a run', () => {
    expect(sweepGaps([1, 2, 3, 4, 5, 6], ['a', 'a', null, 'b', 'c', 'c'])).toEqual([
      { fromDeg: 1, toDeg: 2, reason: 'a' },
      { fromDeg: 4, toDeg: 4, reason: 'b' },
      { fromDeg: 5, toDeg: 6, reason: 'c' },
    ]);
    expect(sweepGaps([1, 2], [null, null])).toEqual([]);
  });

  it("Tool 1 at h = 0.05: Bedi has no answer below about 1.4 deg, h above its ellipse's widest point", () => {
    const s = stepOverSweep(tool, 'one-way', 0.05, 'lead', 0.5, 89, 120, 5);
    expect(s.gaps.bedi).toHaveLength(1);
    const gap = s.gaps.bedi[0];
    if (!gap) throw new Error('no gap');
    expect(gap.fromDeg).toBe(0.5);
    expect(gap.reason).toBe('h is above the widest point of its ellipse (its height Rlong sin(rho) is below h)');
    // The edge: no answer at the gap's last sample, an answer at the next one, as Eq. 11 says.
    const next = s.angleDeg[s.angleDeg.indexOf(gap.toDeg) + 1] as number;
    const bedi = (rho: number) => bediHalfInterval(forwardInput({ ...tool, leadAngleDeg: rho }, 'one-way', 0.05)).ok;
    expect(bedi(gap.toDeg)).toBe(false);
    expect(bedi(next)).toBe(true);
    expect(gap.toDeg).toBeGreaterThan(1.3);
    expect(next).toBeLessThan(1.5);
    // Every null sample is inside a gap, and every gap sample is null.
    for (const key of ['exact', 'sekine', 'redonnet', 'bedi', 'osculating', 'cornerBall'] as const) {
      s.angleDeg.forEach((a, i) => {
        const inGap = s.gaps[key].some((g) => a >= g.fromDeg && a <= g.toDeg);
        expect(inGap, `${key} at ${a}`).toBe(s.values[key][i] === null);
      });
    }
    // The other procedures answer all along.
    expect(s.gaps.exact).toEqual([]);
    expect(s.gaps.sekine).toEqual([]);
  });

  it("above the posture's limit every procedure is blank, for the exact solver's reason", () => {
    const s = stepOverSweep(tool, 'one-way', 1.5, 'tilt', -60, 60, 8);
    for (const key of ['exact', 'sekine', 'bedi'] as const)
      expect(s.gaps[key]).toEqual([{ fromDeg: -60, toDeg: 60, reason: EXACT_NO_ANSWER }]);
  });

  it("a model that does not apply gives its own reason, without the procedure's name or numbers", () => {
    const flat = { toolRadiusMm: 3, cornerRadiusMm: 0, leadAngleDeg: 5, tiltAngleDeg: 0 };
    expect(noAnswerReason('cornerBall', flat)).toBe('a flat end (Rcr = 0) has no corner ball');
    expect(noAnswerReason('sekine', tool)).toBe(
      'h is above the widest point of its circle (its radius Reff is below h)',
    );
    expect(noAnswerReason('cornerBall', tool)).toMatch(/radius Rcr/);
  });
});
