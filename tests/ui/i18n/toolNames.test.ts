/**
 * The catalogue tools' names in Japanese and German (issue 30, i18n/toolNames.ts): every preset's
 * label (toolPresets.ts, read from the registry, not copied), the preset box's "custom" and groups,
 * the chips' legend in each unit, worded with no English word left, the sizes kept with the locale's
 * decimal sign; another text is not worded.
 */
import { describe, expect, it } from 'vitest';
import { catalogue as de } from '../../../src/ui/i18n/de';
import { catalogue as ja } from '../../../src/ui/i18n/ja';
import { toolNameIn } from '../../../src/ui/i18n/toolNames';
import { PRESETS } from '../../../src/ui/toolPresets';

const OTHERS = [
  'custom',
  'metric (mm)',
  'inch',
  'Catalogue tools (mm)',
  'Catalogue tools (inch)',
  'Catalogue tools (mm, inch)',
];

describe("the catalogue tools' names (toolNames.ts)", () => {
  for (const c of [ja, de])
    it(`${c.lang}: every preset, the box's choices and groups, the legend: no English word, the sizes kept`, () => {
      const worded = [...PRESETS.map((p) => p.label), ...OTHERS].map((english) => {
        const text = toolNameIn(english, c);
        expect(text, english).not.toBeNull();
        expect(text, english).not.toMatch(/\b(corner|ball|end|paper|Tool|custom|metric|Catalogue|tools|inch)\b/);
        return text;
      });
      expect(new Set(worded).size).toBe(worded.length);
      const sign = c.lang === 'de' ? ',' : '.';
      expect(toolNameIn('D6, corner R0.5', c)).toContain(`R0${sign}5`);
      expect(toolNameIn('D1/2 in, corner R0.125 in', c)).toContain(`D1/2 in`);
      expect(toolNameIn('D6, corner R1 (paper Tool 1)', c)).toMatch(/D6.*R1.*1/);
      expect(toolNameIn('Something else', c)).toBeNull();
    });
});
