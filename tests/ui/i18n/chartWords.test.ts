/**
 * The teaching charts' words in Japanese and German (issue 30): every caption, axis title, legend
 * head, choice, summary and note of the "L against lead and tilt" charts, of the three-axis
 * "step against slope" chart and of a doubly curved point's charts of L against each radius, for each variant (a cylinder's side and axis, a gap at one sample or
 * over a range, raster or waterline, crossing or not, on a surface of revolution, every refusal code
 * of the constant step): no English word left (Japanese: no Latin word but the symbols and units),
 * every number given said.
 */
import { describe, expect, it } from 'vitest';
import type { ChartWords, ProfileWords, RadiusWords, SlopeWords, ViewNoteWords } from '../../../src/ui/i18n/catalogue';
import { catalogue as de } from '../../../src/ui/i18n/de';
import { catalogue as ja } from '../../../src/ui/i18n/ja';

const CODES = ['beyond-step', 'shank-cuts', 'flank-wall', 'wall-only', 'past-surface', 'needs-slope', 'gouging'];

function chartTexts(c: ChartWords): string[] {
  return [
    c.leadTitle('mm', '5'),
    c.errorTitle('%'),
    c.tiltTitle('in', '2.5'),
    c.leadAxis,
    c.tiltAxis,
    c.errorAxis('mm'),
    c.description('T'),
    c.legendHead('rho', '5'),
    c.legendHead('beta', '2.5'),
    c.leadOnly,
    c.seeBelow,
    c.none,
    ...Object.values(c.errorIn),
    ...Object.values(c.rhoScale),
    c.summary('5', '2.5', 'V'),
    c.noSummary,
    c.cylinder(true, 'feed'),
    c.cylinder(false, 'cross'),
    c.gap('N', 'rho', '12.5', null),
    c.gap('N', 'beta', '12.5', '17.5'),
  ];
}

function slopeTexts(s: SlopeWords): string[] {
  return [
    s.stepTitle('mm', '0.05 mm', '30°'),
    s.cuspTitle('in', 'Lxy = 0.1 in', '0.002 in'),
    s.slopeAxis,
    s.stepAxis('mm'),
    s.scallopAxis('mm'),
    s.description('T', 'S'),
    s.legendHead('30°'),
    s.strategy('raster', '15°'),
    s.strategy('waterline', '15°'),
    s.floor,
    s.scallopOf('dz = 0.2 mm'),
    s.none,
    s.gap,
    s.noStepAbove('62.5°', '0.05 mm', false),
    s.noStepAbove('62.5°', '0.05 mm', true),
    s.crossing(null, '15°', '0.05 mm', null, false),
    s.crossing('38.2°', '15°', '0.05 mm', '0.912 mm', true),
    s.crossing('38.2°', '15°', '0.05 mm', null, false),
    ...CODES.map((code) => s.refusal('Lxy = 1 mm', '10°', null, code)),
    s.refusal('dz = 1 mm', '10°', '20°', 'gouging'),
  ];
}

function radiusTexts(r: RadiusWords): string[] {
  return [
    r.radius('convex', '40 mm'),
    r.radius('concave', '20 mm'),
    r.radius('straight', ''),
    r.title('mm', 'Rf', 'Rc', r.radius('concave', '40 mm'), r.radius('convex', '80 mm')),
    r.xLabel('Rc', 'in'),
    r.description('T'),
    r.band.gouging,
    r.band.limit,
    r.legendHead('Rf', r.radius('convex', '80 mm')),
    r.branch('Rf', 'convex'),
    r.branch('Rc', 'concave'),
    r.branch('Rc', 'straight'),
    r.seeBelow,
    r.summary('80 mm', '-40 mm', '1.2345 mm', '1.5 mm', '1.1 mm'),
    r.gap('convex', 'Rf', '12.5 mm', null, 'Rc', r.radius('straight', ''), 'gouging'),
    r.gap('concave', 'Rc', '12.5 mm', '17.5 mm', 'Rf', r.radius('convex', '80 mm'), 'limit'),
  ];
}

function noteTexts(n: ViewNoteWords): string[] {
  return [
    ...Object.values(n.curved),
    n.curvedAnswered,
    n.question('30', '15'),
    n.question('30', null),
    n.tables,
    n.revolution(n.question('30', null)),
    n.equivalent(n.question('30', '15'), '12.5', '3.25', true),
    n.equivalent(n.question('30', '15'), '12.5', '3.25', false),
  ];
}

