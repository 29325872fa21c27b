/**
 * Roughness at a doubly curved point on the page (issue 19): the worker's reply carries Rz, Ra, Rq
 * along the normal as the core gives them (forward, inverse), a target Ra is asked as `curved-ra`
 * and answered at the h that leaves it (the surface left has the Ra asked for), and an Ra above the
 * largest is said on its field with that limit. Pure: no DOM.
 */
import { describe, expect, it } from 'vitest';
import { compareDoublyCurved } from '../../src/core/procedures/compareDoublyCurved';
import {
  doublyCurvedHeightForRaMm,
  doublyCurvedMaxRaMm,
  doublyCurvedRoughness,
  doublyCurvedRoughnessAtInterval,
} from '../../src/core/roughness/doublyCurved';
import { exactRoughness } from '../../src/core/roughness/roughness';
import { curvedInverse, curvedPoint } from '../../src/core/surfaces/doublyCurvedPoint';
import { buildRequest } from '../../src/ui/request';
import { parseUrl, withField } from '../../src/ui/state';
import { solvePage } from '../../src/worker/jobs/page';
import { teachPage } from '../../src/worker/jobs/teachPage';
import { answeredMessages } from '../support/pageAnswer';

const TOOL = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 3 };
const RADII = { feedRadiusMm: 80, crossRadiusMm: -40 };
const URL = '?R=3&Rcr=1&rho=5&tilt=3&feedRadius=80&crossRadius=-40&unit=mm';

describe('roughness at a doubly curved point, on the page', () => {
  it('forward: Rz, Ra, Rq of the core at the exact step-over', () => {
    for (const pattern of ['one-way', 'zigzag'] as const) {
      const built = buildRequest(parseUrl(`${URL}&h=0.02&pattern=${pattern}`).state);
      if (!built.ok) throw new Error('valid');
      const reply = solvePage(built.request);
      if (!reply.ok || !('roughness' in reply) || reply.roughness === null || !('comparison' in reply))
        throw new Error('answered');
      const c = compareDoublyCurved({ ...TOOL, ...RADII, pattern, scallopHeightMm: 0.02 });
      const r = doublyCurvedRoughness(curvedPoint(TOOL, RADII, pattern), c.exact);
      expect(reply.roughness).toMatchObject({ rzMm: r.rzMm, raMm: r.raMm, rqMm: r.rqMm, scallopHeightMm: 0.02 });
      // Rz is the peak-to-valley of the profile: the highest cusp for one-way (all cusps equal).
      if (pattern === 'one-way') expect(reply.roughness.rzMm).toBeCloseTo(0.02, 12);
      expect(reply.roughness.raMm).toBeGreaterThan(0);
      expect(reply.roughness.rqMm).toBeGreaterThan(reply.roughness.raMm);
    }
  });

  it('inverse: the roughness the typed step-over leaves, as the core gives it', () => {
    const built = buildRequest(parseUrl(`${URL}&mode=inverse&L=1.5&pattern=zigzag`).state);
    if (!built.ok || built.request.mode !== 'curved-inverse') throw new Error('valid');
    const reply = solvePage(built.request);
    if (!reply.ok || !('roughness' in reply) || reply.roughness === null) throw new Error('answered');
    const point = curvedPoint(TOOL, RADII, 'zigzag');
    const r = doublyCurvedRoughnessAtInterval(point, curvedInverse(point, 1.5));
    expect(reply.roughness.raMm).toBe(r.raMm);
    expect(reply.roughness.rzMm).toBe(r.rzMm);
  });

  it('a target Ra: the h that leaves it, its step-over, and the surface left has that Ra', () => {
    const built = buildRequest(parseUrl(`${URL}&target=ra&ra=0.004`).state);
    if (!built.ok || built.request.mode !== 'curved-ra') throw new Error('valid');
    expect(built.request.input.targetRaMm).toBe(0.004);
    const reply = solvePage(built.request);
    if (!reply.ok || !('roughness' in reply) || reply.roughness === null || !('comparison' in reply))
      throw new Error('answered');
    const h = doublyCurvedHeightForRaMm(curvedPoint(TOOL, RADII, 'one-way'), 0.004);
    expect(reply.roughness.scallopHeightMm).toBe(h);
    expect(reply.exact.cuspHeightMm).toBe(h);
    expect(reply.exact.intervalMm).toBe(
      compareDoublyCurved({ ...TOOL, ...RADII, pattern: 'one-way', scallopHeightMm: h }).exact.intervalMm,
    );
    // Independent of the root finder: the roughness of the answer is the target.
    expect(reply.roughness.raMm).toBeCloseTo(0.004, 9);
    // The teaching views are drawn at that h.
    const teach = teachPage(built.request);
    if (!teach.ok || !('section' in teach)) throw new Error('taught');
    expect(teach.feed).toBeDefined();
  });

  it("nearly flat radii give the plane's roughness (a closed check of the rows)", () => {
    const built = buildRequest(parseUrl('?R=3&Rcr=1&rho=5&tilt=3&feedRadius=1e6&crossRadius=1e6&unit=mm&h=0.02').state);
    if (!built.ok) throw new Error('valid');
    const reply = solvePage(built.request);
    if (!reply.ok || !('roughness' in reply) || reply.roughness === null) throw new Error('answered');
    const plane = exactRoughness({
      ...TOOL,
      pattern: 'one-way',
      scallopHeightMm: 0.02,
      surface: { kind: 'plane' },
    } as never);
    expect(reply.roughness.raMm).toBeCloseTo(plane.raMm, 7);
  });

  it('an Ra at or above the largest is said on the Ra field with that limit, in the user unit', () => {
    const max = doublyCurvedMaxRaMm(curvedPoint(TOOL, RADII, 'one-way'));
    const state = parseUrl(`${URL}&target=ra&ra=1`).state;
    for (const typed of [String(max * 1.0001), '1']) {
      const s = withField(state, 'ra', typed);
      const m = answeredMessages(s).get('ra') ?? '';
      expect(m).toMatch(
        new RegExp(`^Roughness Ra must be below ${max.toPrecision(6).replace(/0+$/, '').replace('.', '\\.')}`),
      );
      expect(m).toContain('at this point');
    }
    const inch = withField({ ...state, unit: 'in' }, 'ra', '1');
    expect(answeredMessages(inch).get('ra')).toMatch(/must be below [\d.e-]+ in \(got 1\)/);
    // The worker, which trusts no caller, refuses it too.
    const reply = solvePage({ mode: 'curved-ra', input: { ...TOOL, ...RADII, pattern: 'one-way', targetRaMm: max } });
    expect(reply.ok).toBe(false);
  });
});
