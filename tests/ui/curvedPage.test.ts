/**
 * Issue 19 on the page: the doubly curved point's inputs (two radii, each a magnitude with its
 * side, and the presets), their URL form (`feedRadius=`, `crossRadius=` signed in the link's unit;
 * the old `surfaceRadius=&surfaceAxis=` still the cylinder), the request they make, where their
 * errors show (gouging on the radius that must change, in the user's unit) and the worker's answer
 * against the core. Pure: no DOM.
 */
import { describe, expect, it } from 'vitest';
import { formatInputNumber, fromMm, toMm } from '../../src/core/input/units';
import {
  doublyCurvedForward,
  doublyCurvedInverse,
  doublyCurvedLimits,
  doublyCurvedRadiusLimit,
} from '../../src/core/surfaces/doublyCurved';
import { buildRequest } from '../../src/ui/request';
import { type CalculatorState, defaultState, parseUrl, toSearch, withField } from '../../src/ui/state';
import { CURVED_PRESETS, curvedPresetOf, withCurvedPreset } from '../../src/ui/surfaceState';
import { solvePage } from '../../src/worker/jobs/page';
import { answeredMessages } from '../support/pageAnswer';

const TOOL = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 };
const BASE = '?R=3&Rcr=1&rho=5&h=0.05';

/** Every message a state's errors give, as one text. */
function messagesOf(state: CalculatorState): Map<string, string> {
  const messages = answeredMessages(state);
  if (messages.size === 0) throw new Error(`valid: ${toSearch(state)}`);
  return messages;
}

/** No message may show NaN, Infinity or -0 of its own (the text typed, quoted as "got", is the user's). */
function expectClean(text: string): void {
  expect(text.replace(/\(got [^)]*\)/g, '')).not.toMatch(/NaN|Infinity|(^|[^\d.])-0(?![\d.])/);
}

/** A dome with unequal radii (the defaults, 80 and 40 mm). */
const dome0 = (s: CalculatorState) => withCurvedPreset(s, 'dome');

describe('the doubly curved point in the state and the URL', () => {
  it('feedRadius and crossRadius round-trip, signed in the link, magnitudes with sides in the state', () => {
    for (const [q, f, c, rf, rc] of [
      [`${BASE}&feedRadius=80&crossRadius=-40&unit=mm`, 'convex', 'concave', '80', '40'],
      [`${BASE}&feedRadius=-12.5&crossRadius=-12.5&unit=mm`, 'concave', 'concave', '12.5', '12.5'],
      [`${BASE}&feedRadius=2&unit=in`, 'convex', 'straight', '2', '40'],
    ] as const) {
      const p = parseUrl(q);
      expect(p.notices).toEqual([]);
      expect(p.state.surface).toBe('curved');
      expect([p.state.feedSide, p.state.crossSide]).toEqual([f, c]);
      expect(p.state.fields.Rf).toBe(rf);
      if (c !== 'straight') expect(p.state.fields.Rc).toBe(rc);
      expect(parseUrl(toSearch(p.state)).state).toEqual(p.state);
    }
    expect(toSearch(parseUrl(`${BASE}&feedRadius=80&crossRadius=-40&unit=mm`).state)).toBe(
      '?R=3&Rcr=1&rho=5&feedRadius=80&crossRadius=-40&h=0.05&unit=mm',
    );
  });

  it('old cylinder links keep working and keep their form; mixing the two forms is said, the radii win', () => {
    const old = '?R=3&Rcr=1&rho=5&surfaceRadius=-30&surfaceAxis=cross&h=0.05&unit=mm';
    expect(toSearch(parseUrl(old).state)).toBe(old);
    const mixed = parseUrl(`${BASE}&surfaceRadius=30&feedRadius=80&crossRadius=40&unit=mm`);
    expect(mixed.state.surface).toBe('curved');
    expect(mixed.notices.join(' ')).toMatch(/surfaceRadius and feedRadius or crossRadius are both in the link/);
    const bad = parseUrl(`${BASE}&feedRadius=abc&crossRadius=40&unit=mm`);
    expect(bad.state.feedSide).toBe('straight');
    expect(bad.notices.join(' ')).toMatch(/feedRadius="abc" in the link is not a number/);
  });

  it('the presets set the sides (a sphere equal radii, a dome unequal ones) and are read back from them', () => {
    const s: CalculatorState = { ...defaultState(), surface: 'curved' };
    for (const preset of CURVED_PRESETS) expect(curvedPresetOf(withCurvedPreset(s, preset)), preset).toBe(preset);
    const sphere = withCurvedPreset(s, 'sphere');
    expect(sphere.fields.Rc).toBe(sphere.fields.Rf);
    // Five-axis, a bowl keeps the radii (a waterline bowl is spherical).
    expect(withCurvedPreset(dome0(s), 'bowl').fields).toEqual(dome0(s).fields);
    expect(withCurvedPreset(dome0(s), 'bowl', true).fields.Rc).toBe(dome0(s).fields.Rf);
    const dome = withCurvedPreset(sphere, 'dome');
    expect(Number(dome.fields.Rc)).toBe(Number(dome.fields.Rf) / 2);
    expect([withCurvedPreset(s, 'saddle').feedSide, withCurvedPreset(s, 'saddle').crossSide]).toEqual([
      'convex',
      'concave',
    ]);
    expect(withCurvedPreset(s, 'cylinder-along').feedSide).toBe('straight');
    expect(withCurvedPreset(s, 'cylinder-across').crossSide).toBe('straight');
  });
});

