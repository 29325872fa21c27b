/**
 * The catalogues cannot drift (issue 30 point 3): the type check fails on a missing or an extra key
 * (catalogue.ts); here, the page's `data-i18n` keys are exactly the catalogues' page keys, every
 * field of the registry that the page shows has its words, and no Japanese or German word is left
 * in English: a Japanese entry holds Japanese script, and no Latin word beyond the paper's symbols,
 * names and units; a German entry differs from the English one beside it and uses no English word
 * from a list of the page's own (step, scallop, tool, feed...).
 */
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { PAGE_FIELD_KEYS } from '../../../src/core/input/fields';
import { PROCEDURE_KEYS, PROCEDURES } from '../../../src/core/procedures/procedures';
import type { Catalogue } from '../../../src/ui/i18n/catalogue';
import { catalogue as de } from '../../../src/ui/i18n/de';
import { catalogue as ja } from '../../../src/ui/i18n/ja';
import { PRESET_LABELS } from '../../../src/ui/surfaceState';
import { formulaNumber } from '../../../src/ui/views/formulaSlots';

const HTML = readFileSync(fileURLToPath(new URL('../../../index.html', import.meta.url)), 'utf8');
/** index.html's data-i18n keys and their English text (the page as written). */
const ENGLISH = new Map(
  [...HTML.matchAll(/data-i18n="([^"]+)"[^>]*>([^<]*)</g)].map((m) => [m[1] as string, (m[2] as string).trim()]),
);

/** Every string of a catalogue, with where it is. */
function strings(c: Catalogue): Array<[string, string]> {
  return [
    ...Object.entries(c.page).map(([k, v]) => [`page.${k}`, v] as [string, string]),
    ...Object.entries(c.fields).flatMap(([k, w]) => [
      [`fields.${k}.label`, w.label] as [string, string],
      [`fields.${k}.hint`, w.hint] as [string, string],
    ]),
    ['diameter.label', c.diameter.label],
    ['diameter.hint', c.diameter.hint],
    ['diameter.cornerHint', c.diameter.cornerHint],
    ...Object.entries(c.labels).map(([k, v]) => [`labels.${k}`, v] as [string, string]),
    ['degrees', c.degrees],
    ['slider', c.slider],
    ...Object.entries(c.question).map(([k, v]) => [`question.${k}`, v] as [string, string]),
    ...Object.entries(c.finish).map(([k, v]) => [`finish.${k}`, v] as [string, string]),
    ...Object.entries(c.tabs).map(([k, v]) => [`tabs.${k}`, v] as [string, string]),
    ...Object.entries(c.phrases).map(([k, v]) => [`phrases.${k}`, v] as [string, string]),
    ['headline.stepOver', c.headline.stepOver],
    ['headline.scallopHeight', c.headline.scallopHeight],
    ...Object.entries({ ...c.procedures.names, ...c.procedures.rows }).flatMap(([k, n]) => [
      [`procedures.${k}.label`, n.label] as [string, string],
      [`procedures.${k}.shortLabel`, n.shortLabel] as [string, string],
    ]),
    ...Object.entries(c.procedures.head).map(([k, v]) => [`procedures.head.${k}`, v] as [string, string]),
    ['procedures.leadOnly', c.procedures.leadOnly],
    ...Object.entries(c.procedures.curved).map(([k, v]) => [`procedures.curved.${k}`, v] as [string, string]),
    ...Object.entries(c.procedures.assumes).map(([k, v]) => [`procedures.assumes.${k}`, v] as [string, string]),
    ...Object.entries(c.procedures.curvedTitles).map(
      ([k, v]) => [`procedures.curvedTitles.${k}`, v] as [string, string],
    ),
    ...noteStrings(c),
    ['said.notAvailable', c.said.notAvailable],
    ...Object.entries(c.said.surfacePresets).map(([k, v]) => [`said.surfacePresets.${k}`, v] as [string, string]),
    ['said.rasterNote', c.said.rasterNote],
    ...(['failed', 'threw', 'load', 'stopped'] as const).map(
      (k) => [`said.reason.${k}`, c.said.reason(k)] as [string, string],
    ),
    ...[true, false].map(
      (g) => [`said.tableWorker.${g}`, c.said.tableWorker(g, c.said.reason('threw'))] as [string, string],
    ),
    ['said.tableComputing', c.said.tableComputing],
    [
      'said.tableSaved.five',
      c.said.tableSaved(
        'x.CSV',
        120,
        ['0.001', '0.05'],
        'mm',
        { kind: 'five-axis', lead: ['0', '45'], tilt: ['0', '10'] },
        7,
      ),
    ],
    [
      'said.tableSaved.three',
      c.said.tableSaved(
        'x.CSV',
        120,
        ['0.001', '0.05'],
        'mm',
        { kind: 'three-axis', slope: ['0', '80'], step: 'Lxy' },
        7,
      ),
    ],
  ];
}

