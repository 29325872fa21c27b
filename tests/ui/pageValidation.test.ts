/**
 * The page validates the fields and the worker solves (issue 27 point 4): the five-axis builder
 * asks no surface model (gouging, the height and step-over limits, the largest Ra are the worker's
 * refusals), yet every field shows the message it showed when the page validated whole. Checked
 * over random questions (seeded strata: plane, convex and concave cylinders along and across the
 * feed; forward, inverse and a target Ra; one-way and zigzag; tools from a ball to a flat end, with
 * lead and tilt), with values on both sides of each limit: the page's build answered by the
 * worker's job (tests/support/pageAnswer.ts) against the core's whole validation of the same fields.
 */
import { describe, expect, it } from 'vitest';
import { seededRandom } from '../../src/core/math/seededRandom';
import { validateTargetRa } from '../../src/core/roughness/roughness';
import { validateForward, validateInverse } from '../../src/core/surfaces/validate';
import { buildRequest, fieldMessages } from '../../src/ui/request';
import { type CalculatorState, defaultState, type FieldKey, withField } from '../../src/ui/state';
import { answeredMessages } from '../support/pageAnswer';

type Surface = 'plane' | 'convex' | 'concave';
type Mode = 'forward' | 'inverse' | 'ra';

/** A random question of one stratum, in mm, its numbers written as the page's fields. */
function question(rnd: () => number, surface: Surface, mode: Mode): CalculatorState {
  const logUniform = (lo: number, hi: number) => lo * (hi / lo) ** rnd();
  const R = logUniform(0.5, 10);
  const Rcr = [R, 0, R * rnd()][Math.floor(3 * rnd())] as number;
  const fields: Partial<Record<FieldKey, string>> = {
    R: String(R),
    Rcr: String(Rcr),
    rho: String(60 * rnd()),
    tilt: String(rnd() < 0.5 ? 0 : 60 * rnd() - 30),
    Rs: String(logUniform(1, 300)),
    // Beside each limit: from far below to beyond it.
    h: String(logUniform(1e-4, 2 * R)),
    L: String(rnd() < 0.5 ? logUniform(1e-2, 2 * R) : R * (1.5 + 1.5 * rnd())),
    ra: String(logUniform(1e-5, 0.5 * R)),
  };
  let s: CalculatorState = {
    ...defaultState(),
    surface,
    surfaceAxis: rnd() < 0.5 ? 'feed' : 'cross',
    pattern: rnd() < 0.5 ? 'one-way' : 'zigzag',
    mode: mode === 'inverse' ? 'inverse' : 'forward',
    target: mode === 'ra' ? 'ra' : 'h',
  };
  for (const [key, text] of Object.entries(fields)) s = withField(s, key as FieldKey, text as string);
  return s;
}

/** Each field's message when the core validates the state's fields whole (as the page did before). */
function wholeMessages(s: CalculatorState, mode: Mode): Map<FieldKey, string> {
  const num = (key: FieldKey) => Number(s.fields[key]);
  const raw = {
    R: num('R'),
    Rcr: num('Rcr'),
    rho: num('rho'),
    tilt: num('tilt'),
    pattern: s.pattern,
    ...(s.surface === 'plane'
      ? {}
      : { surfaceRadius: s.surface === 'concave' ? -num('Rs') : num('Rs'), surfaceAxis: s.surfaceAxis }),
  };
  const v =
    mode === 'forward'
      ? validateForward({ ...raw, h: num('h') })
      : mode === 'inverse'
        ? validateInverse({ ...raw, interval: num('L') })
        : validateTargetRa({ ...raw, ra: num('ra') });
  return v.ok ? new Map() : fieldMessages(s, v.errors as Parameters<typeof fieldMessages>[1]);
}

describe('the page validates the fields, the worker refuses what needs a solve, the messages as before', () => {
  const strata = (['plane', 'convex', 'concave'] as const).flatMap((surface) =>
    (['forward', 'inverse', 'ra'] as const).map((mode) => ({ surface, mode })),
  );
  strata.forEach(({ surface, mode }, k) => {
    const seed = 2704 + k;
    it(`${surface}, ${mode} (seed ${seed}, 12 questions)`, () => {
      const rnd = seededRandom(seed);
      let refused = 0;
      for (let i = 0; i < 12; i++) {
        const s = question(rnd, surface, mode);
        // Numbers typed in range: the page's own checks pass, every refusal is the worker's.
        expect(buildRequest(s).ok, JSON.stringify(s.fields)).toBe(true);
        const whole = wholeMessages(s, mode);
        expect(answeredMessages(s), JSON.stringify(s.fields)).toEqual(whole);
        if (whole.size > 0) refused++;
      }
      // Each stratum meets the limits too (not only answers).
      expect(refused).toBeGreaterThan(0);
    });
  });
});
