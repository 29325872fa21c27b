/**
 * Issue 20 on the page: the machine switch (five-axis or three-axis), the slope, the pass strategy,
 * the raster angle, the surface of revolution's radii (waterline) and the programmed steps; their
 * URL form (`machine=3axis&slope=&passes=&rasterAngle=`, `Lxy=` or `dz=` inverse), the request they
 * make against the core's own answer, and every refusal on its field in the user's unit. Pure.
 */
import { describe, expect, it } from 'vitest';
import { formatInputNumber, fromMm, toMm } from '../../src/core/input/units';
import { slopedPlaneForward, slopedPlaneInverse } from '../../src/core/threeAxis/slopedPlane';
import { waterlineForward, waterlineInverse } from '../../src/core/threeAxis/waterlineRevolution';
import { catalogue as de } from '../../src/ui/i18n/de';
import { catalogue as ja } from '../../src/ui/i18n/ja';
import { setCatalogue } from '../../src/ui/i18n/words';
import { buildRequest } from '../../src/ui/request';
import { type CalculatorState, defaultState, parseUrl, toSearch, withField } from '../../src/ui/state';
import { WATERLINE_PRESETS, waterlinePresetOf, withCurvedPreset } from '../../src/ui/surfaceState';
import { solvePage } from '../../src/worker/jobs/page';
import { answeredMessages } from '../support/pageAnswer';

const TOOL = { toolRadiusMm: 3, cornerRadiusMm: 1 };

function messagesOf(state: CalculatorState): Map<string, string> {
  const messages = answeredMessages(state);
  if (messages.size === 0) throw new Error(`valid: ${toSearch(state)}`);
  return messages;
}

/** The answer the worker gives for a state (it must be valid). */
function answerOf(state: CalculatorState) {
  const built = buildRequest(state);
  if (!built.ok) throw new Error(JSON.stringify(built.errors));
  const reply = solvePage(built.request);
  if (!reply.ok || !('answer' in reply)) throw new Error('three-axis answer expected');
  return reply;
}

describe('three-axis machining in the state and the URL', () => {
  it('machine, slope, passes, raster angle and the radii round-trip; no lead, tilt or pattern is written', () => {
    for (const q of [
      '?R=3&Rcr=1&machine=3axis&slope=30&h=0.05&unit=mm',
      '?R=3&Rcr=1&machine=3axis&slope=45&rasterAngle=60&h=0.01&unit=in',
      '?R=3&Rcr=1&machine=3axis&slope=30&passes=waterline&feedRadius=50&crossRadius=-8&h=0.05&unit=mm',
      '?R=3&Rcr=1&machine=3axis&slope=30&mode=inverse&Lxy=1.5&unit=mm',
      '?R=3&Rcr=1&machine=3axis&slope=30&passes=waterline&mode=inverse&dz=0.25&unit=mm',
    ]) {
      const p = parseUrl(q);
      expect(p.notices, q).toEqual([]);
      expect(p.state.machine).toBe('3axis');
      expect(toSearch(p.state)).toBe(q);
      expect(parseUrl(toSearch(p.state)).state).toEqual(p.state);
    }
    // Lead and tilt typed before the switch stay in the state (five-axis again) but not in a three-axis link.
    const s = { ...withField(defaultState(), 'tilt', '7'), machine: '3axis' as const };
    expect(toSearch(s)).not.toMatch(/rho|tilt|pattern/);
    expect(parseUrl('?machine=4axis').notices.join(' ')).toMatch(/machine="4axis" is not 5axis or 3axis; using 5axis/);
    const missing = parseUrl('?R=3&machine=3axis&h=0.05');
    expect(missing.notices.join(' ')).toMatch(/Rcr is missing/);
    expect(missing.notices.join(' ')).toMatch(/slope is missing/);
  });

  it('the waterline presets set the surface of revolution and are read back from it', () => {
    const s: CalculatorState = { ...defaultState(), machine: '3axis', passes: 'waterline' };
    for (const preset of WATERLINE_PRESETS)
      expect(waterlinePresetOf(withCurvedPreset(s, preset, true)), preset).toBe(preset);
    const fillet = withCurvedPreset(s, 'fillet', true);
    expect(Number(fillet.fields.Rc)).toBeLessThan(Number(fillet.fields.Rf));
  });
});