describe('the request a doubly curved point makes, and its answer', () => {
  it('both radii curved: signed radii in mm (from inches too), answered as the core answers', () => {
    const mm = buildRequest(parseUrl(`${BASE}&feedRadius=80&crossRadius=-40&unit=mm`).state);
    if (!mm.ok || mm.request.mode !== 'curved-forward') throw new Error('valid');
    expect(mm.request.input).toMatchObject({ feedRadiusMm: 80, crossRadiusMm: -40, scallopHeightMm: 0.05 });
    const inch = buildRequest(parseUrl('?R=0.1&Rcr=0.04&rho=5&h=0.002&feedRadius=3&crossRadius=-2&unit=in').state);
    if (!inch.ok || inch.request.mode !== 'curved-forward') throw new Error('valid');
    expect(inch.request.input.feedRadiusMm).toBeCloseTo(toMm(3, 'in'), 12);
    expect(inch.request.input.crossRadiusMm).toBeCloseTo(-toMm(2, 'in'), 12);
    const reply = solvePage(mm.request);
    if (!reply.ok || reply.request.mode !== 'curved-forward' || !('comparison' in reply)) throw new Error('answered');
    const exact = doublyCurvedForward({
      ...TOOL,
      pattern: 'one-way',
      feedRadiusMm: 80,
      crossRadiusMm: -40,
      scallopHeightMm: 0.05,
    });
    expect(reply.exact.intervalMm).toBe(exact.intervalMm);
    const c = reply.comparison;
    if (c === null || !c.plane.ok || !c.cylinderAlong.ok || !c.cylinderAcross.ok) throw new Error('rows');
    expect(c.plane.deviationMm).toBeCloseTo(c.plane.intervalMm - exact.intervalMm, 12);
    // On a saddle, the concave radius across the feed brings the passes' scallops closer: the plane steps wider.
    expect(c.plane.intervalMm).toBeGreaterThan(0);
    expect(c.cylinderAlong.intervalMm).not.toBe(c.cylinderAcross.intervalMm);
  });

  it('inverse: a typed L gives the cusp height of the core', () => {
    const built = buildRequest(
      parseUrl('?R=3&Rcr=1&rho=5&tilt=3&pattern=zigzag&mode=inverse&L=2&feedRadius=-60&crossRadius=-30&unit=mm').state,
    );
    if (!built.ok || built.request.mode !== 'curved-inverse') throw new Error('valid');
    const reply = solvePage(built.request);
    if (!reply.ok || !('comparison' in reply)) throw new Error('answered');
    const core = doublyCurvedInverse({
      ...TOOL,
      tiltAngleDeg: 3,
      pattern: 'zigzag',
      feedRadiusMm: -60,
      crossRadiusMm: -30,
      intervalMm: 2,
    });
    expect(reply.exact.cuspHeightMm).toBe(core.cuspHeightMm);
    expect(reply.exact.otherCuspHeightMm).toBe(core.otherCuspHeightMm);
    expect(reply.comparison).toBeNull();
  });

  it('one radius straight asks the cylinder exactly as the old cylinder inputs did; both straight the plane', () => {
    const curved = buildRequest(parseUrl(`${BASE}&crossRadius=-40&unit=mm`).state);
    const old = buildRequest(parseUrl(`${BASE}&surfaceRadius=-40&surfaceAxis=feed&unit=mm`).state);
    expect(curved.ok && curved.request).toEqual(old.ok && old.request);
    const across = buildRequest(parseUrl(`${BASE}&feedRadius=25&unit=mm`).state);
    const oldAcross = buildRequest(parseUrl(`${BASE}&surfaceRadius=25&surfaceAxis=cross&unit=mm`).state);
    expect(across.ok && across.request).toEqual(oldAcross.ok && oldAcross.request);
    const plane = withCurvedPreset({ ...defaultState(), surface: 'curved' as const }, 'plane');
    expect(buildRequest(plane)).toEqual(buildRequest(defaultState()));
  });
});

