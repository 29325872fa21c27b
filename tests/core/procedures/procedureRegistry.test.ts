/**
 * The procedure registry (src/core/procedures/procedures.ts): each approximation carries its own model and
 * its forward and inverse functions, and the comparison, the sweeps, the CSV and the worker
 * iterate that one list. Checked against closed forms written here (a circle's and an ellipse's
 * L/2 and sagitta; the combined radius 1/rho = 1/Reff + 1/Rs), not against the code under test.
 */
import { describe, expect, it } from 'vitest';
import { forwardInput, inverseInput, type ToolInput } from '../../../src/core/input/validate';
import { combinedRadiusMm } from '../../../src/core/procedures/approximations';
import { compareForward, compareInverse } from '../../../src/core/procedures/compare';
import {
  APPROXIMATION_KEYS,
  APPROXIMATIONS,
  CORRECTED_KEYS,
  CURVATURE_ROW_KEYS,
  CURVATURE_ROWS,
  modelCurve,
  PROCEDURES,
} from '../../../src/core/procedures/procedures';
import { noAnswerReason } from '../../../src/core/procedures/sweepGaps';
import type { CylinderSurface } from '../../../src/core/surfaces/cylinder';
import { solve } from '../../../src/worker/api';
import { random } from '../../cli/helpers';

const tool = (R: number, Rcr: number, rho: number, tilt = 0): ToolInput => ({
  toolRadiusMm: R,
  cornerRadiusMm: Rcr,
  leadAngleDeg: rho,
  tiltAngleDeg: tilt,
});

/** A circle's L/2 at height h, and its sagitta at L/2 (closed forms). */
const circleHalf = (r: number, h: number) => Math.sqrt(2 * r * h - h * h);
const circleHeight = (r: number, half: number) => r - Math.sqrt(r * r - half * half);
/** An ellipse (semi-axes a across, b up) touching the plane: L/2 at h, and the height at L/2. */
const ellipseHalf = (a: number, b: number, h: number) => a * Math.sqrt(1 - ((b - h) / b) ** 2);
const ellipseHeight = (a: number, b: number, half: number) => b * (1 - Math.sqrt(1 - (half / a) ** 2));

describe("each approximation's functions are its own", () => {
  it("forward and inverse agree with the closed form of the model's own curve (200 random tools, seed 18)", () => {
    const rand = random(18);
    for (let n = 0; n < 200; n++) {
      const R = 0.5 + 10 * rand();
      const t = tool(R, R * rand(), 1 + 60 * rand(), 20 * rand() - 10);
      for (const key of APPROXIMATION_KEYS) {
        const m = modelCurve(key, t);
        if (!m.ok) continue;
        const c = m.curve;
        const top = c.shape === 'circle' ? c.radiusMm : c.shortRadiusMm;
        const h = top * (0.01 + 0.5 * rand());
        const half = APPROXIMATIONS[key].halfInterval(forwardInput(t, 'one-way', h));
        if (!half.ok) throw new Error(`${key}: ${half.notApplicable}`);
        const expected = c.shape === 'circle' ? circleHalf(c.radiusMm, h) : ellipseHalf(c.longRadiusMm, top, h);
        expect(half.halfIntervalMm / expected, key).toBeCloseTo(1, 9);
        const wide = c.shape === 'circle' ? c.radiusMm : c.longRadiusMm;
        const L = 2 * wide * (0.05 + 0.9 * rand());
        const height = APPROXIMATIONS[key].scallopHeight(inverseInput(t, 'one-way', L));
        if (!height.ok) throw new Error(`${key}: ${height.notApplicable}`);
        const sagitta = c.shape === 'circle' ? circleHeight(c.radiusMm, L / 2) : ellipseHeight(wide, top, L / 2);
        expect(height.scallopHeightMm / sagitta, key).toBeCloseTo(1, 7);
      }
    }
  });

  it("where a model has no answer, its reason names that procedure (the registry's label)", () => {
    // A flat end without lead or tilt: no procedure's model applies.
    const flat = tool(3, 0, 0);
    for (const key of APPROXIMATION_KEYS) {
      const m = APPROXIMATIONS[key].model(flat);
      expect(m.ok, key).toBe(false);
      if (!m.ok) expect(m.notApplicable.startsWith(`${PROCEDURES[key].shortLabel}:`), m.notApplicable).toBe(true);
    }
  });

  it('the corrected procedures are exactly those whose model is a circle; their rows follow them', () => {
    const circles = APPROXIMATION_KEYS.filter((key) => {
      const m = modelCurve(key, tool(3, 1, 5, 2));
      return m.ok && m.curve.shape === 'circle';
    });
    expect([...CORRECTED_KEYS]).toEqual(circles);
    expect([...CURVATURE_ROW_KEYS]).toEqual(['plane', ...CORRECTED_KEYS.map((k) => `${k}Corrected`)]);
    for (const key of CORRECTED_KEYS) expect(CURVATURE_ROWS[`${key}Corrected`].corrects).toBe(key);
  });

  it("the sweep's reasons name each model's widest point by its own symbol", () => {
    const t = tool(3, 1, 5);
    expect(noAnswerReason('bedi', t)).toBe(
      'h is above the widest point of its ellipse (its height Rlong sin(rho) is below h)',
    );
    expect(noAnswerReason('redonnet', t)).toBe(
      'h is above the widest point of its circle (its radius Reff is below h)',
    );
    expect(noAnswerReason('osculating', t)).toBe(
      'h is above the widest point of its circle (its radius Reff is below h)',
    );
    expect(noAnswerReason('cornerBall', t)).toBe(
      'h is above the widest point of its circle (its radius Rcr is below h)',
    );
  });
});

