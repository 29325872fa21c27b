/**
 * The input errors in Japanese and German (issue 30, src/ui/i18n/errorText.ts and the catalogues'
 * errors): every error code of the core, with and without its bound and side, gives one finite
 * line in each language that names the field in that language, quotes what was typed, gives the
 * bound in the user's unit (German with a decimal comma, every digit kept), and leaves no English
 * word of the core's sentences and nothing undefined.
 */
import { describe, expect, it } from 'vitest';
import { type AnyFieldName, type InputErrorCode, inputError } from '../../../src/core/input/validate';
import { describeCurvedError, radiusMm } from '../../../src/ui/curvedRequest';
import { finishFieldErrors } from '../../../src/ui/finishFields';
import type { Catalogue } from '../../../src/ui/i18n/catalogue';
import { catalogue as de } from '../../../src/ui/i18n/de';
import { describeInputErrorIn } from '../../../src/ui/i18n/errorText';
import { catalogue as ja } from '../../../src/ui/i18n/ja';
import { describeError, setCatalogue } from '../../../src/ui/i18n/words';
import type { PageFieldError } from '../../../src/ui/requestTypes';
import { type CalculatorState, defaultState, parseField } from '../../../src/ui/state';
import type { CurvedError } from '../../../src/worker/pageProtocol';

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

describe("the teeth-and-feed fields' own message (finishFields.ts): in the language in force, as the tool fields'", () => {
  /** Every finish field with a text that is not a number: fz typed (F and n off), then fz empty (F and n on). */
  const BAD: CalculatorState = {
    ...defaultState('mm'),
    fields: { ...defaultState('mm').fields, z: 'abc', fz: 'abc', runout: 'x', runoutPhase: 'x', passPhase: 'x' },
  };
  const RATE: CalculatorState = { ...BAD, fields: { ...BAD.fields, fz: '', F: 'abc', n: 'x' } };
  const messages = () => [
    ...finishFieldErrors(BAD, describeError),
    ...finishFieldErrors(RATE, describeError).filter((e) => e.key === 'F' || e.key === 'n'),
  ];

  it('English as before; German and Japanese name the field in the language, the text quoted, no English word', () => {
    expect(finishFieldErrors(BAD, describeError).find((e) => e.key === 'fz')?.message).toBe(
      'Feed per tooth fz must be a number (got "abc").',
    );
    try {
      for (const c of [de, ja]) {
        setCatalogue(c, null, (e, unit, options) => describeInputErrorIn(c, e, unit, options));
        const shown = messages();
        expect(shown.map((e) => e.key).sort()).toEqual(['F', 'fz', 'n', 'passPhase', 'runout', 'runoutPhase', 'z']);
        for (const { key, message } of shown) {
          expect(message.startsWith(c.fields[key].label), message).toBe(true);
          expect(message).toContain(key === 'fz' || key === 'z' || key === 'F' ? 'abc' : 'x');
          expect(ENGLISH.test(message), message).toBe(false);
        }
        // A control character typed after a digit is quoted as its escape in every language.
        const bell: CalculatorState = { ...BAD, fields: { ...BAD.fields, z: '3\u0007' } };
        const z = finishFieldErrors(bell, describeError).find((e) => e.key === 'z')?.message ?? '';
        expect(z, z).toContain('3\\x07');
      }
    } finally {
      setCatalogue(null, null, null);
    }
  });
});

/** A doubly curved point on screen: Rf 80 mm convex, Rc 40 mm concave, h, L and Ra as typed. */
const CURVED_STATE: CalculatorState = {
  ...defaultState('mm'),
  surface: 'curved',
  feedSide: 'convex',
  crossSide: 'concave',
  fields: { ...defaultState('mm').fields, Rf: '80', Rc: '40', h: '0,5', L: '9', ra: '1' },
};

/** One worker refusal per kind at a doubly curved point (pageProtocol.ts CurvedError). */
const CURVED_ERRORS: readonly CurvedError[] = [
  { field: 'feedRadius', code: 'out-of-range', gotMm: 2e6 },
  {
    field: 'crossRadius',
    code: 'gouging',
    limit: { minCurvaturePerMm: -0.02, kind: 'concave-at-least', radiusMm: 50.25 },
    otherMm: 80,
  },
  {
    field: 'feedRadius',
    code: 'gouging',
    limit: { minCurvaturePerMm: 0.08, kind: 'convex-at-most', radiusMm: 12.5 },
    otherMm: Number.POSITIVE_INFINITY,
  },
  {
    field: 'feedRadius',
    code: 'gouging',
    limit: { minCurvaturePerMm: 0, kind: 'not-concave', radiusMm: null },
    otherMm: -40,
  },
  {
    field: 'crossRadius',
    code: 'gouging',
    limit: { minCurvaturePerMm: 2000, kind: 'none', radiusMm: null },
    otherMm: 80,
  },
  { field: 'h', code: 'above-limit', limitMm: 0.4, limitBy: 'right-flank' },
  { field: 'h', code: 'above-limit', limitMm: 0.4, limitBy: 'shank-left' },
  { field: 'interval', code: 'beyond-max', maxMm: 8.25 },
  { field: 'ra', code: 'beyond-max-ra', maxMm: 0.0125 },
];