/** The cross-feed profile's words (views/profileWords.ts), every variant. */
function profileTexts(p: ProfileWords): string[] {
  return [
    p.plotPlane,
    p.plotCylinder('convex', 'feed'),
    p.plotCylinder('concave', 'cross'),
    p.plotCurved('convex', 'concave'),
    p.noteCylinder('convex', '30 mm', 'feed'),
    p.noteCylinder('concave', '30 mm', 'cross'),
    p.noteCurved('R1', 'R2'),
    p.heightsPlane,
    p.heightsSurface,
    p.curvatureTrue,
    p.scale(1, p.heightsPlane, true, 20, ''),
    p.scale(5, p.heightsSurface, false, null, p.curvatureTrue),
    p.scale(5, p.heightsPlane, true, 20, ''),
    p.exaggeration,
    p.auto,
    p.trueScale,
    p.vertical(20),
    p.zoomIn,
    p.zoomOut,
    p.reset,
    p.cusp,
    p.approximations,
    p.ring,
    p.nextPass,
    p.cylinderAlong,
    p.cylinderAcross,
    p.arc,
    p.high('0.01 mm', 20),
  ];
}

const KEPT = new Set('L h R D Rcr rho beta alpha psi Lxy Lxy0 dz mm in CAM Z T V N S Rf Rc Rs Rb a b R1 R2'.split(' '));
const ENGLISH =
  /\b(against|lead|tilt|fixed|dashed|dotted|current|error|axis|angle|signed|approximation|along|length|at|deg|slope|step|scallop|programmed|constant|leaves|raster|waterline|flat|floor|above|below|cross|larger|of|the|no|and|on|cylinder|answer|from|to|convex|concave|straight|held|log|gouging|limit|posture|paper|tables|plane|view|upright|frame|simulated|drawn|point|results|exaggerated|vertical|zoom|reset|ellipse|next|pass|ignored|scale|heights|radially|section|circle|flanks|true|auto|fold|trough|high|approximations|compare|shapes|turned|measured|revolved|stepped|marks|corrected|adjacent|passes|arc)\b/i;

describe("the teaching charts' words", () => {
  for (const [name, c] of [
    ['ja', ja],
    ['de', de],
  ] as const)
    it(`${name}: no English word in any caption, axis title, choice, legend, summary or note; the numbers said`, () => {
      const texts = [
        ...chartTexts(c.chart),
        ...slopeTexts(c.slope),
        ...radiusTexts(c.radius),
        ...noteTexts(c.viewNotes),
        ...profileTexts(c.profile),
      ];
      for (const text of texts) {
        if (name === 'ja')
          for (const w of text.match(/[A-Za-z][A-Za-z0-9]*/g) ?? []) expect(KEPT.has(w), `${text}: "${w}"`).toBe(true);
        else expect(ENGLISH.exec(text)?.[0] ?? null, text).toBeNull();
      }
      expect(c.chart.gap('N', 'beta', '12.5', '17.5')).toContain('17.5');
      expect(c.slope.crossing('38.2°', '15°', '0.05 mm', '0.912 mm', true)).toContain('0.912 mm');
      expect(c.slope.refusal('dz = 1 mm', '10°', '20°', 'gouging')).toContain('20°');
      expect(c.radius.gap('concave', 'Rc', '12.5 mm', '17.5 mm', 'Rf', '80 mm', 'limit')).toContain('17.5 mm');
      expect(c.radius.summary('80 mm', '-40 mm', '1.2345 mm', '1.5 mm', '1.1 mm')).toContain('1.2345 mm');
      expect(c.viewNotes.equivalent('Q', '12.5', '3.25', true)).toMatch(/12\.5°.*3\.25°/);
      expect(c.profile.noteCylinder('convex', '30 mm', 'feed')).toContain('30 mm');
      expect(c.profile.noteCurved('R1', 'R2')).toMatch(/R1.*R2/);
      expect(c.profile.scale(5, 'H', true, 20, '')).toMatch(/H.*5.*20|H.*20.*5|5.*H.*20/);
      expect(c.profile.high('0.01 mm', 20)).toMatch(/0\.01 mm.*20/);
      expect(new Set([c.profile.plotCylinder('convex', 'feed'), c.profile.plotCylinder('convex', 'cross')]).size).toBe(
        2,
      );
      // Each refusal code has its own words (none falls back to the generic sentence).
      expect(new Set(CODES.map((code) => c.slope.refusal('L', '1°', null, code))).size).toBe(CODES.length);
    });
});
