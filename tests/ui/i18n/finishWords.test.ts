/**
 * The finish box's worker messages and the Machined surface view in Japanese and German (issue 30):
 * every refusal code of the finish fields worded from the worker's data (the field as the page
 * names it, the bound in the user's unit with the locale's decimal sign, what was typed), the
 * failures of each part, the surfaces where feed marks are not computed, the box's own lines (a
 * worker restarted, the areal rows' titles, the cell map, the x3p download) and every line of the
 * surface view: no English word left (Japanese: no Latin word but the symbols and units), every
 * number given said. English keeps the worker's own sentence.
 */
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { type FinishErrorCode, finishError } from '../../../src/core/finish/finishInput';
import { TARGET_SA_RUNOUT } from '../../../src/core/roughness/targetSa';
import type { FinishWords, SurfaceWords } from '../../../src/ui/i18n/catalogue';
import { catalogue as de } from '../../../src/ui/i18n/de';
import { finishMessageIn, finishScopeIn, targetSaMessageIn } from '../../../src/ui/i18n/finishText';
import { catalogue as ja } from '../../../src/ui/i18n/ja';
import { EN_SURFACE, exceptionDetail, exceptionIn } from '../../../src/ui/views/surfaceWords';
import type { FinishFieldMessage } from '../../../src/worker/finishProtocol';

/** worker/simulate.ts's source: its reason for an exception, read back by surfaceWords.ts exceptionIn. */
const SIMULATE = readFileSync(fileURLToPath(new URL('../../../src/worker/simulate.ts', import.meta.url)), 'utf8');

/** One worker refusal per code, as the worker sends it (its English and its data; lengths in mm). */
const REFUSALS: ReadonlyArray<readonly [FinishFieldMessage['field'], FinishErrorCode, string, number?]> = [
  ['fz', 'missing', ''],
  ['fz', 'not-a-number', 'abc'],
  ['runout', 'not-finite', 'Infinity'],
  ['flutes', 'not-an-integer', '2.5'],
  ['feedRate', 'not-positive', '0'],
  ['spindleSpeed', 'not-positive', '-5'],
  ['runout', 'negative', '-0.01'],
  ['fz', 'too-small', '0.0000001', 1e-6],
  ['fz', 'too-large', '5', 3],
  ['runout', 'too-large', '0.5', 0.3],
  ['flutes', 'too-large', '80', 64],
  ['passPhase', 'out-of-range', '1.5'],
  ['fz', 'both-feeds', '0.1'],
  ['fz', 'rate-too-small', '0.0000005', 1e-6],
  ['fz', 'rate-too-large', '3.5', 3],
  ['fz', 'not-computed-here', ''],
];

/** The worker's message of a refusal: its English sentence in mm and its data. */
function refusal(field: FinishFieldMessage['field'], code: FinishErrorCode, got: string, limit?: number) {
  const { message, ...error } = finishError(field, code, got, limit);
  return { field, message, error } satisfies FinishFieldMessage;
}

function finishTexts(f: FinishWords): string[] {
  return [
    f.failure('not-converged', 'marks'),
    f.failure('not-converged', 'areal'),
    f.failure('not-swept', 'marks'),
    f.failure('not-swept', 'areal'),
    ...(['cylinder', 'doublyCurved', 'waterlineRevolution', 'other'] as const).map((k) => f.scope(k)),
    f.worker(true, 'R'),
    f.worker(false, 'R'),
    ...Object.values(f.areal),
    f.mapLabel,
    f.mapScale('0.1 mm', '1.2 mm', '0.45 µm'),
    f.x3pComputing,
    f.x3pNone(null),
    f.x3pNone('M'),
    f.x3pGaveUp('R'),
    f.x3pSaved('finish.x3p', 256),
    f.targetSa.runout,
    f.targetSa.tooLong,
    f.targetSa.worker(true, 'R'),
    f.targetSa.worker(false, 'R'),
  ];
}