describe("a doubly curved point's refusals in Japanese and German (curvedText.ts)", () => {
  it('English: the page words them itself (curvedRequest.ts), each bound in the unit', () => {
    const english = CURVED_ERRORS.slice(1, 3).map((e) => describeCurvedError(e, CURVED_STATE).message);
    expect(english).toEqual([
      'Cross radius Rc must be at least 50.25 mm while concave, with Rf = 80 mm held (got 40, concave): a tighter one is gouged (the tool reaches into the surface away from the contact).',
      'Feed radius Rf must be convex and at most 12.5 mm, with Rc straight (got 80, convex): a flatter one is gouged (the tool reaches into the surface away from the contact).',
    ]);
  });

  for (const c of [ja, de])
    it(`${c.lang}: on the English one's field, each its own line, the bounds with the locale's decimal sign, what was typed, no English word`, () => {
      const worded = CURVED_ERRORS.map((e) => c.curved(e, CURVED_STATE));
      expect(worded.map((m) => m.key)).toEqual(CURVED_ERRORS.map((e) => describeCurvedError(e, CURVED_STATE).key));
      const messages = worded.map((m) => m.message);
      expect(new Set(messages).size).toBe(CURVED_ERRORS.length);
      const sign = c.lang === 'de' ? ',' : '.';
      const [range, concave, convex, notConcave, none, flank, shank, wall, ra] = messages as string[];
      expect(range).toContain(`0${sign}001 mm`);
      expect(range).toContain(c.fields.Rf.label);
      expect(concave).toContain(`50${sign}25 mm`);
      expect(concave).toContain(`40, ${c.question.concave}`);
      expect(concave).toContain(`Rf = 80 mm`);
      expect(convex).toContain(`12${sign}5 mm`);
      expect(notConcave).toContain('Rc = -40 mm');
      expect(none).toContain(c.fields.Rc.label);
      expect(flank).toContain(`0${sign}4 mm`);
      expect(flank).toContain('0,5');
      expect(shank).not.toBe(flank);
      expect(wall).toContain(`8${sign}25 mm`);
      expect(ra).toContain(`0${sign}0125 mm`);
      for (const line of messages) {
        expect(line, line).not.toMatch(/undefined|NaN|Infinity|null|\n/);
        expect(ENGLISH.test(line), line).toBe(false);
        if (c.lang === 'ja') expect(/[\u3000-\u30ff\u4e00-\u9fff]/.test(line), line).toBe(true);
      }
      // The target Ra's bound is said at this point, not on a surface.
      expect(ra).toContain(c.lang === 'de' ? 'an diesem Punkt' : 'この点');
    });
});

describe("a radius field's own errors in Japanese and German (curvedText.ts radiusFieldIn)", () => {
  const TEXTS = ['', 'abc', '-40', '0'];

  it('English: as the page words them (curvedRequest.ts radiusMm), in force with no catalogue', () => {
    const own = (t: string) => radiusMm({ ...CURVED_STATE, fields: { ...CURVED_STATE.fields, Rf: t } }, 'Rf');
    expect(TEXTS.map((t) => (own(t) as PageFieldError).message)).toEqual([
      'Feed radius Rf is missing: enter a radius, or choose straight.',
      'Feed radius Rf must be a number (got "abc").',
      'Feed radius Rf must be a positive number: convex or concave is chosen beside it (got -40).',
      'Feed radius Rf must be a positive number: convex or concave is chosen beside it (got 0).',
    ]);
    expect(own('80')).toBe(80);
  });

  for (const c of [ja, de])
    it(`${c.lang}: each its own line on its field, naming the field, quoting what was typed, no English word`, () => {
      const worded = TEXTS.map((t) => c.radiusField('Rc', t, parseField(t)));
      expect(worded.map((m) => m.key)).toEqual(['Rc', 'Rc', 'Rc', 'Rc']);
      const [missing, nan, sign, zero] = worded.map((m) => m.message) as string[];
      expect(new Set([missing, nan, sign]).size).toBe(3);
      for (const line of [missing, nan, sign, zero] as string[]) {
        expect(line).toContain(c.fields.Rc.label);
        expect(line, line).not.toMatch(/undefined|NaN|null/);
        expect(ENGLISH.test(line), line).toBe(false);
        if (c.lang === 'ja') expect(/[\u3000-\u30ff\u4e00-\u9fff]/.test(line), line).toBe(true);
      }
      expect(nan).toContain('"abc"');
      expect(sign).toContain('-40');
      expect(zero).toContain('0');
    });
});
