import { describe, expect, it } from 'vitest';
import { forwardInput } from '../../../src/core/input/validate';
import { gaugeMax, groupSteps, looksSame, sceneToleranceMm } from '../../../src/ui/views/stepGroups';
import { traceFrames } from '../../../src/worker/api';

const tool = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 };
const tol = sceneToleranceMm(3);

describe('step-through: frames that look the same are merged or explained', () => {
  for (const tilt of [0, 8]) {
    it(`Tool 1, tilt ${tilt}: every frame in one step, in order; no two steps of a phase alike`, () => {
      const { frames } = traceFrames(forwardInput({ ...tool, tiltAngleDeg: tilt }, 'one-way', 0.1));
      const steps = groupSteps(frames, tol, 1);
      // Fewer steps than frames: the search's last passes move by far less than the scene shows.
      expect(steps.length).toBeLessThan(frames.length - 20);
      expect(steps.reduce((n, s) => n + s.count, 0)).toBe(frames.length);
      let end = -1;
      for (const s of steps) {
        end += s.count;
        expect(s.frame).toBe(frames[end]); // the run's last frame is the one shown
        expect(s.passTo - s.passFrom + 1).toBe(s.count);
      }
      steps.forEach((s, i) => {
        const prev = steps[i - 1];
        if (prev && prev.frame.phase === s.frame.phase && prev.frame.flank === s.frame.flank)
          expect(looksSame(prev.frame, s.frame, tol, 1), `step ${i + 1}`).toBe(false);
      });
      // Each flank's convergence shows its last search point again: explained, not merged.
      const converged = steps.filter((s) => s.frame.phase === 'converged' && s.frame.flank !== null);
      expect(converged).toHaveLength(2);
      for (const s of converged) expect(s.sameAsPrevious).toBe(true);
      const merged = steps.filter((s) => s.frame.phase === 'search' && s.count > 1);
      expect(merged.length).toBeGreaterThan(0);
      expect(steps.at(-1)?.frame.flank).toBe(null);
    });
  }

  it('a run is compared with its first frame, so small moves cannot add up unseen', () => {
    const { frames } = traceFrames(forwardInput(tool, 'one-way', 0.1));
    const search = frames.filter((f) => f.phase === 'search' && f.flank === 'right');
    const steps = groupSteps(search, tol, 1);
    let start = 0;
    for (const s of steps) {
      const first = search[start];
      if (!first) throw new Error('missing frame');
      expect(looksSame(first, s.frame, tol, 1)).toBe(true);
      start += s.count;
    }
  });

  it('frames far apart stay apart: a huge tolerance merges, zero tolerance keeps every distinct frame', () => {
    const { frames } = traceFrames(forwardInput(tool, 'one-way', 0.1));
    const none = groupSteps(frames, 0, 1);
    const distinct = frames.filter((f, i) => i === 0 || !looksSame(frames[i - 1] ?? f, f, 0, 1)).length;
    expect(none.length).toBe(distinct);
    expect(groupSteps(frames, 1e6, 1e-9).length).toBeLessThan(none.length);
  });
});

describe('the d_s / Rcr gauge scale', () => {
  it('starts at 0 and ends at the next quarter at or above the largest ratio (at least 1): nothing clipped', () => {
    expect(gaugeMax([])).toBe(1);
    expect(gaugeMax([0.95, 0.99])).toBe(1);
    expect(gaugeMax([0.95, 1.0015])).toBe(1.25);
    expect(gaugeMax([1.6])).toBe(1.75);
    const { frames } = traceFrames(forwardInput(tool, 'one-way', 0.1));
    const ratios = frames.flatMap((f) => (f.dsMm === null ? [] : [f.dsMm]));
    const max = gaugeMax(ratios);
    for (const r of ratios) expect(r).toBeLessThanOrEqual(max);
  });
});
