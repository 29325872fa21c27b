/**
 * The input errors in Japanese and German (issue 30, src/ui/i18n/errorText.ts and the catalogues'
 * errors): every error code of the core, with and without its bound and side, gives one finite
 * line in each language that names the field in that language, quotes what was typed, gives the
 * bound in the user's unit (German with a decimal comma, every digit kept), and leaves no English
 * word of the core's sentences and nothing undefined.
 */
import { describe, expect, it } from 'vitest';
import { type AnyFieldName, type InputErrorCode, inputError } from '../../../src/core/input/validate';
import type { Catalogue } from '../../../src/ui/i18n/catalogue';
import { catalogue as de } from '../../../src/ui/i18n/de';
import { describeInputErrorIn } from '../../../src/ui/i18n/errorText';
import { catalogue as ja } from '../../../src/ui/i18n/ja';

/** Each code with a field it is given on (the core's own use). */
const CASES: ReadonlyArray<readonly [InputErrorCode, AnyFieldName]> = [
  ['missing', 'Rcr'],
  ['not-a-number', 'Rcr'],
  ['not-finite', 'h'],
  ['not-positive', 'R'],
  ['negative', 'Rcr'],
  ['too-small', 'h'],
  ['too-large', 'h'],
  ['out-of-range', 'rho'],
  ['out-of-range', 'tilt'],
  ['out-of-range', 'surfaceRadius'],
  ['not-a-pattern', 'pattern'],
  ['not-an-axis', 'surfaceAxis'],
  ['gouging', 'surfaceRadius'],
  ['shank-gouging', 'surfaceRadius'],
  ['corner-exceeds-radius', 'Rcr'],
  ['flank-wall', 'h'],
  ['shank-cuts', 'h'],
  ['beyond-diameter', 'interval'],
  ['beyond-interval', 'interval'],
  ['beyond-max-ra', 'ra'],
  ['wall-only', 'interval'],
  ['radius-gouging', 'feedRadius'],
];

const ENGLISH = /\b(must|the|tool|posture|cannot|below|above|least|most|radius of|scallop|wall|enter|number|got)\b/;

function lines(c: Catalogue): string[] {
  const out: string[] = [];
  for (const [code, field] of CASES)
    for (const limit of [null, 2.54321])
      for (const side of [null, 'left'] as const) {
        const e = inputError(field, code, '7.25', limit, side, { axis: 'cross', leanDeg: 47.5 });
        const withRadius =
          code === 'radius-gouging'
            ? { ...e, radiusLimit: { kind: 'concave-at-least' as const, heldMm: 40, other: { kind: 'none' as const } } }
            : e;
        out.push(describeInputErrorIn(c, withRadius, 'mm', { typed: '7,25', radiusAsMagnitude: true }));
        out.push(describeInputErrorIn(c, withRadius, 'in', { typed: '7,25', toolSizeAsDiameter: true }));
      }
  return out;
}

describe('input errors in Japanese and German', () => {
  it('every code: one finite line, the typed text quoted, no English word, nothing undefined', () => {
    for (const c of [ja, de])
      for (const line of lines(c)) {
        expect(line, line).not.toMatch(/undefined|NaN|Infinity|null|\n/);
        expect(line.includes('7,25') || /未入力|fehlt/.test(line), line).toBe(true);
        expect(ENGLISH.test(line), line).toBe(false);
      }
  });

  it('the bound in the unit on screen: German with a decimal comma, Japanese with a point, every digit kept', () => {
    const e = inputError('Rcr', 'corner-exceeds-radius', '5', 2.54321);
    expect(describeInputErrorIn(de, e, 'mm', { typed: '5' })).toBe(
      'Eckenradius Rcr darf den Werkzeugradius R = 2,54321 mm nicht überschreiten (eingegeben: 5); Rcr = R ist ein Kugelfräser.',
    );
    expect(describeInputErrorIn(ja, e, 'mm', { typed: '5' })).toBe(
      'コーナ半径 Rcrは工具半径 R = 2.54321 mm を超えられません（入力：5）。Rcr = R はボールエンドミルです。',
    );
    // Inch: the bound converted (2.54321 mm = 0.100126 in), the size given as D named D/2.
    expect(describeInputErrorIn(de, e, 'in', { typed: '0,2', toolSizeAsDiameter: true })).toBe(
      'Eckenradius Rcr darf höchstens D/2 = 0,100126 in betragen (eingegeben: 0,2); Rcr = D/2 ist ein Kugelfräser.',
    );
  });

  it('the tool size given as D: named D, its bound doubled', () => {
    const e = inputError('R', 'not-positive', '0');
    expect(describeInputErrorIn(de, e, 'mm', { typed: '0', toolSizeAsDiameter: true })).toBe(
      'Werkzeugdurchmesser D muss größer als 0 mm sein (eingegeben: 0).',
    );
  });
});