function surfaceTexts(s: SurfaceWords): string[] {
  return [
    s.invalid,
    s.failed,
    s.pending(null),
    s.pending(40),
    ...Object.values(s.reasons),
    s.exception('42'),
    s.exaggeration(null, 'µm'),
    s.exaggeration(20, 'µin'),
    s.comparison('1.2 µm', '1.25 µm', '0.05 µm', true, '0.1 µm', '120 x 120', 5),
    s.comparison('1.2 µm', '1.5 µm', '0.3 µm', false, '0.1 µm', '120 x 120', 5),
    s.traceLabel,
    s.traceCaption(5, '2 µm', '0.5 µm', '0.6 µm'),
    s.meanLine,
    s.sceneLabel,
  ];
}

const KEPT = new Set(
  'L h R D Rcr fz F n z e q Sa Sq Sz Sp Sv Ssk Sku Rz Ra Rq x3p finish mm in min rpm µm µin CC M R W 3D Infinity abc'.split(
    ' ',
  ),
);
const ENGLISH =
  /\b(must|missing|number|whole|teeth|greater|than|least|most|tool|radius|below|fraction|feed|period|give|not|both|could|computed|search|converge|try|smaller|defined|thin|slivers|passes|cut|tooth|bottom|edges|miss|yet|only|plane|lead|tilt|worker|gave|up|restarted|again|root|mean|square|height|highest|peak|deepest|valley|skewness|kurtosis|heights|cell|coloured|lowest|blue|along|across|drawn|not to scale|computing|surface|saved|over|out of date|inputs|invalid|nothing|simulate|solver|change|input|simulating|the|covers|cylinder|exact|values|still|hold|scallop|flat|lying|leaves|true|scale|exaggerated|vertical|exaggeration|colour|above|point|simulated|cusp|against|differ|within|beyond|stated|resolution|bound|cells|profilometer|trace|marked|line|view|machined|by|and|of|to|at|on|in a)\b/i;

