/**
 * The three-axis errors in Japanese and German (issue 30): stratified random three-axis questions
 * over the whole input domain and past its edges (the tool, flat end to ball, the slope from 0 to 90
 * and beyond, raster and waterline, straight and curved radii convex and concave, h and every
 * programmed step from tiny to beyond the tool), each refusal the core gives (its validation's or
 * its solvers') worded from its data in each language and unit: every code the page can meet is
 * met; each sentence has no English word left (Japanese: no Latin word but the symbols and units;
 * German: none of the page's English words), names the bound it broke in the user's unit with the
 * locale's decimal sign (the shank, flank, step and surface limits, the gouging radius), quotes what
 * was given, and shows no NaN, Infinity, undefined or null.
 */
import { describe, expect, it } from 'vitest';
import { formatInputNumber, fromMm, type LengthUnit } from '../../../src/core/input/units';
import { seededRandom } from '../../../src/core/math/seededRandom';
import { MIN_THREE_AXIS_LENGTH_MM } from '../../../src/core/threeAxis/errors';
import { solveThreeAxis } from '../../../src/core/threeAxis/solve';
import {
  type RawThreeAxisInput,
  type ThreeAxisInputError,
  type ThreeAxisQuantity,
  validateThreeAxis,
} from '../../../src/core/threeAxis/validate';
import type { Catalogue } from '../../../src/ui/i18n/catalogue';
import { catalogue as de } from '../../../src/ui/i18n/de';
import { describeThreeAxisErrorIn } from '../../../src/ui/i18n/errorText';
import { catalogue as ja } from '../../../src/ui/i18n/ja';
import { localDecimal } from '../../../src/ui/i18n/langChoice';

const SEED = 3030;

/** One random question: its raw inputs, quantity and value (mm and degrees). */
function question(r: () => number): { raw: RawThreeAxisInput; quantity: ThreeAxisQuantity; value: number } {
  const pick = <T>(xs: readonly T[]): T => xs[Math.floor(r() * xs.length)] as T;
  const R = pick([0.0005, 0.5 + 9.5 * r(), 3]);
  const Rcr = pick([0, R * r(), R, R * 1.5]);
  const slope = pick([0, 90, 90 * r(), 90 * r(), 89.9, -5, 95]);
  const passes = pick(['raster', 'waterline'] as const);
  const radius = () => pick([undefined, (r() < 0.5 ? -1 : 1) * 10 ** (-0.5 + 3 * r()), -2, 0.0001]);
  const raw: RawThreeAxisInput =
    passes === 'raster'
      ? { R, Rcr, slope, passes, rasterAngle: pick([0, 90 * r(), 90, 120]) }
      : { R, Rcr, slope, passes, feedRadius: radius(), crossRadius: radius() };
  const quantity = pick<ThreeAxisQuantity>([
    'h',
    'h',
    'interval',
    passes === 'raster' ? 'horizontalStep' : 'stepDown',
    'stepDown',
  ]);
  const value = pick([10 ** (-6 + 7 * r()), 1e-12, -1]);
  return { raw, quantity, value };
}

/** The core's refusals of `count` random questions, each once per code and field, with the passes. */
function refusals(count: number): Array<{ e: ThreeAxisInputError; waterline: boolean }> {
  const r = seededRandom(SEED);
  const out = new Map<string, { e: ThreeAxisInputError; waterline: boolean }>();
  for (let i = 0; i < count; i++) {
    const q = question(r);
    const v = validateThreeAxis(q.raw, q.quantity, q.value);
    const errors = v.ok
      ? (() => {
          const s = solveThreeAxis(v.value);
          return s.ok ? [] : s.errors;
        })()
      : v.errors;
    for (const e of errors) {
      const key = `${e.code} ${e.field} ${e.limit === null ? 'none' : e.limit < MIN_THREE_AXIS_LENGTH_MM ? 'tiny' : 'limit'} ${/together/.test(e.message)}`;
      if (!out.has(key)) out.set(key, { e, waterline: q.raw.passes === 'waterline' });
    }
  }
  return [...out.values()];
}

const KEPT = new Set('L h R D Rcr rho beta alpha psi Rs Rf Rc Lxy dz z Z mm in e'.split(' '));
const ENGLISH =
  /\b(step|over|scallop|height|tool|feed|surface|plane|slope|must|be|below|above|at|least|most|got|the|and|of|or|is|passes?|raster|waterline|shank|flank|wall|gouged?|gouging|cusp|straight|concave|convex|missing|number|answered|here|degrees?)\b/i;

describe(`three-axis errors in Japanese and German (seed ${SEED})`, () => {
  const all = refusals(4000);

  it('the random questions meet every refusal the page can meet', () => {
    const codes = new Set(all.map((x) => x.e.code));
    for (const code of [
      'out-of-range',
      'too-small',
      'vertical-wall',
      'needs-slope',
      'shank-cuts',
      'flank-wall',
      'wall-only',
      'beyond-step',
      'past-surface',
      'gouging',
      'not-with',
    ] as const)
      expect(codes.has(code), code).toBe(true);
  });

  for (const [name, c] of [
    ['ja', ja],
    ['de', de],
  ] as [string, Catalogue][])
    for (const unit of ['mm', 'in'] as LengthUnit[])
      it(`${name}, ${unit}: no English word, the bound in the unit with the locale's decimal sign, what was given`, () => {
        for (const { e, waterline } of all) {
          const typed = typeof e.got === 'number' ? formatInputNumber(e.got) : e.got;
          const text = describeThreeAxisErrorIn(c, e, unit, typed, waterline);
          const where = `${e.code} ${e.field} ${e.message} -> ${text}`;
          expect(text, where).not.toMatch(/NaN|Infinity|undefined|null|\[object/);
          if (name === 'ja') {
            expect(/[\u3000-\u30ff\u4e00-\u9fff]/.test(text), where).toBe(true);
            for (const w of text.match(/[A-Za-z][A-Za-z0-9]*/g) ?? [])
              expect(KEPT.has(w), `${where}: "${w}"`).toBe(true);
          } else expect(ENGLISH.exec(text)?.[0] ?? null, where).toBeNull();
          // The bound it broke, as a length in the unit (its magnitude for a gouging radius) or an angle.
          const isLength = !['slope', 'rasterAngle', 'passes', 'rho', 'tilt'].includes(e.field);
          if (
            e.limit !== null &&
            Number.isFinite(e.limit) &&
            e.limit >= MIN_THREE_AXIS_LENGTH_MM &&
            e.code !== 'vertical-wall' &&
            e.code !== 'needs-slope'
          ) {
            const bound = isLength
              ? `${formatInputNumber(fromMm(e.code === 'gouging' ? Math.abs(e.limit) : e.limit, unit))} ${unit}`
              : `${e.limit}°`;
            expect(text, where).toContain(localDecimal(bound, c));
          }
          // What was given, except where the sentence says what belongs elsewhere.
          if (
            !['missing', 'vertical-wall', 'needs-slope', 'wall-only', 'not-with'].includes(e.code) &&
            !(e.field === 'stepDown' && !waterline) &&
            !/together/.test(e.message)
          )
            expect(text, where).toContain(typed.length > 24 ? typed.slice(0, 21) : typed);
        }
      });
});
