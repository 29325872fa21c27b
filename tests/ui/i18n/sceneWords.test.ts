/**
 * The 3D scene's labels in Japanese and German (issue 30): the dimensions keep their symbols and
 * every digit, with the locale's decimal sign; the word "arc" and the scene's own words (the
 * surfaces' names, a cusp, the step-through's point, the feed axis) and its accessible name are the
 * language's: no English word left (Japanese: no Latin word but the symbols and units).
 */
import { describe, expect, it } from 'vitest';
import { SCENE_WORDS } from '../../../src/render/sceneWords';
import { catalogue as de } from '../../../src/ui/i18n/de';
import { catalogue as ja } from '../../../src/ui/i18n/ja';
import type { SceneLabelTexts } from '../../../src/ui/sceneLabelTexts';

const ENGLISH_LABELS: SceneLabelTexts = {
  interval: 'L = 2.8872 mm',
  halfInterval: 'L/2 = 1.4436 mm',
  arc: true,
  contactOffset: 'y0 = -0.1234 mm',
  programmedStep: 'Lxy = 0.9100 mm',
};

const KEPT = new Set('L y0 Lxy dz mm in P hp base i h R X D'.split(' '));
const ENGLISH = new RegExp(
  `\\b(${[
    ...Object.values(SCENE_WORDS).flatMap((w) => (typeof w === 'string' ? [w] : [w(null), w(5)])),
    'arc',
    'view',
    'tool',
    'posture',
    'passes',
    'sections',
  ]
    .flatMap((w) => w.match(/[a-z]{3,}/g) ?? [])
    .join('|')})\\b`,
  'i',
);

describe("the 3D scene's labels", () => {
  for (const [name, c, sign] of [
    ['ja', ja, '.'],
    ['de', de, ','],
  ] as const)
    it(`${name}: the symbols and digits kept with the locale's decimal sign, no English word, every word given`, () => {
      const l = c.scene.labels(ENGLISH_LABELS);
      expect(l.interval).toBe(`L = 2${sign}8872 mm`);
      expect(l.halfInterval).toBe(`L/2 = 1${sign}4436 mm`);
      expect(l.arc).toBe(true);
      expect(l.contactOffset).toBe(`y0 = -0${sign}1234 mm`);
      expect(l.programmedStep).toBe(`Lxy = 0${sign}9100 mm`);
      expect(c.scene.labels({ ...ENGLISH_LABELS, contactOffset: null }).contactOffset).toBeNull();
      const words = Object.values(l.words ?? {}).flatMap((w) => (typeof w === 'string' ? [w] : [w(null), w(5)]));
      expect(Object.keys(l.words ?? {}).length).toBe(Object.keys(SCENE_WORDS).length);
      // The scale badge and its title say how many times the heights are drawn taller.
      expect(l.words?.scale(5)).toContain('5');
      expect(l.words?.scaleTitle(5)).toContain('5');
      const texts = [l.interval, l.halfInterval, l.name ?? '', ...words];
      for (const text of texts) {
        expect(text).not.toBe('');
        if (name === 'ja')
          for (const w of text.match(/[A-Za-z][A-Za-z0-9]*/g) ?? []) expect(KEPT.has(w), `${text}: "${w}"`).toBe(true);
        else expect(ENGLISH.exec(text)?.[0] ?? null, text).toBeNull();
      }
    });
});
