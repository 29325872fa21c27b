/**
 * The results table's notes in Japanese and German (issue 30, i18n/tableNotes.ts): every sentence the
 * page writes under the table (resultsText.ts's notes made here over each procedure, each model,
 * h and L/2, a plane and a cylinder; the models' own reasons made by the core over tools that reach
 * them; the sentences results.ts, resultsOther.ts and the worker write whole, checked against their
 * sources) is read back and worded in each language, the procedures' names in it, no English word
 * left, the numbers with the locale's decimal sign; a sentence not known is kept English.
 */
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import {
  APPROXIMATION_KEYS,
  CORRECTED_KEYS,
  CURVATURE_ROWS,
  correctedRowKey,
  modelCurve,
  PROCEDURES,
} from '../../../src/core/procedures/procedures';
import { catalogue as de } from '../../../src/ui/i18n/de';
import { catalogue as ja } from '../../../src/ui/i18n/ja';
import { noteIn, noteSentences, notesIn, WHOLE_NOTES } from '../../../src/ui/i18n/tableNotes';
import { CROSS_AXIS_NOTE, curvatureNoteText, noteText } from '../../../src/ui/resultsText';
import { expectWorded } from './wordedIn';

const source = (path: string) => readFileSync(fileURLToPath(new URL(`../../../src/${path}`, import.meta.url)), 'utf8');
/** The sources that write the notes' whole sentences. */
const SOURCES = [
  'ui/results.ts',
  'ui/resultsOther.ts',
  'core/procedures/compare.ts',
  'core/procedures/compareDoublyCurved.ts',
]
  .map(source)
  .join('\n');

/** The models' own reasons, as the worker gives them (rows.ts: the model's notApplicable), over tools that reach each. */
const REASONS = [
  ...new Set(
    [0, 0.5, 3].flatMap((Rcr) =>
      [0, 1e-310, 0, 30].flatMap((rho) =>
        APPROXIMATION_KEYS.map((key) => {
          const m = modelCurve(key, { toolRadiusMm: 3, cornerRadiusMm: Rcr, leadAngleDeg: rho, tiltAngleDeg: 0 });
          return m.ok ? null : m.notApplicable;
        }),
      ),
    ),
  ),
].filter((r): r is string => r !== null);

/** Every sentence the page writes in the notes (and a row's hover title). */
const NOTES = [
  ...WHOLE_NOTES.map(([english]) => english),
  `With tilt, ${APPROXIMATION_KEYS.filter((k) => PROCEDURES[k].leadOnly)
    .map((k) => PROCEDURES[k].shortLabel)
    .join(', ')} are lead-only models: applied with the lead angle alone, the tilt ignored.`,
  ...APPROXIMATION_KEYS.flatMap((key) => [
    ...(['circle', 'ellipse'] as const).flatMap((shape) =>
      (['h', 'half'] as const).map((quantity) =>
        noteText(key, { kind: 'beyond-model', shape, quantity, valueMm: 0.0512, limitMm: 2.5 }, 'mm'),
      ),
    ),
    noteText(key, { kind: 'wall', intervalMm: 6.25, maxIntervalMm: 5.5 }, 'mm'),
  ]),
  ...CORRECTED_KEYS.flatMap((base) => {
    const key = correctedRowKey(base);
    return [
      ...(['h', 'half'] as const).map((quantity) =>
        curvatureNoteText(
          key,
          { kind: 'beyond-model', shape: 'circle', quantity, valueMm: 0.0512, limitMm: 2.5 },
          'mm',
        ),
      ),
      curvatureNoteText(key, { kind: 'wall', intervalMm: 6.25, maxIntervalMm: 5.5 }, 'mm'),
      // rows.ts's own reason for a concave surface tighter than Reff.
      `${CURVATURE_ROWS[key].shortLabel}: its effective radius is not smaller than the concave surface's radius, so the combined radius 1/(1/Reff + 1/Rs) is not positive.`,
      // A doubly curved point's corrected row (resultsOther.ts: its name, then compareDoublyCurved.ts's reason).
      `${CURVATURE_ROWS[key].shortLabel} (1/rho = 1/Reff + 1/Rc): its effective radius (2.5 mm) is not smaller than the concave radius across the feed, so the combined radius is not positive.`,
      `${CURVATURE_ROWS[key].shortLabel} (1/rho = 1/Reff + 1/Rc): h is above the widest point of the combined circle (2.5 mm).`,
      ...REASONS.filter((r) => r.startsWith(`${PROCEDURES[base].shortLabel}: `)).map(
        (r) => `${CURVATURE_ROWS[key].shortLabel} (1/rho = 1/Reff + 1/Rc): ${r}`,
      ),
    ];
  }),
  'Plane, exact (both curvatures ignored): h is at or above the flank limit of that surface.',
  ...REASONS,
];

/** English words of the notes a translation never keeps ("Radius", "Ellipse" are German too). */
const ENGLISH =
  /(?<!\p{L})(is|at|or|above|the|this|can|leave|tool|leaves|wall|not|its|and|for|model|has|no|here|on|plane|without|tilt|lead|of|curvature|circle|widest|point|height|below|with|step-over|scallop|passes|wider|than|exact|each|rows|corrected|combined|concave|surface|cylinder|procedures?|applied|answer|effective|models?)(?!\p{L})/giu;
/** The Latin words a Japanese note keeps: the paper's symbols, authors, units. */
const KEPT = new Set('h L R Rs Rc Rf Reff Rcr Rb Rshort Rlong rho sin sqrt Eq mm µm Sekine Redonnet Bedi'.split(' '));

describe("the results table's notes (tableNotes.ts, from the page's English)", () => {
  it('the page writes the whole sentences read back, and the core reaches each kind of reason', () => {
    for (const [english] of WHOLE_NOTES.filter(([e]) => e !== CROSS_AXIS_NOTE))
      expect(SOURCES.includes(english), english).toBe(true);
    expect(WHOLE_NOTES.map(([e]) => e)).toContain(CROSS_AXIS_NOTE);
    expect(SOURCES).toContain('are lead-only models: applied with the lead angle alone, the tilt ignored.');
    expect(SOURCES).toContain("notApplicable: 'h is at or above the flank limit of that surface.'");
    expect(REASONS.length).toBeGreaterThanOrEqual(6);
    // Joined by spaces, the notes split back into their sentences ("et al." never ends one).
    expect(noteSentences(NOTES.join(' '))).toEqual(NOTES);
  });

  for (const c of [ja, de])
    it(`${c.lang}: each sentence worded, no English word left, the names in the language, the decimal sign`, () => {
      const worded = NOTES.map((english) => {
        const t = expectWorded(noteIn(english, c), english, c, ENGLISH, KEPT);
        if (c.lang === 'de') expect(t, english).not.toMatch(/\d\.\d/);
        return t;
      });
      expect(new Set(worded).size).toBe(new Set(NOTES).size);
      expect(worded.join(' ')).toContain(c.procedures.names.sekine.shortLabel);
      expect(noteIn('Something the page never wrote.', c)).toBeNull();
      expect(notesIn(`${NOTES[0]} Something the page never wrote.`, c)).toEqual([
        [noteIn(NOTES[0] ?? '', c), false],
        ['Something the page never wrote.', true],
      ]);
    });
});