describe('bad input at a doubly curved point: one line on its field, in the user unit', () => {
  it('gouging shows on the radius that must grow, with its limit (the other held) in mm and in inches', () => {
    const limit = doublyCurvedRadiusLimit(TOOL, { feedRadiusMm: 80, crossRadiusMm: -2 }, 'cross');
    expect(limit.kind).toBe('concave-at-least');
    const mm = messagesOf(parseUrl(`${BASE}&feedRadius=80&crossRadius=-2&unit=mm`).state);
    expect([...mm.keys()]).toEqual(['Rc']);
    expect(mm.get('Rc')).toContain(`at least ${formatInputNumber(limit.radiusMm ?? 0)} mm while concave`);
    expect(mm.get('Rc')).toContain('Rf = 80 mm held');
    // In inches the tool is 25.4 times larger: the limit scales, said in inches.
    const inchState = parseUrl('?R=3&Rcr=1&rho=5&h=0.05&feedRadius=80&crossRadius=-2&unit=in').state;
    const inch = messagesOf(inchState);
    expect(inch.get('Rc')).toContain(`at least ${formatInputNumber(fromMm(toMm(limit.radiusMm ?? 0, 'in'), 'in'))} in`);
    // A bowl too tight both ways for any radius: said on both, "at any radius".
    const tight = messagesOf(parseUrl(`${BASE}&feedRadius=-5&crossRadius=-4&unit=mm`).state);
    expect(tight.get('Rf')).toMatch(/gouges at any radius, with Rc = -4 mm held/);
    expect(tight.get('Rc')).toMatch(/gouges at any radius, with Rf = -5 mm held/);
  });

  it('each radius field: missing, not a number, a sign or 0 typed, out of range; h and L against this point', () => {
    const s = parseUrl(`${BASE}&feedRadius=80&crossRadius=40&unit=mm`).state;
    const cases: Array<[string, string, RegExp]> = [
      ['Rf', '', /^Feed radius Rf is missing/],
      ['Rf', 'abc', /^Feed radius Rf must be a number \(got "abc"\)/],
      ['Rc', '-40', /^Cross radius Rc must be a positive number: convex or concave is chosen beside it/],
      ['Rc', '0', /^Cross radius Rc must be a positive number/],
      ['Rc', '-0', /^Cross radius Rc must be a positive number/],
      ['Rf', '2e6', /^Feed radius Rf must be a radius from 0\.001 mm to 1000000 mm \(got 2e6, convex\)/],
      ['Rc', '1e400', /^Cross radius Rc must be a number/],
    ];
    for (const [key, text, re] of cases) {
      const m = messagesOf(withField(s, key as 'Rf', text));
      expect(m.get(key as 'Rf'), `${key}=${text}`).toMatch(re);
      expectClean([...m.values()].join(' '));
    }
    const limit = doublyCurvedLimits({ ...TOOL, feedRadiusMm: 80, crossRadiusMm: 40 }).limitMm;
    const h = messagesOf(withField(s, 'h', '2'));
    expect(h.get('h')).toContain(`must be below ${formatInputNumber(limit)} mm at this point (got 2)`);
    const L = messagesOf({ ...withField(s, 'L', '20'), mode: 'inverse' });
    expect(L.get('L')).toMatch(/^Step-over L must be below [\d.]+ mm at this point \(got 20\)/);
    // Other values are kept: the radii and the tool fields as typed.
    expect(withField(s, 'Rf', 'abc').fields.Rc).toBe('40');
    // A target Ra is answered at a doubly curved point; above the largest Ra there, said on its field.
    expect(buildRequest({ ...s, target: 'ra' }).ok).toBe(true);
    const ra = messagesOf(withField({ ...s, target: 'ra' }, 'ra', '5'));
    expect(ra.get('ra')).toMatch(/^Roughness Ra must be below [\d.]+ mm \(got 5\), the largest Ra .* at this point/);
  });
});
