/**
 * What the page gives the 3D scene for an answer (ui/sceneLabels.ts): a plane's labels as before,
 * a doubly curved point's step-over as an arc with the curved legend, a three-axis answer's
 * programmed step (Lxy for raster, dz for waterline) in the user's unit, and nothing for an error.
 */
import { describe, expect, it } from 'vitest';
import { sceneOfReply } from '../../src/ui/sceneLabels';
import { solveCurved } from '../../src/worker/jobs/curved';
import { solve } from '../../src/worker/jobs/solve';
import { solveThreeAxisRequest } from '../../src/worker/jobs/threeAxis';

const TOOL = { toolRadiusMm: 3, cornerRadiusMm: 1 };

describe('the scene of an answer', () => {
  it('a plane: L, L/2 and y0 as before, the plane legend', () => {
    const reply = solve({
      mode: 'forward',
      input: {
        ...TOOL,
        leadAngleDeg: 5,
        tiltAngleDeg: 3,
        pattern: 'one-way',
        surface: { kind: 'plane' },
        scallopHeightMm: 0.05,
      },
    });
    const s = sceneOfReply(reply, 'mm');
    expect(s?.curvedLegend).toBe(false);
    expect(s?.labels.interval).toMatch(/^L = \d+\.\d+ mm$/);
    expect(s?.labels.arc).toBe(false);
    expect(s?.labels.contactOffset).toMatch(/^y0 = /);
    expect(s?.labels.programmedStep).toBeUndefined();
  });

  it('a doubly curved point: L as an arc, the curved legend', () => {
    const reply = solveCurved({
      mode: 'curved-forward',
      input: {
        ...TOOL,
        leadAngleDeg: 5,
        tiltAngleDeg: 0,
        pattern: 'one-way',
        feedRadiusMm: 20,
        crossRadiusMm: 30,
        scallopHeightMm: 0.05,
      },
    });
    const s = sceneOfReply(reply, 'mm');
    expect(s?.curvedLegend).toBe(true);
    // Measured along an arc: the scene says so after L and L/2 (render/sceneWords.ts, in the reader's language).
    expect(s?.labels.interval).toMatch(/^L = \d+\.\d+ mm$/);
    expect(s?.labels.arc).toBe(true);
  });

  it('three-axis: Lxy for raster, dz for waterline, in inches when asked', () => {
    const raster = solveThreeAxisRequest({
      mode: 'three-axis',
      input: {
        surface: 'plane',
        case: { ...TOOL, slopeDeg: 30, passes: 'raster', rasterAngleDeg: 0 },
        quantity: 'h',
        mm: 0.05,
      },
    });
    if (!raster.ok) throw new Error('answered');
    expect(sceneOfReply(raster, 'mm')?.labels.programmedStep).toMatch(/^Lxy = \d+\.\d+ mm$/);
    const waterline = solveThreeAxisRequest({
      mode: 'three-axis',
      input: {
        surface: 'revolution',
        case: { ...TOOL, slopeDeg: 40, feedRadiusMm: 20, crossRadiusMm: 20 },
        quantity: 'h',
        mm: 0.05,
      },
    });
    if (!waterline.ok) throw new Error('answered');
    const s = sceneOfReply(waterline, 'in');
    expect(s?.labels.programmedStep).toMatch(/^dz = \d+\.\d+ in$/);
    expect(s?.labels.contactOffset).toBeNull();
  });

  it('an error: no scene', () => {
    const reply = solveCurved({
      mode: 'curved-forward',
      input: {
        ...TOOL,
        leadAngleDeg: 5,
        tiltAngleDeg: 0,
        pattern: 'one-way',
        feedRadiusMm: 10,
        crossRadiusMm: -12,
        scallopHeightMm: 0.05,
      },
    });
    expect(sceneOfReply(reply, 'mm')).toBeNull();
  });
});