describe('the three-axis request and its answer, against the core', () => {
  it('raster: the programmed step Lxy, L and the posture are the core sloped plane answer', () => {
    const reply = answerOf(parseUrl('?R=3&Rcr=1&machine=3axis&slope=30&rasterAngle=20&h=0.05&unit=mm').state);
    const core = slopedPlaneForward({ ...TOOL, slopeDeg: 30, passes: 'raster', rasterAngleDeg: 20 }, 0.05);
    if (!core.ok) throw new Error('core');
    expect(reply.answer.horizontalStepMm).toBe(core.value.horizontalStepMm);
    expect(reply.answer.intervalMm).toBe(core.value.intervalMm);
    expect([reply.answer.leadDeg, reply.answer.tiltDeg]).toEqual([core.value.leadDeg, core.value.tiltDeg]);
    // The sweep for the chart: 200 slopes, the flat floor's step first.
    expect(reply.sweep?.points).toHaveLength(200);
    expect(reply.sweep?.points[0]?.slopeDeg).toBe(0);
  });

  it('inches: the request is in mm, the answer the same as in mm', () => {
    const inch = buildRequest(parseUrl('?R=0.125&Rcr=0.03125&machine=3axis&slope=30&h=0.002&unit=in').state);
    if (!inch.ok || inch.request.mode !== 'three-axis') throw new Error('valid');
    expect(inch.request.input.case.toolRadiusMm).toBeCloseTo(toMm(0.125, 'in'), 12);
    expect(inch.request.input.mm).toBeCloseTo(toMm(0.002, 'in'), 12);
  });

  it('waterline on a dome and inverse dz / Lxy: the core waterline and sloped plane answers', () => {
    const dome = answerOf(
      parseUrl('?R=3&Rcr=1&machine=3axis&slope=40&passes=waterline&feedRadius=50&crossRadius=50&h=0.02&unit=mm').state,
    );
    const core = waterlineForward({ ...TOOL, slopeDeg: 40, feedRadiusMm: 50, crossRadiusMm: 50 }, 0.02);
    if (!core.ok) throw new Error('core');
    expect(dome.answer.stepDownMm).toBe(core.value.stepDownMm);
    expect(dome.waterline?.geometry).toEqual(core.value.geometry);
    const dz = answerOf(
      parseUrl(
        '?R=3&Rcr=1&machine=3axis&slope=40&passes=waterline&feedRadius=50&crossRadius=50&mode=inverse&dz=0.3&unit=mm',
      ).state,
    );
    const coreDz = waterlineInverse(
      { ...TOOL, slopeDeg: 40, feedRadiusMm: 50, crossRadiusMm: 50 },
      { field: 'stepDown', mm: 0.3 },
    );
    if (!coreDz.ok) throw new Error('core');
    expect(dz.answer.cuspHeightMm).toBe(coreDz.value.cuspHeightMm);
    const lxy = answerOf(parseUrl('?R=3&Rcr=1&machine=3axis&slope=30&mode=inverse&Lxy=1.5&unit=mm').state);
    const coreLxy = slopedPlaneInverse(
      { ...TOOL, slopeDeg: 30, passes: 'raster', rasterAngleDeg: 0 },
      { field: 'horizontalStep', mm: 1.5 },
    );
    if (!coreLxy.ok) throw new Error('core');
    expect(lxy.answer.cuspHeightMm).toBe(coreLxy.value.cuspHeightMm);
    // The sweep holds the typed step constant.
    expect(lxy.sweep?.programmedStepMm).toBe(1.5);
  });
});