describe("the finish box's and the surface view's words", () => {
  for (const [name, c] of [
    ['ja', ja],
    ['de', de],
  ] as const)
    it(`${name}: every refusal code, failure, surface, the box's lines and the surface view's: no English word; the numbers said`, () => {
      const worded = REFUSALS.map(([field, code, got, limit]) =>
        finishMessageIn(c, refusal(field, code, got, limit), 'mm'),
      );
      const texts = [...worded, ...finishTexts(c.finishText), ...surfaceTexts(c.surface)];
      for (const text of texts) {
        if (name === 'ja')
          for (const w of text.match(/[A-Za-zµ][A-Za-z0-9]*/g) ?? []) expect(KEPT.has(w), `${text}: "${w}"`).toBe(true);
        else expect(ENGLISH.exec(text)?.[0] ?? null, text).toBeNull();
      }
      // Each code has its own words, and every refusal quotes what was typed.
      expect(new Set(worded).size).toBe(REFUSALS.length);
      REFUSALS.forEach(([, code, got], i) => {
        if (got !== '' && !['both-feeds', 'rate-too-small', 'rate-too-large'].includes(code))
          expect(worded[i], code).toContain(got.length > 24 ? got.slice(0, 21) : got);
      });
      // The bound in the user's unit with the locale's decimal sign: R = 3 mm is 0.11811 in.
      const sign = name === 'de' ? ',' : '.';
      expect(finishMessageIn(c, refusal('fz', 'too-large', '5', 3), 'in')).toContain(`0${sign}11811 in`);
      expect(finishMessageIn(c, refusal('fz', 'rate-too-large', '3.5', 3), 'mm')).toContain(`3${sign}5 mm`);
      expect(finishMessageIn(c, refusal('fz', 'missing', ''), 'mm')).toContain(c.fields.fz.label);
      expect(finishMessageIn(c, refusal('flutes', 'not-an-integer', '2.5'), 'mm')).toContain('64');
      // The failures carry their part; the scope names its surface.
      expect(c.finishText.failure('not-swept', 'areal')).not.toBe(c.finishText.failure('not-swept', 'marks'));
      expect(
        new Set((['cylinder', 'doublyCurved', 'waterlineRevolution', 'other'] as const).map(c.finishText.scope)).size,
      ).toBe(4);
      expect(c.finishText.worker(true, 'out of memory')).toContain('out of memory');
      expect(c.finishText.mapScale('0.1 mm', '1.2 mm', '0.45 µm')).toMatch(/0\.1 mm.*1\.2 mm.*0\.45 µm/);
      expect(c.finishText.x3pSaved('finish.x3p', 256)).toMatch(/finish\.x3p.*256.*256/);
      expect(c.surface.comparison('1.2 µm', '1.25 µm', '0.05 µm', true, '0.1 µm', '120 x 120', 5)).toMatch(
        /1\.2 µm.*1\.25 µm.*0\.05 µm.*0\.1 µm.*120.*120.*5/,
      );
      expect(c.surface.comparison('a', 'b', 'c', true, 'd', 'e', 5)).not.toBe(
        c.surface.comparison('a', 'b', 'c', false, 'd', 'e', 5),
      );
      expect(c.surface.traceCaption(5, '2 µm', '0.5 µm', '0.6 µm')).toMatch(/5.*2 µm.*0\.5 µm.*0\.6 µm/);
      expect(c.surface.pending(40)).toContain('40 %');
      // An exception: a sentence of the language, its own text left out for the hover title (exceptionDetail);
      // the worker's English read back (worker/simulate.ts writes it so).
      expect(c.surface.exception('RangeError: Ra 2 > 1')).not.toMatch(/RangeError|Ra 2/);
      expect(c.surface.exception('X')).not.toBe(EN_SURFACE.exception('X'));
      expect(exceptionIn('No simulation: RangeError: Ra 2 > 1', c.surface)).toBe(
        c.surface.exception('RangeError: Ra 2 > 1'),
      );
      expect(exceptionDetail('No simulation: RangeError: Ra 2 > 1', c.surface)).toBe('RangeError: Ra 2 > 1');
      expect(exceptionDetail('No simulation: RangeError: Ra 2 > 1', EN_SURFACE)).toBe('');
      expect(exceptionIn('No simulation: RangeError: Ra 2 > 1', EN_SURFACE)).toBe(
        'No simulation: RangeError: Ra 2 > 1',
      );
      expect(SIMULATE).toMatch(/`No simulation: \$\{String\(e\)\}`/);
      expect(c.surface.exaggeration(20, 'µin')).toMatch(/20.*µin/);
    });

  it("the target-Sa box's messages: its own refusals by name, the teeth's from their data, English the worker's", () => {
    const runout = { field: 'runout', message: TARGET_SA_RUNOUT, refusal: 'runout' } as const;
    const tooLong = { field: 'flutes', message: 'T', refusal: 'tooLong' } as const;
    const teeth = refusal('runout', 'too-large', '0.5', 0.3);
    for (const c of [ja, de]) {
      expect(targetSaMessageIn(c, runout, 'mm')).toBe(c.finishText.targetSa.runout);
      expect(targetSaMessageIn(c, tooLong, 'mm')).toBe(c.finishText.targetSa.tooLong);
      expect(targetSaMessageIn(c, teeth, 'in')).toBe(finishMessageIn(c, teeth, 'in'));
      expect(c.finishText.targetSa.worker(true, 'out of memory')).toContain('out of memory');
    }
    expect(targetSaMessageIn(de, teeth, 'mm')).toContain('0,3 mm');
    for (const m of [runout, tooLong, teeth]) expect(targetSaMessageIn(null, m, 'mm')).toBe(m.message);
  });

  it("English: the worker's own sentences, unchanged", () => {
    const m = refusal('fz', 'too-large', '5', 3);
    expect(finishMessageIn(null, m, 'in')).toBe(m.message);
    expect(finishScopeIn(null, 'cylinder', 'E')).toBe('E');
    expect(finishScopeIn(de, 'somewhere', 'E')).toBe(de.finishText.scope('other'));
    const failure = { field: 'fz', message: 'F', failure: { kind: 'not-converged', part: 'marks' } } as const;
    expect(finishMessageIn(null, failure, 'mm')).toBe('F');
    expect(finishMessageIn(ja, failure, 'mm')).toBe(ja.finishText.failure('not-converged', 'marks'));
  });
});
