/**
 * The shop sheet's words in Japanese and German (issue 30) for every kind of sheet, including those
 * the browser test does not open (a cylinder, a doubly curved point, three-axis raster and
 * waterline, the zigzag pattern, every mark, the no-scallop star): each line and legend of the
 * sheet holds no English word of the English sheet's (Japanese: no Latin word at all beyond the
 * symbols and units), and says each number it is given.
 */
import { describe, expect, it } from 'vitest';
import { type SheetCase, shopSheet } from '../../../src/core/output/shopSheet';
import { PLANE } from '../../../src/core/surfaces/cylinder';
import { validateThreeAxis } from '../../../src/core/threeAxis/validate';
import type { SheetWords } from '../../../src/ui/i18n/catalogue';
import { DE_SHEET } from '../../../src/ui/i18n/deSheet';
import { JA_SHEET } from '../../../src/ui/i18n/jaSheet';
import { sheetTitleLines } from '../../../src/ui/shopSheetText';
import { EN_SHEET } from '../../../src/ui/shopSheetWords';

const tool = { toolRadiusMm: 3, cornerRadiusMm: 1, tiltAngleDeg: 4 };

function threeAxis(raw: Parameters<typeof validateThreeAxis>[0]): SheetCase {
  const v = validateThreeAxis(raw, 'h', 0.01);
  if (!v.ok) throw new Error('valid');
  return { kind: 'three-axis', problem: v.value };
}

/** One case of each kind the sheet words differently. */
const CASES: SheetCase[] = [
  { kind: 'five-axis', ...tool, pattern: 'one-way', surface: PLANE },
  { kind: 'five-axis', ...tool, pattern: 'zigzag', surface: { kind: 'cylinder', radiusMm: -30, axis: 'cross' } },
  { kind: 'five-axis', ...tool, pattern: 'one-way', surface: { kind: 'cylinder', radiusMm: 40, axis: 'feed' } },
  { kind: 'doubly-curved', ...tool, pattern: 'one-way', radii: { feedRadiusMm: 80, crossRadiusMm: -40 } },
  threeAxis({ R: 3, Rcr: 1, slope: 20, passes: 'raster', rasterAngle: 30 }),
  threeAxis({ R: 3, Rcr: 1, slope: 30, passes: 'waterline', feedRadius: -50 }),
];

/** Every word a sheet in `words` shows, for each case, in mm and in inches. */
function everything(words: SheetWords): string[] {
  const lines = CASES.flatMap((c) =>
    (['mm', 'in'] as const).flatMap((unit) =>
      sheetTitleLines(c, shopSheet(c, [0.01 * (unit === 'in' ? 25.4 : 1)], unit), unit, '2026-12-07', words),
    ),
  );
  return [
    ...lines,
    words.title('Lxy', 'mm'),
    words.caption('L', 'mm', 'lead'),
    words.caption('dz', 'in', 'slope'),
    words.column.lead,
    words.column.slope,
    words.deg,
    words.yourH,
    words.markLabel('W', words.where('1.5 mm', 'lead', '0')),
    words.markReason('G', words.where('0.3 in', 'slope', '60')),
    ...Object.values(words.marks),
    words.noScallop,
    words.ownRow('0.05 mm'),
    words.hintHover,
    words.hintTouch,
    words.heightsLabel('mm', 12),
    words.heightsError('in', 12, null),
    words.heightsError('mm', 12, '13'),
    words.region,
    words.csv,
    words.print,
    words.close,
    words.saved('shop-sheet_R3_Rcr1_one-way_plane_tilt0_mm.csv'),
  ];
}

/** The Latin words a translation keeps: the symbols, the units, the marks' letters, file kinds. */
const KEPT = new Set('L h R D Rcr rho Rs Rf Rc Lxy dz mm in W G X Z CSV CAM'.split(' '));
const latin = (t: string) => t.match(/[A-Za-z][A-Za-z0-9]*/g) ?? [];
/** The file name a saved line quotes. */
const FILE = /shop-sheet_\S+\.csv/g;

describe("the shop sheet's words", () => {
  const english = new Set(
    [
      ...everything(EN_SHEET),
      'Lead angle rho must be at least 0 and below 90 degrees.',
      'The tool gouges this doubly curved point at this posture: the swept tool reaches inside the surface away from the contact.',
      'Scallop height h must be below 0.5 mm at this point and posture (got 1.5).',
      'Waterline passes have no step-down here.',
    ].flatMap((t) => latin(t.replace(FILE, ''))),
  );

  it('the English words are the sheet as written (the lines the sheet showed before the catalogues)', () => {
    expect(everything(EN_SHEET).slice(0, 2)).toEqual([
      'Tool: D 6 mm (R 3 mm), corner radius Rcr 1 mm',
      'Five-axis, tilt 4 deg; one-way passes; on a plane',
    ]);
    for (const w of ['doubly', 'revolution', 'concave', 'straight', 'upright', 'zigzag', 'fall', 'gouges', 'flat'])
      expect(english.has(w), w).toBe(true);
  });

  for (const [lang, words] of [
    ['ja', JA_SHEET],
    ['de', DE_SHEET],
  ] as const)
    it(`${lang}: no English word in any sheet's lines, legend, names or buttons; every number given is said`, () => {
      const own = words.refusals;
      // The sheet's own refusals (English: the core's reasons, whose words count as the sheet's).
      const refusals = [own.leadRange, own.curvedGouge, own.curvedWall('0.5 mm', '1.5'), own.noStepDown];
      expect(refusals[2]).toContain('0.5 mm');
      for (const text of [...everything(words), ...refusals]) {
        const left = latin(text.replace(FILE, '')).filter((w) => !KEPT.has(w) && (lang === 'ja' || english.has(w)));
        expect(left, text).toEqual([]);
      }
      const lines = everything(words);
      expect(lines.some((l) => l.includes('80 mm') && l.includes('-40 mm'))).toBe(true);
      expect(lines.some((l) => l.includes('-50 mm'))).toBe(true);
      expect(lines.some((l) => l.includes('30°') || l.includes('30 °'))).toBe(true);
      expect(words.saved('a.csv')).toContain('a.csv');
      expect(words.heightsError('mm', 12, '13')).toContain('13');
    });
});