/** The table notes' sentences (tableNotes.ts), each made with a procedure's name in the language and numbers. */
function noteStrings(c: Catalogue): Array<[string, string]> {
  const n = c.procedures.notes;
  const name = c.procedures.names.sekine.shortLabel;
  const said: Array<[string, string]> = [
    ['noScallop', n.noScallop],
    ['leadOnly', n.leadOnly(name)],
    ['cylinder', n.cylinder],
    ['crossAxis', n.crossAxis],
    ['curved', n.curved],
    ['curvedInverse', n.curvedInverse],
    ['planeBeyond', n.planeBeyond],
    ['reason', n.reason(name, c.chart.reasons.sekineShort)],
    ['notPositive', n.notPositive(name, '3 mm')],
    ['flankLimit', n.flankLimit(name)],
    ['combinedWidest', n.combinedWidest(name, '3 mm')],
    ...[true, false].map((cyl) => [`wall.${cyl}`, n.wall(name, '4 mm', '3 mm', cyl)] as [string, string]),
    ...(['circle', 'ellipse', 'combined'] as const).flatMap((model) =>
      (['Reff', 'height', 'halfWidth', 'rho'] as const).flatMap((limit) =>
        (['h', 'L/2'] as const).map(
          (what) =>
            [`beyond.${model}.${limit}.${what}`, n.beyond(name, what, '1 mm', model, limit, '2 mm')] as [
              string,
              string,
            ],
        ),
      ),
    ),
  ];
  return said.map(([k, v]) => [`procedures.notes.${k}`, v]);
}

/**
 * Latin words a translation keeps: the paper's symbols (P_hp, P_base, CC, O, y0) and authors, names,
 * units, file kinds, key names (Ctrl+C) and the embed code's HTML elements (iframe, path-interval-calculator).
 */
const KEPT = new Set(
  'L h R D Rcr rho beta alpha psi Rs Rf Rc Lxy dz Ra z fz e q X Y Z CSV CAM Fusion Sekine Redonnet Bedi Kameya Enter hf Sa ISO M3 x3p F n x y P hp base CC O y0 N i L0 Reff Rlong sin sqrt Esc mm error Ctrl C iframe path interval calculator'.split(
    ' ',
  ),
);

/** Entries whose German is the English word too ("Radius R", a sentence's full stop). */
const SAME_IN_GERMAN = new Set(['sizeR', 'fullStop']);

describe('the catalogues', () => {
  it("the page's data-i18n keys are the catalogues' page keys, both ways", () => {
    const keys = [...ENGLISH.keys()].sort();
    expect(keys.length).toBeGreaterThan(40);
    expect(Object.keys(ja.page).sort()).toEqual(keys);
    expect(Object.keys(de.page).sort()).toEqual(keys);
  });

  it("the page's data-i18n-label keys (its landmarks' names) are the catalogues' label keys, each worded", () => {
    const labels = [...HTML.matchAll(/aria-label="([^"]+)" data-i18n-label="([^"]+)"/g)];
    expect(labels.length).toBe(9);
    for (const c of [ja, de]) {
      expect(Object.keys(c.labels).sort()).toEqual(labels.map((m) => m[2]).sort());
      for (const [, english, key] of labels) expect(c.labels[key as keyof Catalogue['labels']]).not.toBe(english);
    }
  });

  it('every field the page shows has its words in each language', () => {
    for (const c of [ja, de]) expect(Object.keys(c.fields).sort()).toEqual([...PAGE_FIELD_KEYS].sort());
  });

  it('Japanese: each entry holds Japanese script, and its Latin words are symbols or names only', () => {
    for (const [where, text] of strings(ja)) {
      expect(/[\u3000-\u30ff\u4e00-\u9fff]/.test(text), `${where}: ${text}`).toBe(true);
      for (const word of text.match(/[A-Za-z][A-Za-z0-9]*/g) ?? [])
        expect(KEPT.has(word), `${where}: "${word}"`).toBe(true);
    }
  });

  it("the procedures' names keep the registry's authors and the paper's equation numbers, for every procedure", () => {
    for (const c of [ja, de])
      for (const key of PROCEDURE_KEYS) {
        const english = PROCEDURES[key];
        const name = c.procedures.names[key];
        expect(name.label.match(/\d+/g), `${c.lang} ${key}`).toEqual(english.label.match(/\d+/g));
        const author = /^[A-Z][a-z]+(?= et al\.)/.exec(english.label)?.[0];
        if (author !== undefined) expect(name.shortLabel.startsWith(author), `${c.lang} ${key}`).toBe(true);
        expect(name.label, `${c.lang} ${key}`).not.toBe(english.label);
      }
  });

  it("the words the page's first code writes in English (surfaceState.ts, formulaSlots.ts, fields.ts) are other words in each language", () => {
    const fields = readFileSync(fileURLToPath(new URL('../../../src/ui/fields.ts', import.meta.url)), 'utf8');
    expect(fields).toContain("'custom radii'");
    expect(formulaNumber(null)).toBe('n/a');
    for (const c of [ja, de]) {
      expect(Object.keys(c.said.surfacePresets).sort()).toEqual([...Object.keys(PRESET_LABELS), 'custom'].sort());
      for (const [key, text] of Object.entries(c.said.surfacePresets))
        expect(text, `${c.lang} ${key}`).not.toBe(
          key === 'custom' ? 'custom radii' : PRESET_LABELS[key as keyof typeof PRESET_LABELS],
        );
      expect(c.said.notAvailable).not.toMatch(/^n\/?a$/i);
      expect(fields).not.toContain(c.said.rasterNote);
    }
  });

  it('German: no entry is the English one, and none uses an English word of the page', () => {
    const english =
      /\b(step|over|scallop|height|tool|feed|tooth|teeth|flutes?|lead|tilt|angle|surface|plane|radius of|pass(es)?|one-way|copy|download|sheet|table|along|across|the|and|of|slider|deg|inch)\b/i;
    for (const [where, text] of strings(de)) {
      const key = where.replace(/^page\./, '');
      if (ENGLISH.has(key) && !SAME_IN_GERMAN.has(key))
        expect(text.toLowerCase(), where).not.toBe(ENGLISH.get(key)?.toLowerCase());
      expect(english.test(text), `${where}: ${text}`).toBe(false);
    }
  });
});