describe('bad three-axis input: one line on its field, in the user unit; other values kept', () => {
  const base = parseUrl('?R=3&Rcr=1&machine=3axis&slope=30&h=0.05&unit=mm').state;
  it('slope, raster angle, steps and the surface radii each say their constraint and limit', () => {
    const cases: Array<[CalculatorState, string, RegExp]> = [
      [withField(base, 'slope', '95'), 'slope', /^Slope alpha must be from 0 to 90 degrees \(got 95\)/],
      [withField(base, 'slope', 'abc'), 'slope', /^Slope alpha must be a finite number \(got "abc"\)/],
      [withField(base, 'slope', ''), 'slope', /^Slope alpha is missing/],
      [withField(base, 'psi', '120'), 'psi', /^Raster angle psi must be from 0 to 90 degrees from the fall line/],
      [
        { ...withField(base, 'slope', '0'), passes: 'waterline' },
        'slope',
        /^Slope alpha must be above 0 degrees for waterline/,
      ],
      [
        { ...withField(base, 'Lxy', '20'), mode: 'inverse' },
        'Lxy',
        /^Horizontal step Lxy must be below 6 mm \(got 20\)/,
      ],
      [{ ...base, target: 'ra' }, 'ra', /^A target Ra is not offered for three-axis machining: /],
      // Not "Target Sa as a target": the quantity named once.
      [
        { ...base, target: 'sa' },
        'sa',
        /^A target Sa is not offered for three-axis machining: give the scallop height h\.$/,
      ],
      [
        {
          ...base,
          passes: 'waterline',
          feedSide: 'concave',
          crossSide: 'concave',
          fields: { ...base.fields, Rf: '50', Rc: '2' },
        },
        'Rc',
        /^Cross radius Rc is too tight for this tool at this slope \(got 2\): a concave meridian must have a radius of at least [\d.]+ mm/,
      ],
      [
        { ...base, passes: 'waterline', feedSide: 'convex', fields: { ...base.fields, Rf: 'x' } },
        'Rf',
        /^Feed radius Rf must be a number/,
      ],
    ];
    for (const [state, key, re] of cases) {
      const m = messagesOf(state);
      expect(m.get(key), `${key}: ${[...m.entries()].join(' | ')}`).toMatch(re);
      expect([...m.values()].join(' ').replace(/\(got [^)]*\)/g, '')).not.toMatch(/NaN|Infinity|(^|[^\d.])-0(?![\d.])/);
      // The other fields keep their text.
      expect(state.fields.R).toBe('3');
    }
  });

  it('a target Ra or Sa not offered: said in the language in force, the symbol once', () => {
    try {
      setCatalogue(de, null, null);
      expect(messagesOf({ ...base, target: 'sa' }).get('sa')).toBe(
        'Ein Ziel-Sa wird bei der 3-Achs-Bearbeitung nicht angeboten: bitte die Rautiefe h angeben.',
      );
      setCatalogue(ja, null, null);
      expect(messagesOf({ ...base, target: 'ra' }).get('ra')).toBe(
        '3軸加工では目標 Ra は使えません。カスプ高さ h を入力してください。',
      );
    } finally {
      setCatalogue(null, null, null);
    }
  });

  it('in inches every length of a message is in inches (the value as typed)', () => {
    const s = parseUrl('?R=0.125&Rcr=0.03125&machine=3axis&slope=30&mode=inverse&Lxy=2&unit=in').state;
    const m = messagesOf(s);
    const limitIn = formatInputNumber(fromMm(toMm(0.25, 'in'), 'in'));
    expect(m.get('Lxy')).toMatch(new RegExp(`^Horizontal step Lxy must be below ${limitIn} in \\(got 2\\)`));
    expect(m.get('Lxy')).not.toMatch(/mm/);
  });
});
