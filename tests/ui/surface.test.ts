/**
 * The page's surface inputs (issue 12): plane, convex or concave cylinder, the radius as a
 * magnitude in the user's unit and the axis; their URL form; the request they make and where their
 * errors show. Pure: no DOM.
 */
import { describe, expect, it } from 'vitest';
import { formatInputNumber, fromMm, toMm } from '../../src/core/input/units';
import { forwardInput } from '../../src/core/input/validate';
import { scallopHeightForRaMm } from '../../src/core/roughness/roughness';
import { minConcaveRadiusMm } from '../../src/core/surfaces/cylinder';
import { exactForward } from '../../src/core/surfaces/solve';
import { buildRequest, fieldMessages, fieldOfError } from '../../src/ui/request';
import { convertState, defaultState, parseUrl, toSearch, withField } from '../../src/ui/state';
import { solvePage } from '../../src/worker/jobs/page';
import { answered, answeredMessages, answeredRanges } from '../support/pageAnswer';

const parse = (q: string) => parseUrl(q);
const TOOL = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 };

describe('surface in the state and the URL', () => {
  it('a plane writes neither surfaceRadius nor surfaceAxis; the defaults are a plane, feed, radius 50 mm', () => {
    const s = defaultState();
    expect(s.surface).toBe('plane');
    expect(s.surfaceAxis).toBe('feed');
    expect(s.fields.Rs).toBe('50');
    const q = new URLSearchParams(toSearch(s));
    expect(q.has('surfaceRadius')).toBe(false);
    expect(q.has('surfaceAxis')).toBe(false);
    // A plane keeps the axis and radius it had for the next cylinder, but the link says nothing of them.
    const kept = toSearch({ ...withField(s, 'Rs', '12'), surfaceAxis: 'cross' });
    expect(kept).not.toMatch(/surface/);
  });

  it('a cylinder round-trips: signed radius (concave negative), axis; the field keeps the magnitude as typed', () => {
    for (const [q, kind, axis, field] of [
      ['?R=3&Rcr=1&rho=5&surfaceRadius=20&surfaceAxis=feed&h=0.05&unit=mm', 'convex', 'feed', '20'],
      ['?R=3&Rcr=1&rho=5&surfaceRadius=-37.5&surfaceAxis=cross&h=0.05&unit=mm', 'concave', 'cross', '37.5'],
      ['?R=3&Rcr=1&rho=5&surfaceRadius=%2B8&h=0.05&unit=mm', 'convex', 'feed', '8'],
    ] as const) {
      const p = parse(q);
      expect(p.notices).toEqual([]);
      expect(p.state.surface).toBe(kind);
      expect(p.state.surfaceAxis).toBe(axis);
      expect(p.state.fields.Rs).toBe(field);
      const again = parse(toSearch(p.state));
      expect(again.state).toEqual(p.state);
    }
    expect(toSearch(parse('?R=3&Rcr=1&rho=5&surfaceRadius=-37.5&surfaceAxis=cross&h=0.05&unit=mm').state)).toBe(
      '?R=3&Rcr=1&rho=5&surfaceRadius=-37.5&surfaceAxis=cross&h=0.05&unit=mm',
    );
  });

  it('an invalid radius falls back to a plane, an invalid axis to feed, each with a notice', () => {
    const p = parse('?R=3&Rcr=1&rho=5&surfaceRadius=abc&surfaceAxis=sideways&h=0.05&unit=mm');
    expect(p.state.surface).toBe('plane');
    expect(p.state.surfaceAxis).toBe('feed');
    expect(p.notices).toHaveLength(2);
    expect(p.notices.join(' ')).toMatch(/surfaceRadius="abc" .* using a plane/);
    expect(p.notices.join(' ')).toMatch(/surfaceAxis="sideways" is not feed or cross/);
    // An axis alone: a plane (silently; it has no axis).
    expect(parse('?R=3&Rcr=1&rho=5&surfaceAxis=cross&h=0.05&unit=mm').state.surface).toBe('plane');
  });

  it('inch mode converts the radius like the other lengths', () => {
    // The default radius becomes the inch default; an edited one converts without loss.
    expect(convertState({ ...defaultState(), surface: 'concave' }, 'in').fields.Rs).toBe('2');
    const s = convertState(withField({ ...defaultState(), surface: 'concave' }, 'Rs', '50'), 'in');
    expect(s.fields.Rs).toBe('1.968503937008');
    expect(new URLSearchParams(toSearch(s)).get('surfaceRadius')).toBe('-1.968503937008');
    // Back to mm: what was typed.
    expect(convertState(s, 'mm').fields.Rs).toBe('50');
  });
});

