/**
 * What L and the heights mean on the surface asked, in Japanese and German (issue 30,
 * i18n/meaningWords.ts): every sentence the page writes under the results (resultsText.ts
 * surfaceMeaning on each cylinder, resultsText.ts curvedMeaning at each kind of doubly curved
 * point, in mm and in inches) is read back and worded in each language, its radii kept with the
 * locale's decimal sign, no English word left; a sentence the page never wrote is not worded.
 */
import { describe, expect, it } from 'vitest';
import type { CylinderSurface } from '../../../src/core/domain/surface';
import { catalogue as de } from '../../../src/ui/i18n/de';
import { catalogue as ja } from '../../../src/ui/i18n/ja';
import { meaningIn } from '../../../src/ui/i18n/meaningWords';
import { curvedMeaning, surfaceMeaning } from '../../../src/ui/resultsText';
import { expectWorded } from './wordedIn';

/** Every sentence, with the radii it names (as the page writes them, in its unit). */
const SENTENCES = (['mm', 'in'] as const).flatMap((unit) => [
  ...([12.5, -40.25] as const).flatMap((radiusMm) =>
    (['feed', 'cross'] as const).map((axis) =>
      surfaceMeaning({ kind: 'cylinder', radiusMm, axis } as CylinderSurface, unit),
    ),
  ),
  ...(
    [
      [50.5, 80],
      [50, -80.75],
      [-60, 120],
      [-60, -90.5],
    ] as const
  ).map(([f, c]) => curvedMeaning(f, c, unit)),
]);

const ENGLISH =
  /(?<!\p{L})(on|this|at|convex|concave|cylinder|axis|along|across|feed|passes|run|go|around|step|and|the|flank|widths?|reaches|are|arc|lengths|surface|between|paths|every|height|is|measured|radially|from|doubly|curved|point|plane|through|contact)(?!\p{L})/giu;
/** The Latin a Japanese sentence keeps: the paper's symbols and the units. */
const KEPT = new Set(['L', 'Rf', 'Rc', 'CC', 'mm', 'in', 'µm']);

describe('what L and the heights mean on the surface (meaningWords.ts, from the page English)', () => {
  it('the page writes a sentence for each cylinder and doubly curved point, each naming its radii', () => {
    expect(SENTENCES).toHaveLength(16);
    expect(new Set(SENTENCES).size).toBe(16);
    expect(SENTENCES[0]).toMatch(/^On this convex cylinder \(radius 12\.5\d* mm, axis along the feed/);
  });

  for (const c of [ja, de])
    it(`${c.lang}: each sentence worded, its radii kept, no English word left`, () => {
      const worded = SENTENCES.map((english) => {
        const t = expectWorded(meaningIn(english, c), english, c, ENGLISH, KEPT);
        // Each radius the English names, with the language's decimal sign.
        const radii = [...english.matchAll(/(\d+\.\d+) (mm|in)\b/g)].map((m) => m[1] ?? '');
        expect(radii.length).toBeGreaterThan(0);
        for (const r of radii) expect(t, english).toContain(c.lang === 'de' ? r.replace('.', ',') : r);
        return t;
      });
      // Side and axis carried: no two sentences worded alike.
      expect(new Set(worded).size).toBe(SENTENCES.length);
      expect(meaningIn('Something the page never wrote.', c)).toBeNull();
    });
});
