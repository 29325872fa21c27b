/**
 * The step-through's, the formulas' and the paper's tables' words in Japanese and German (issue 30):
 * every caption of the step-through's steps (each phase, merged runs, the closing line tilted or
 * not), its counter, gauge, buttons and notes; every procedure's assumptions and the formulas'
 * notes (a cylinder's either axis, the three-axis posture's box); the tables' notes, captions, head
 * and names: no English word left (Japanese: no Latin word but the paper's symbols, units and
 * authors), every number given said, each variant worded apart.
 */
import { describe, expect, it } from 'vitest';
import { PROCEDURE_KEYS } from '../../../src/core/procedures/procedures';
import { catalogue as de } from '../../../src/ui/i18n/de';
import { catalogue as ja } from '../../../src/ui/i18n/ja';
import type { FormulaWords, StepperWords, TableWords } from '../../../src/ui/i18n/teachWords';
import { EN_FORMULAS } from '../../../src/ui/views/formulaWords';
import { EN_STEPPER } from '../../../src/ui/views/stepperWords';
import { EN_TABLES } from '../../../src/ui/views/tableWords';

function stepperTexts(s: StepperWords): string[] {
  const side = s.side('right');
  return [
    s.step(3, 31),
    side,
    s.side('left'),
    s.merged('sections', 2, 5, 4),
    s.merged('passes', 7, 12, 6),
    s.start(side, '12.34', '0.5 µm', '1 mm'),
    s.approach(side, s.merged('sections', 2, 5, 4), '23.45', '0.9 mm', '0.1 mm'),
    s.approach(side, '', '23.45', '0.9 mm', '0.1 mm'),
    s.single(side, '34.56'),
    s.noSingle(side),
    s.search(side, 9, '10.00', '20.00', '15.00', '1.2345 mm', s.merged('passes', 7, 12, 6)),
    s.search(side, 9, '10.00', '20.00', '15.00', null, ''),
    s.flankConverged(side, 'wR', '0.9436 mm', '15.00'),
    s.closingUntilted('0.9436 mm', '0.9437 mm'),
    s.closingTilted('0.91 mm', '0.97 mm', '0.92 mm', '0.98 mm'),
    ...Object.values(s.same),
    s.counter(3, 31),
    s.gaugeLabel,
    s.noDs,
    s.ds('0.98765', '0.98 mm', '1 mm'),
    s.play,
    s.playOne,
    s.pause,
    s.back,
    s.forward,
    ...Object.values(s.names),
    s.intro,
    s.motion,
    s.cylinder,
  ];
}

function formulaTexts(f: FormulaWords): string[] {
  return [
    ...Object.values(f.assumes),
    f.leadOnly,
    f.maths('N'),
    f.cylinder('+30 mm', 'feed'),
    f.cylinder('-30 mm', 'cross'),
    f.notApplicable('N'),
    f.units('mm', 'µm'),
    f.units('in', 'thou'),
    f.postureTitle,
    f.postureIntro,
    f.postureLine('T', 'F', 'V'),
    ...Object.values(f.postureLabels),
    f.anglesFormula,
  ];
}

function tableTexts(t: TableWords): string[] {
  return [
    t.note,
    t.why,
    t.halfCaption,
    t.heightCaption,
    t.halfName,
    t.heightName,
    t.region('N'),
    t.table,
    t.printedHalf,
    t.load,
  ];
}

/** Latin words a Japanese text keeps: the paper's symbols, units, authors, the formulas' function names. */
const KEPT = new Set(
  'L h R D Rcr rho beta alpha psi Rs Reff Rlong d s gamma scp P hp i wR wL X Y mm in thou sin sqrt eta N T F V Redonnet 3D'.split(
    ' ',
  ),
);
/** English words of these views (from their English words), none of which German uses (shared ones, Ring, Radius, Ellipse, Maximum, linear, plausible, left out). */
const ENGLISH =
  /(?<!\p{L})(step|of|flank|right|left|box|boxes|start|section|sections|angle|where|above|lowest|point|against|move|along|towards|touches|pseudo|plane|single|bounds|search|range|every|meets|contact|runs|over|whole|half|their|farthest|crossings|with|best|crossing|out|narrows|neighbours|converged|exact|solver|gives|each|both|scene|hardly|changes|shows|last|candidates|stopped|moving|answer|from|here|between|ends|play|back|forward|first|controls|reduced|motion|press|instead|animating|paper|procedure|searches|torus|shown|only|cylinder|itself|results|choose|through|true|tool|moves|surface|leaves|projection|offset|rotated|tilt|valid|posture|ball|flat|included|approximation|centre|height|replaced|circle|ignores|curvature|far|small|lead|tends|overestimates|curves|faster|elliptic|semi|axes|stands|close|breaks|down|idea|osculates|symmetric|misses|asymmetry|brings|treats|bull|nose|calculators|bottom|play|model|applied|alone|ignored|equations|wide|scrolls|sideways|solved|reach|radial|revolved|formulas|left|approximations|below|corrected|rows|applicable|notes|under|table|lengths|angles|degrees|current|state|slope|upright|sloped|raster|programmed|waterline|cell|printed|recomputed|either|unit|highlighted|value|round|digits|tables|evaluate|did|click|condition|load|why|column|low|things|open|whether|normalised|how|reading|returns|values|agree|brute|force|sampling|convergence|view|tuned|screen|wider|calculator|the|and|to|at|on|is|it|so|by|as)(?!\p{L})/giu;