describe('the request a surface makes', () => {
  it('a cylinder goes to the core as the signed radius in mm and the axis', () => {
    const r = buildRequest(parse('?R=3&Rcr=1&rho=5&surfaceRadius=-30&surfaceAxis=cross&h=0.002&unit=in').state);
    if (!r.ok || r.request.mode !== 'forward') throw new Error('valid');
    expect(r.request.input.surface).toEqual({ kind: 'cylinder', radiusMm: -30 * 25.4, axis: 'cross' });
    const p = buildRequest(defaultState());
    expect(p.ok && p.request.mode === 'forward' && p.request.input.surface).toEqual({ kind: 'plane' });
    const inv = buildRequest(parse('?R=3&Rcr=1&rho=5&surfaceRadius=30&mode=inverse&L=2.5&unit=mm').state);
    expect(inv.ok && inv.request.mode === 'inverse' && inv.request.input.surface).toEqual({
      kind: 'cylinder',
      radiusMm: 30,
      axis: 'feed',
    });
  });

  it('gouging shows on the radius field with the smallest admissible radius, in the user unit', () => {
    expect(fieldOfError('surfaceRadius')).toBe('Rs');
    for (const unit of ['mm', 'in'] as const) {
      const base = { ...defaultState(unit), surface: 'concave' as const };
      const tight = withField(base, 'Rs', unit === 'mm' ? '20' : '0.8');
      // Gouging is a solve: the page asks, the worker refuses (its message on the radius field as the page's own).
      expect(answered(tight)).toBe(false);
      // The tool as the fields give it in this unit (R = 0.11811 in is not quite 3 mm).
      const mm = (key: 'R' | 'Rcr') => toMm(Number(base.fields[key]), unit);
      const limit = minConcaveRadiusMm({ ...TOOL, toolRadiusMm: mm('R'), cornerRadiusMm: mm('Rcr') }, 'feed');
      const shown = formatInputNumber(fromMm(limit, unit));
      expect(answeredMessages(tight).get('Rs')).toBe(
        `Surface radius Rs: a concave cylinder must have a radius of at least ${shown} ${unit} for this tool and posture (got ${tight.fields.Rs}); a tighter one is gouged (the tool reaches below the surface away from the contact).`,
      );
    }
  });

  it('a radius with a sign, 0, out of range or not a number: a message on the radius field', () => {
    const cyl = { ...defaultState(), surface: 'convex' as const };
    const message = (text: string) => {
      const s = withField(cyl, 'Rs', text);
      const r = buildRequest(s);
      if (r.ok) throw new Error(`${text} is invalid`);
      return fieldMessages(s, r.errors).get('Rs');
    };
    expect(message('-20')).toBe('Surface radius Rs must be greater than 0 mm (got -20).');
    expect(message('0')).toBe('Surface radius Rs must be greater than 0 mm (got 0).');
    expect(message('0.0001')).toBe('Surface radius Rs must be a radius from 0.001 mm to 1000000 mm (got 0.0001).');
    expect(message('abc')).toMatch(/Surface radius Rs must be a number \(got "abc"\)/);
    expect(message('')).toMatch(/Surface radius Rs is missing/);
    // A plane ignores whatever the hidden radius field holds.
    expect(buildRequest(withField(defaultState(), 'Rs', 'abc')).ok).toBe(true);
  });

  it('a target Ra on a cylinder across the feed is answered on the page, the step-over as the core gives it', () => {
    const s = parse('?R=3&Rcr=1&rho=5&surfaceRadius=50&surfaceAxis=cross&target=ra&ra=0.01&unit=mm').state;
    const r = buildRequest(s);
    if (!r.ok || r.request.mode !== 'ra') throw new Error('asked');
    const reply = solvePage(r.request);
    if (!reply.ok || !('roughness' in reply) || !('exact' in reply)) throw new Error('answered');
    const surface = { kind: 'cylinder', radiusMm: 50, axis: 'cross' } as const;
    const tool = { ...TOOL, pattern: 'one-way' } as const;
    const h = scallopHeightForRaMm(TOOL, 'one-way', 0.01, surface);
    expect(reply.roughness.scallopHeightMm).toBe(h);
    expect(reply.exact.intervalMm).toBe(exactForward(forwardInput(tool, 'one-way', h, surface)).intervalMm);
    // Independent of the solve: the surface that step-over leaves has the Ra asked for.
    expect(reply.roughness.raMm).toBeCloseTo(0.01, 9);
    const feed = buildRequest({ ...s, surfaceAxis: 'feed' });
    expect(feed.ok && feed.request.mode).toBe('ra');
  });

  it('the radius slider starts at the gouging limit for a concave cylinder; h and L ranges follow the surface', () => {
    const concave = { ...defaultState(), surface: 'concave' as const };
    const limit = minConcaveRadiusMm(TOOL, 'feed');
    expect(Number(answeredRanges(concave).Rs.min)).toBe(Math.ceil(limit / 0.1) * 0.1);
    // A radius the tool gouges: the worker refuses it, and its reply starts the slider at the limit too.
    const gouged = withField(concave, 'Rs', '5');
    expect(answered(gouged)).toBe(false);
    expect(Number(answeredRanges(gouged).Rs.min)).toBe(Math.ceil(limit / 0.1) * 0.1);
    expect(Number(answeredRanges({ ...concave, surface: 'convex' }).Rs.min)).toBe(0.1);
    const convex = withField({ ...concave, surface: 'convex' as const }, 'Rs', '5');
    expect(answeredRanges(convex).L.max).not.toBe(answeredRanges(defaultState()).L.max);
  });
});
