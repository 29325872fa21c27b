import { describe, expect, it } from 'vitest';
import {
  bediHalfInterval,
  cornerBallHalfInterval,
  osculatingHalfInterval,
  redonnetHalfInterval,
  sekineHalfInterval,
} from '../../../src/core/procedures/approximations';
import { exactForward, exactInverse } from '../../../src/core/surfaces/solve';
import { validateForward, validateInverse } from '../../../src/core/surfaces/validate';
import { seededRandom } from '../../support/bruteForce';
import { everyNumberFinite } from '../../support/finite';

/**
 * Issue 7: no input, valid or not, makes the core produce NaN, Infinity or null where a number
 * belongs. 100 000 raw cases, each validated forward and inverse (200 000 validations), and every
 * valid one solved (exact forward or inverse and the five approximations); every number of every
 * result checked itself (not through JSON).
 */
describe('fuzz of the core (seed 20261123)', () => {
  it('200 000 validations and every valid case solved: only finite numbers or a message', () => {
    const rand = seededRandom(20261123);
    const failures: string[] = [];
    const pick = <T>(xs: readonly T[]): T => xs[Math.floor(rand() * xs.length)] as T;
    // Raw values: plausible numbers, extremes (subnormal, huge, negative zero), junk text.
    const length = (): unknown =>
      pick([
        () => 10 ** (-4 + 7 * rand()),
        () => rand() * 10,
        () =>
          pick([
            0,
            -0,
            -1,
            1e-320,
            5e-324,
            1e308,
            1e-9,
            1e3,
            1000.0000001,
            'abc',
            '',
            '1e400',
            '-1e-400',
            null,
            undefined,
          ]),
        () => String(10 ** (-3 + 5 * rand())),
      ])();
    const angle = (max: number): unknown =>
      pick([
        () => rand() * max,
        () => pick([0, 1e-320, 89.9999999, 90, -90, -1, 'x', 1e-12, Number.NaN]),
        () => max * (2 * rand() - 1),
      ])();
    let valid = 0;
    let calls = 0;
    for (let i = 0; i < 100_000; i++) {
      const R = length();
      const raw = {
        R,
        Rcr: rand() < 0.8 && typeof R === 'number' ? R * pick([0, 1, rand(), 1e-9]) : length(),
        rho: angle(90),
        tilt: rand() < 0.5 ? 0 : angle(90),
        pattern: pick(['one-way', 'zigzag', 'one-way', 'diagonal', undefined]),
        surfaceRadius: rand() < 0.6 ? undefined : pick([() => length(), () => -(length() as number), () => 'plane'])(),
        surfaceAxis: pick(['feed', 'cross', undefined, 'up']),
      };
      const h = rand() < 0.7 ? 10 ** (-9 + 9 * rand()) : length();
      const f = validateForward({ ...raw, h });
      const v = validateInverse({ ...raw, interval: rand() < 0.7 ? 10 ** (-6 + 7 * rand()) : length() });
      calls += 2;
      for (const r of [f, v]) {
        if (!r.ok) {
          if (r.errors.some((e) => e.message.length <= 10))
            failures.push(`a message of 10 characters or fewer: ${JSON.stringify({ raw, errors: r.errors })}`);
          if (!everyNumberFinite(r.errors.map((e) => e.limit ?? 0)))
            failures.push(`a limit not finite: ${JSON.stringify({ raw, h, errors: r.errors })}`);
        }
      }
      if (f.ok) {
        valid++;
        const out = [
          exactForward(f.value),
          sekineHalfInterval(f.value),
          redonnetHalfInterval(f.value),
          bediHalfInterval(f.value),
          osculatingHalfInterval(f.value),
          cornerBallHalfInterval(f.value),
        ];
        calls += out.length;
        if (!everyNumberFinite(out)) failures.push(`forward: ${JSON.stringify(f.value)}`);
      }
      if (v.ok) {
        valid++;
        const out = exactInverse(v.value);
        calls++;
        if (!everyNumberFinite(out)) failures.push(`inverse: ${JSON.stringify(v.value)}`);
      }
    }
    // Each case checked as it comes, said at the end (an assertion per case cost more than the cases).
    expect(failures.slice(0, 20)).toEqual([]);
    // Both sides are exercised: tens of thousands of valid cases among the rejected ones.
    expect(valid).toBeGreaterThan(20_000);
    expect(valid).toBeLessThan(180_000);
    expect(calls).toBeGreaterThanOrEqual(200_000);
  }, 120_000);
});
