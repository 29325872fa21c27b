/**
 * A link notice's details in Japanese and German (issue 30, i18n/linkNotices.ts): every detail the
 * page writes in English when it replaces a link's value (read from its own functions here: state.ts
 * parseUrl, themeChoice.ts, present.ts, langChoice.ts; app.ts's view= as it writes it) is read back,
 * worded with no English word left, its parameters and the values quoted kept; a detail not read
 * back keeps all of them English (the notice marks that part so). Compiled with the page (present.ts
 * has DOM types).
 */
import { describe, expect, it } from 'vitest';
import { catalogue as de } from '../../../src/ui/i18n/de';
import { catalogue as ja } from '../../../src/ui/i18n/ja';
import { chooseLang } from '../../../src/ui/i18n/langChoice';
import { linkDetailsIn } from '../../../src/ui/i18n/linkNotices';
import { noticeParts } from '../../../src/ui/i18n/noticeWords';
import { linkNotice } from '../../../src/ui/messages';
import { parsePresent } from '../../../src/ui/present';
import { parseUrl } from '../../../src/ui/state';
import { parseTheme } from '../../../src/ui/themeChoice';

const BASE = 'R=3&Rcr=1&rho=5&h=0.05';
/** One link per kind of detail (parseUrl's), each giving at least one. */
const LINKS = [
  'R=3&Rcr=abc&rho=5&h=0.05',
  'Rcr=1',
  'R=3&R=4&R=5&R=6&R=7&R=8&Rcr=1&rho=5&h=0.05',
  'R=3&R=4&Rcr=1&rho=5&h=0.05',
  'R=3&D=6&Rcr=1&rho=5&h=0.05',
  `unit=cm&${BASE}`,
  `${BASE}&fz=0.1&F=1000&n=5000`,
  `${BASE}&surfaceRadius=abc`,
  `${BASE}&feedRadius=abc`,
  `${BASE}&surfaceRadius=30&feedRadius=80&crossRadius=40`,
  `${BASE}&runout=abc`,
  'D=abc&Rcr=1&rho=5&h=0.05',
];

const DETAILS = [
  ...LINKS.map((link) => {
    const { notices } = parseUrl(`?${link}`);
    expect(notices.length, link).toBeGreaterThan(0);
    return notices;
  }),
  [parseTheme('?theme=pink').notice ?? ''],
  [parsePresent('x').notice ?? ''],
  [chooseLang('?lang=fr', null, []).notice ?? ''],
  ['view="foo" is not one of profile, chart, tables, stepper, formulas, surface.'],
];

/** The English words of the details (from their sentences), none of which the translations keep ("Link" and
 * "Radius" are German too, "surface" is one of view='s values).
 */
const ENGLISH =
  /(?<!\p{L})(is|missing|from|the|using|default|not|number|left|empty|plane|cylinder|defaults|straight|line|curvature|are|used|both|and|or|ignored|gives|one|way|times|first|more|following|system|colour|scheme|presentation|mode|off|showing|of)(?!\p{L})/giu;

describe("a link notice's details (linkNotices.ts, from the page's English)", () => {
  it('every kind of detail is given by the page', () => {
    expect(DETAILS.flat().every((d) => d.endsWith('.'))).toBe(true);
    expect(DETAILS.flat().join(' ')).toMatch(/and 2 more ignored/);
  });

  for (const c of [ja, de])
    it(`${c.lang}: each read back and worded, the parameters and values kept, no English word`, () => {
      for (const details of DETAILS) {
        const english = details.join(' ');
        const worded = linkDetailsIn(english, c);
        expect(worded, english).not.toBeNull();
        expect([...new Set((worded ?? '').match(ENGLISH) ?? [])], worded ?? '').toEqual([]);
        if (c.lang === 'ja') expect(worded).not.toMatch(/link/i);
        // The parameters with their values as the link gives them.
        for (const quoted of english.match(/[A-Za-z]\w*="[^"]*"/g) ?? []) expect(worded, english).toContain(quoted);
        for (const number of english.match(/\d+(\.\d+)?/g) ?? []) expect(worded, english).toContain(number);
      }
      // The notice: the details in the language, nothing kept English; a detail not read back: all kept.
      const replaced = noticeParts(linkNotice(DETAILS[0] ?? []), c);
      expect(replaced?.[1]).toBe('');
      expect(replaced?.[0]).toContain('Rcr="abc"');
      const unknown = [...(DETAILS[0] ?? []), 'Something else.'].join(' ');
      expect(linkDetailsIn(unknown, c)).toBeNull();
      expect(noticeParts(linkNotice([unknown]), c)?.[1]).toBe(unknown);
    });
});