describe('the curvature correction 1/rho = 1/Reff + 1/Rs, written once', () => {
  const feed = (radiusMm: number): CylinderSurface => ({ kind: 'cylinder', radiusMm, axis: 'feed' });

  it('combines the radii with the axis along the feed; across it the surface is straight, rho = Reff', () => {
    expect(combinedRadiusMm(24, feed(20))).toBeCloseTo(1 / (1 / 24 + 1 / 20), 12);
    expect(combinedRadiusMm(24, feed(-30))).toBeCloseTo(1 / (1 / 24 - 1 / 30), 12);
    expect(combinedRadiusMm(24, { kind: 'cylinder', radiusMm: -30, axis: 'cross' })).toBe(24);
    // A concave surface tighter than the circle: no positive combined radius.
    expect(combinedRadiusMm(24, feed(-20)) > 0).toBe(false);
  });

  it('the forward and inverse comparison rows and the worker use it for every corrected procedure', () => {
    const t = tool(3, 1, 5, 2);
    const s = feed(-60);
    const h = 0.02;
    const forward = compareForward(forwardInput(t, 'one-way', h, s)).curvature;
    const L = 1.2;
    const inverse = compareInverse(inverseInput(t, 'one-way', L, s)).curvature;
    for (const key of CORRECTED_KEYS) {
      const m = modelCurve(key, t);
      if (!m.ok || m.curve.shape !== 'circle') throw new Error(key);
      const rho = 1 / (1 / m.curve.radiusMm + 1 / -60);
      const f = forward?.corrected[key];
      expect(f?.ok && f.combinedRadiusMm, key).toBeCloseTo(rho, 9);
      expect(f?.ok && f.halfIntervalMm / circleHalf(rho, h), key).toBeCloseTo(1, 9);
      const i = inverse?.corrected[key];
      expect(i?.ok && i.scallopHeightMm / circleHeight(rho, L / 2), key).toBeCloseTo(1, 9);
    }
    // A trough tighter than Redonnet's circle (Reff 23.9 mm, lead only), which the tool tilted by 20
    // degrees still fits (from 6.7 mm): the worker's note says why, by the combined radius.
    const tight = feed(-15);
    const reply = solve({ mode: 'forward', input: forwardInput(tool(3, 1, 5, 20), 'one-way', 0.02, tight) });
    const row = reply.ok ? reply.curvature?.find((r) => r.key === 'redonnetCorrected') : undefined;
    expect(row?.valueMm).toBeNull();
    expect(row?.note).toEqual({
      kind: 'reason',
      text: `${CURVATURE_ROWS.redonnetCorrected.shortLabel}: its effective radius is not smaller than the concave surface's radius, so the combined radius 1/(1/Reff + 1/Rs) is not positive.`,
    });
  });
});
