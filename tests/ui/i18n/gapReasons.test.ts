/**
 * A chart gap's reason in Japanese and German (issue 30, views/gapReasons.ts): every reason the core
 * gives for a procedure without an answer (core/procedures/sweepGaps.ts noAnswerReason, made here over
 * tools and postures that reach each one: a flat end, a ball, no lead, a subnormal lead; the
 * others, h beyond each model's widest point or the posture's limit) is read back against the English words and worded
 * in each language, no English word left, its symbols kept; a sentence not known is not worded.
 */
import { describe, expect, it } from 'vitest';
import { PROCEDURE_KEYS } from '../../../src/core/procedures/procedures';
import { noAnswerReason } from '../../../src/core/procedures/sweepGaps';
import { catalogue as de } from '../../../src/ui/i18n/de';
import { catalogue as ja } from '../../../src/ui/i18n/ja';
import { EN_CHART } from '../../../src/ui/views/chartWords';
import { gapReasonIn } from '../../../src/ui/views/gapReasons';

/** Every reason the core gives over the grid. */
const REASONS = [
  ...new Set(
    [0, 0.5, 1, 3].flatMap((Rcr) =>
      [0, 1e-310, 0.5, 5, 30, 89].flatMap((rho) =>
        [0, 5].flatMap((tilt) =>
          PROCEDURE_KEYS.map((key) =>
            noAnswerReason(key, { toolRadiusMm: 3, cornerRadiusMm: Rcr, leadAngleDeg: rho, tiltAngleDeg: tilt }),
          ),
        ),
      ),
    ),
  ),
];

/** The English words of the reasons, none of which the translations keep ("Radius", "Ellipse" are German too). */
const ENGLISH =
  /(?<!\p{L})(is|at|or|above|the|highest|scallop|this|posture|can|leave|tool|leaves|wall|not|projected|degenerates|to|line|its|long|infinite|short|effective|flat|and|divides|by|overflows|too|close|for|model|has|no|answer|here|bottom|lies|on|plane|without|tilt|lead|small|count|so|of|curvature|contact|sharp|edge|circle|end|corner|ball|widest|point|height|below)(?!\p{L})/giu;

/** The Latin words a Japanese reason keeps: the paper's symbols. */
const KEPT = new Set('h rho Rshort sin Rb Rcr Rlong Reff Eq'.split(' '));

describe("a chart gap's reason (gapReasons.ts, from the core's English)", () => {
  it('the grid reaches every kind of reason, and each reads back to itself in English', () => {
    expect(REASONS.length).toBeGreaterThanOrEqual(12);
    for (const reason of REASONS) expect(gapReasonIn(reason, EN_CHART), reason).toBe(reason);
    expect(gapReasonIn('some other reason', EN_CHART)).toBeNull();
  });

  for (const c of [ja, de])
    it(`${c.lang}: each reason worded, no English word left, its symbols kept, each worded apart`, () => {
      const worded = REASONS.map((reason) => {
        const text = gapReasonIn(reason, c.chart);
        expect(text, reason).not.toBeNull();
        expect([...new Set((text ?? '').match(ENGLISH) ?? [])], text ?? '').toEqual([]);
        if (c.lang === 'ja')
          expect((text ?? '').match(/[A-Za-z][A-Za-z0-9]*/g)?.filter((w) => !KEPT.has(w)) ?? [], text ?? '').toEqual(
            [],
          );
        for (const symbol of reason.match(/\b(Reff|Rcr|Rlong sin\(rho\)|Rshort|Rb)\b/g) ?? [])
          expect(text, reason).toContain(symbol);
        return text;
      });
      expect(new Set(worded).size).toBe(REASONS.length);
      expect(gapReasonIn('some other reason', c.chart)).toBeNull();
    });
});
