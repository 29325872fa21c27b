/**
 * The teaching views in three-axis mode (issue 28 point 2), without a DOM: the teach job gives a
 * sloped plane's views the plane at the equivalent posture (its L the three-axis answer's L along
 * the plane), none on a surface of revolution; the chart tab's name follows what it draws; the
 * posture formulas reach their closed-form limits (psi = 0: lead alpha, tilt 0; waterline: lead 0,
 * tilt alpha, dz = L sin alpha).
 */
import { describe, expect, it } from 'vitest';
import { slopedPlaneForward } from '../../src/core/threeAxis/slopedPlane';
import { validateThreeAxis } from '../../src/core/threeAxis/validate';
import { formatAngle } from '../../src/ui/format';
import { chartTitle, postureFormulaLines, threeAxisViewNote } from '../../src/ui/views/threeAxisViewText';
import { teachThreeAxis } from '../../src/worker/jobs/teachPage';

function taught(raw: Parameters<typeof validateThreeAxis>[0], h: number) {
  const v = validateThreeAxis(raw, 'h', h);
  if (!v.ok) throw new Error(v.errors[0]?.message);
  const t = teachThreeAxis({ mode: 'three-axis', input: v.value });
  if (!t.ok) throw new Error('taught');
  return t;
}

const line = (lines: ReturnType<typeof postureFormulaLines>, label: string) =>
  lines.find((l) => l.label === label)?.value ?? '';

describe('three-axis teaching views', () => {
  it("a sloped plane's views draw the plane at the equivalent posture: its L is the three-axis L, one-way, at h", () => {
    for (const [slope, psi] of [
      [30, 30],
      [50, 0],
      [20, 75],
    ] as const) {
      const t = taught({ R: 3, Rcr: 1, slope, passes: 'raster', rasterAngle: psi }, 0.01);
      const core = slopedPlaneForward(
        { toolRadiusMm: 3, cornerRadiusMm: 1, slopeDeg: slope, passes: 'raster', rasterAngleDeg: psi },
        0.01,
      );
      if (!core.ok || t.plane === null) throw new Error('answered');
      expect(t.plane.forward.pattern).toBe('one-way');
      expect(t.plane.forward.scallopHeightMm).toBe(0.01);
      expect(Math.abs(t.plane.exact.intervalMm - core.value.intervalMm)).toBeLessThan(1e-9);
      expect(threeAxisViewNote('profile', t)).toBe(
        `The upright tool over slope ${slope}°, raster ${psi}° is the tool at lead ${formatAngle(core.value.leadDeg)}, tilt ${formatAngle(core.value.tiltDeg)} on a plane, one-way: drawn in the plane's own frame (lengths along it, h along its normal).`,
      );
      expect(threeAxisViewNote('chart', t)).toBe(null);
    }
  });

  it('waterline on a surface of revolution: no plane, and the views say why in one line', () => {
    const t = taught({ R: 3, Rcr: 1, slope: 40, passes: 'waterline', feedRadius: 50, crossRadius: 50 }, 0.02);
    expect(t.plane).toBe(null);
    expect(threeAxisViewNote('formulas', t)).toMatch(
      /^Waterline passes on a surface of revolution \(slope 40°, waterline\)/,
    );
  });

  it('the chart tab is named for what it draws', () => {
    expect(chartTitle('three-axis')).toBe('Step against slope');
    expect(chartTitle('curved')).toBe('L against each radius');
    expect(chartTitle(null)).toBe('L against lead and tilt');
  });

  it('the posture formulas at their closed-form limits', () => {
    const fall = postureFormulaLines(taught({ R: 3, Rcr: 1, slope: 35, passes: 'raster', rasterAngle: 0 }, 0.01));
    expect(line(fall, 'Lead')).toBe('rho = 35.00 deg');
    expect(line(fall, 'Tilt')).toBe('beta = 0.00 deg');
    expect(line(fall, 'Programmed step')).toBe('Lxy / L = 1.000000');
    const water = postureFormulaLines(taught({ R: 3, Rcr: 1, slope: 35, passes: 'waterline' }, 0.01));
    expect(line(water, 'Lead')).toBe('rho = 0.00 deg');
    expect(line(water, 'Tilt')).toBe('beta = 35.00 deg');
    expect(line(water, 'Programmed step')).toBe(`dz / L = ${Math.sin((35 * Math.PI) / 180).toFixed(6)}`);
  });
});
