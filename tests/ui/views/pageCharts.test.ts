/**
 * The words of the three-axis and doubly curved charts: the crossing sentence (one sentence, the
 * crossing's slope and step in the user's unit, or plainly no crossing) and the radius chart's gap
 * notes, from the worker's own data for real requests. No NaN, Infinity or -0 in any of them.
 */
import { describe, expect, it } from 'vitest';
import { slopedPlaneInverse } from '../../../src/core/threeAxis/slopedPlane';
import { buildRequest } from '../../../src/ui/request';
import { parseUrl } from '../../../src/ui/state';
import { crossingSentence, radiusGapNotes, radiusWords, refusalNotes } from '../../../src/ui/views/pageChartText';
import { teachCurved, teachThreeAxis } from '../../../src/worker/jobs/teachPage';
import type { CurvedRequest, ThreeAxisRequest } from '../../../src/worker/pageProtocol';

function requestOf(query: string) {
  const built = buildRequest(parseUrl(query).state);
  if (!built.ok) throw new Error(`invalid: ${query}`);
  return built.request;
}

function slopeOf(query: string) {
  const reply = teachThreeAxis(requestOf(query) as ThreeAxisRequest);
  if (!reply.ok) throw new Error('no chart');
  return reply.slope;
}

const clean = (text: string) => expect(text).not.toMatch(/NaN|Infinity|-0(?![.\d])|undefined/);

describe('the crossing sentence', () => {
  it('says where raster and waterline cross, in mm and in inch, as one sentence', () => {
    // psi = 90: the crossing is 45 degrees exactly (Lxy = L cos a, dz = L sin a), both 2.828... mm... there.
    const d = slopeOf('?R=3&Rcr=1&machine=3axis&slope=30&rasterAngle=90&h=0.01&unit=mm');
    const step = d.crossingStepMm as number;
    const mm = crossingSentence(d, 'mm');
    expect(mm).toBe(
      `Above 45° waterline programs a larger step than raster at psi = 90° for the same scallop of 10.00 µm, below it raster at psi = 90° does (both ${step.toFixed(4)} mm at 45°).`,
    );
    const inch = crossingSentence(d, 'in');
    const m =
      /^Above 45° waterline programs a larger step than raster at psi = 90° for the same scallop of 0\.3937 thou, below it raster at psi = 90° does \(both ([\d.]+) thou at 45°\)\.$/.exec(
        inch,
      );
    expect(m, inch).not.toBeNull();
    expect(Number(m?.[1])).toBeCloseTo((1000 * step) / 25.4, 3);
    for (const t of [mm, inch]) {
      clean(t);
      expect(t.match(/\. |\.$/g)).toHaveLength(1);
    }
  });

  it('says plainly when they do not cross (raster down the fall line keeps Lxy = L)', () => {
    const d = slopeOf('?R=3&Rcr=1&machine=3axis&slope=30&rasterAngle=0&h=0.05&unit=mm');
    expect(d.crossingDeg).toBeNull();
    expect(crossingSentence(d, 'mm')).toBe(
      'Waterline and raster at psi = 0° do not cross for a scallop of 50.00 µm: raster at psi = 0° programs the larger step at every slope where both are valid.',
    );
    const w = slopeOf('?R=3&Rcr=1&machine=3axis&slope=30&passes=waterline&feedRadius=50&crossRadius=50&h=0.01&unit=in');
    clean(crossingSentence(w, 'in'));
    expect(crossingSentence(w, 'in')).toMatch(/on a plane of that slope/);
  });
});

describe('where the constant step leaves no scallop', () => {
  it('each run of refused slopes is said with the core inverse reason', () => {
    const d = slopeOf('?R=3&Rcr=1&machine=3axis&slope=30&rasterAngle=90&h=0.01&unit=mm');
    const run = d.constantStepRefusals[0];
    if (run === undefined) throw new Error('the flat floor step is refused on steep slopes');
    const inv = slopedPlaneInverse(
      { toolRadiusMm: 3, cornerRadiusMm: 1, slopeDeg: run.fromDeg, passes: 'raster', rasterAngleDeg: 90 },
      { field: 'horizontalStep', mm: d.constantStepMm },
    );
    expect(inv.ok).toBe(false);
    if (!inv.ok) expect(run.code).toBe(inv.errors[0]?.code);
    const notes = refusalNotes(d, 'in');
    expect(notes[0]).toMatch(/^No scallop for the constant Lxy = [\d.]+ in from about [\d.]+° to [\d.]+°: /);
    for (const n of notes) clean(n);
  });
});

describe('the radius charts words', () => {
  it('name each gap with its radii in the user unit, the side and why', () => {
    const reply = teachCurved(
      requestOf('?R=3&Rcr=1&rho=10&tilt=0&h=0.05&feedRadius=40&crossRadius=-20&unit=mm') as CurvedRequest,
    );
    if (!reply.ok) throw new Error('no data');
    const notes = radiusGapNotes(reply.cross, 'mm');
    expect(
      notes.some((n) =>
        /^No concave L for \|Rc\| from about [\d.]+ mm to [\d.]+ mm \(Rf held convex 40 mm\): the tool gouges/.test(n),
      ),
    ).toBe(true);
    for (const n of [...notes, ...radiusGapNotes(reply.feed, 'in')]) clean(n);
    expect(radiusWords(-20, 'mm')).toBe('concave 20 mm');
    expect(radiusWords(Number.POSITIVE_INFINITY, 'in')).toBe('straight');
  });
});