describe("the step-through's, the formulas' and the paper's tables' words", () => {
  for (const [name, c] of [
    ['ja', ja],
    ['de', de],
  ] as const)
    it(`${name}: no English word in any step's caption, note, assumption, caption or name; the numbers said`, () => {
      const texts = [...stepperTexts(c.stepper), ...formulaTexts(c.formulas), ...tableTexts(c.tables)];
      // Every word left over, with its text (µm and µin are units).
      const left = texts.flatMap((text) =>
        name === 'ja'
          ? (text.replace(/µ(m|in)\b/g, '').match(/[A-Za-z][A-Za-z0-9]*/g) ?? [])
              .filter((w) => !KEPT.has(w))
              .map((w) => `${w}: ${text}`)
          : [...text.matchAll(ENGLISH)].map((m) => `${m[0]}: ${text}`),
      );
      expect(left).toEqual([]);
      const s = c.stepper;
      expect(s.step(3, 31)).toMatch(/3.*31/);
      expect(s.merged('passes', 7, 12, 6)).toMatch(/7.*12.*6/);
      expect(s.start('S', '12.34', '0.5 µm', '1 mm')).toMatch(/^S.*12\.34°.*0\.5 µm.*1 mm/);
      expect(s.approach('S', 'M', '23.45', '0.9 mm', '0.1 mm')).toMatch(/^S.*M.*23\.45°.*0\.9 mm.*0\.1 mm/);
      const search = s.search('S', 9, '10.00', '20.00', '15.00', '1.2345 mm', 'M');
      for (const part of ['S', ' 9 ', '10.00°', '20.00°', '15.00°', '1.2345 mm', 'M'])
        expect(search, part).toContain(part);
      expect(s.flankConverged('S', 'wL', '0.9436 mm', '15.00')).toMatch(/wL = 0\.9436 mm/);
      expect(s.closingTilted('0.91 mm', '0.97 mm', '0.92 mm', '0.98 mm')).toMatch(
        /0\.91 mm.*0\.97 mm.*0\.92 mm.*0\.98 mm/,
      );
      expect(s.ds('0.98765', '0.98 mm', '1 mm')).toMatch(/0\.98765.*0\.98 mm.*1 mm/);
      // Each variant worded apart: the flanks, the runs, the phases' reasons, the buttons' names.
      expect(s.side('right')).not.toBe(s.side('left'));
      expect(s.merged('sections', 1, 2, 2)).not.toBe(s.merged('passes', 1, 2, 2));
      expect(new Set(Object.values(s.same)).size).toBe(3);
      expect(new Set(Object.values(s.names)).size).toBe(5);
      expect(new Set([s.play, s.playOne, s.pause]).size).toBe(3);
      const f = c.formulas;
      expect(Object.keys(f.assumes).sort()).toEqual([...PROCEDURE_KEYS].sort());
      expect(new Set(Object.values(f.assumes)).size).toBe(PROCEDURE_KEYS.length);
      expect(f.cylinder('+30 mm', 'feed')).toContain('+30 mm');
      expect(f.cylinder('+30 mm', 'feed')).not.toBe(f.cylinder('+30 mm', 'cross'));
      expect(f.units('in', 'thou')).toMatch(/in.*thou/);
      expect(f.postureLine('T', 'F', 'V')).toMatch(/T.*F.*V/);
      expect(c.tables.region('N')).toContain('N');
    });

  it("English: the views as written (the step counter, a caption, the formulas' lead-only note, the tables' title)", () => {
    expect(EN_STEPPER.step(3, 31)).toBe('Step 3 of 31. ');
    expect(EN_STEPPER.flankConverged(EN_STEPPER.side('left'), 'wL', '0.9436 mm', '15.00')).toBe(
      'Left flank (-Y) converged: wL = 0.9436 mm at gamma* = 15.00 deg.',
    );
    expect(EN_FORMULAS.assumes.bedi).toMatch(/^Elliptic projection: /);
    expect(EN_FORMULAS.leadOnly).toBe('Lead-only model: applied with the lead angle alone, the tilt ignored.');
    expect(EN_TABLES.load).toBe('Load this condition into the calculator');
  });
});
