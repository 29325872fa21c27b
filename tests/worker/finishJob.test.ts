/**
 * The worker's `finish` job (src/worker/jobs/finish.ts) and the page's finish question
 * (src/ui/finishRequest.ts finishAsk): the job answers exactly the core's finishReport for the
 * validated finish, words each bad value in the request's unit on its field (quoting it as typed),
 * answers with runout as the core does (its feed marks and balanced feed), and writes the x3p of one cell;
 * the page asks nothing without teeth or feed and refuses, in one line, every surface where feed
 * marks are not computed (never a continuous answer).
 */
import { describe, expect, it } from 'vitest';
import { finishFailureWords, NOT_CONVERGED } from '../../src/core/finish/envelope';
import { balancedFeed, feedMarks, finishReport, toothModel } from '../../src/core/finish/index';
import { forwardInput } from '../../src/core/input/validate';
import { type FinishInputs, finishAsk, x3pFileName } from '../../src/ui/finishRequest';
import { type FinishRequest, PROFILE_POINTS } from '../../src/worker/finishProtocol';
import { finish } from '../../src/worker/jobs/finish';
import { solve } from '../../src/worker/jobs/solve';
import type { PageReply } from '../../src/worker/pageProtocol';
import { finishInputsOf } from '../support/finishInputs';

const TOOL = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 };

const inputs = finishInputsOf;

const plane = solve({ mode: 'forward', input: forwardInput(TOOL, 'one-way', 0.05) }) as PageReply;

function asked(i: FinishInputs, reply: PageReply = plane): FinishRequest {
  const a = finishAsk(i, reply);
  if (a.kind !== 'ask') throw new Error(`not asked: ${JSON.stringify(a)}`);
  return a.request;
}

describe('the finish job', () => {
  it("answers the core's finishReport at the answer's step-over, part by part (4 teeth, fz 0.1 mm, one-way)", () => {
    const request = asked(inputs({ flutes: 4, fz: 0.1 }));
    if (!plane.ok || !('exact' in plane)) throw new Error('plane');
    expect(request.intervalMm).toBe(plane.exact.intervalMm);
    expect(request.scallopMm).toBe(plane.exact.cuspHeightMm);
    const marks = finish(request);
    const areal = finish({ ...request, part: 'areal' });
    if (!marks.ok || !areal.ok) throw new Error('refused');
    const core = finishReport(TOOL, 'one-way', plane.exact.intervalMm, {
      flutes: 4,
      feedPerToothMm: 0.1,
      runoutMm: 0,
      runoutPhaseDeg: 0,
      passPhase: 0,
    });
    expect([marks.feedMarks, marks.areal]).toEqual([core.feedMarks, null]);
    expect([areal.feedMarks, areal.areal]).toEqual([null, core.areal]);
    // With the areal parameters, the cell's height map the page paints: its sampled range within Sz.
    const map = areal.map ?? new Float32Array();
    expect(map.length).toBe(256 * 256);
    const range = Math.max(...map) - Math.min(...map);
    const sz = core.areal?.Sz ?? Number.NaN;
    expect(range).toBeLessThanOrEqual(sz * (1 + 1e-6));
    expect(range).toBeGreaterThan(0.95 * sz);
    // And the profiles: along the CC path over two feed periods, its span within hf (the sampling's);
    // across over one step-over, at the x of the highest feed mark.
    const p = areal.profiles;
    if (p === null || p === undefined) throw new Error('no profiles');
    expect([p.along.atMm.length, p.across.atMm.length]).toEqual([PROFILE_POINTS, PROFILE_POINTS]);
    expect(p.along.atMm.at(-1)).toBeCloseTo(0.2, 15);
    expect((p.across.atMm.at(-1) as number) - (p.across.atMm[0] as number)).toBeCloseTo(plane.exact.intervalMm, 14);
    const along = Math.max(...p.along.heightsMm) - Math.min(...p.along.heightsMm);
    expect(along).toBeLessThanOrEqual(core.feedMarks.height + 1e-9);
    expect(along).toBeGreaterThan(0.95 * core.feedMarks.height);
    expect(p.acrossAtXMm).toBe(
      feedMarks(
        toothModel({
          tool: TOOL,
          pattern: 'one-way',
          intervalMm: request.intervalMm,
          finish: { flutes: 4, feedPerToothMm: 0.1, runoutMm: 0, runoutPhaseDeg: 0, passPhase: 0 },
        }),
      ).crestXMm,
    );
    expect(marks.profiles ?? null).toBeNull();
    expect(marks.map).toBeNull();
    expect(marks.request).toBe(request);
    expect(marks.x3p).toBeNull();
  });

  it('words a bad value on its field in the unit of the request, quoting it as typed; others valid', () => {
    const r = asked(inputs({ flutes: 4, fz: 5 * 25.4 }, 'in'));
    const reply = finish({ ...r, typed: { ...r.typed, fz: '5' } });
    expect(reply.ok).toBe(false);
    if (reply.ok) return;
    expect(reply.errors).toEqual([
      {
        field: 'fz',
        message: expect.stringMatching(
          /^Feed per tooth fz must be at most the tool radius R = 0\.11811 in \(got 5\)\.$/,
        ),
        // The same as data (a page words it in its language): the bound in mm, what was typed.
        error: { field: 'fz', code: 'too-large', got: '5', limit: 3 },
      },
    ]);
    const fractional = finish(asked(inputs({ flutes: 2.5, fz: 0.1 })));
    expect(!fractional.ok && fractional.errors.map((e) => e.field)).toEqual(['flutes']);
  });

  it("answers runout with the core's feed marks over a turn and its balanced feed (2 teeth, e 0.005 mm at 30 degrees)", () => {
    const request = asked(inputs({ flutes: 2, fz: 0.1, runout: 0.005, runoutPhase: 30 }));
    const reply = finish(request);
    if (!reply.ok || !plane.ok || !('exact' in plane)) throw new Error('refused');
    const input = { flutes: 2, feedPerToothMm: 0.1, runoutMm: 0.005, runoutPhaseDeg: 30, passPhase: 0 };
    const marks = feedMarks(
      toothModel({ tool: TOOL, pattern: 'one-way', intervalMm: request.intervalMm, finish: input }),
    );
    const balanced = balancedFeed(TOOL, 'one-way', request.intervalMm, input);
    expect(reply.feedMarks).toEqual({
      height: marks.heightMm,
      period: 0.2,
      balancedFz: balanced.ok ? balanced.feedPerToothMm : null,
    });
    // The teeth cut unequally: the marks are taller than without runout.
    const even = feedMarks(
      toothModel({ tool: TOOL, pattern: 'one-way', intervalMm: request.intervalMm, finish: { ...input, runoutMm: 0 } }),
    );
    expect(marks.heightMm).toBeGreaterThan(even.heightMm);
  });

  it('writes the x3p of one cell when asked: a zip of 256 x 256 float64 heights', () => {
    const r = asked(inputs({ flutes: 4, fz: 0.1 }));
    const reply = finish({ ...r, x3p: { size: 256, fileName: 'f.x3p', comment: 'f' } });
    if (!reply.ok || reply.x3p === null) throw new Error('no x3p');
    expect([...reply.x3p.slice(0, 4)]).toEqual([0x50, 0x4b, 0x03, 0x04]);
    expect(reply.x3p.length).toBeGreaterThan(256 * 256 * 8);
    expect(reply.x3p.length).toBeLessThan(256 * 256 * 8 + 20_000);
  });
});

describe("the page's finish question", () => {
  it('asks nothing without teeth or feed, and nothing of a refused answer', () => {
    expect(finishAsk(inputs({}), plane)).toEqual({ kind: 'none' });
    expect(finishAsk(inputs({ flutes: 4, fz: 0.1 }), null)).toEqual({ kind: 'none' });
  });

  it('refuses a cylinder in one line (never the continuous answer)', () => {
    const cylinder = solve({
      mode: 'forward',
      input: forwardInput(TOOL, 'one-way', 0.05, { kind: 'cylinder', radiusMm: 50, axis: 'feed' }),
    }) as PageReply;
    expect(finishAsk(inputs({ flutes: 4, fz: 0.1 }), cylinder)).toEqual({
      kind: 'refused',
      message: expect.stringMatching(/^Feed marks are not computed on cylinders yet: only on a plane/),
      surface: 'cylinder',
    });
  });
});

describe("the page's finish question beyond the five-axis plane", () => {
  const teeth = inputs({ flutes: 4, fz: 0.1 });
  /** A three-axis answer as the worker gives it, with only the parts the finish reads. */
  const threeAxis = (surface: 'plane' | 'revolution') =>
    ({
      ok: true,
      request: {
        mode: 'three-axis',
        input: {
          surface,
          case: { toolRadiusMm: 3, cornerRadiusMm: 1, slopeDeg: 30, passes: 'raster', rasterAngleDeg: 30 },
        },
      },
      answer: { leadDeg: 12, tiltDeg: -3, cuspHeightMm: 0.01, intervalMm: 1.5, noScallop: false },
    }) as unknown as PageReply;

  it('asks the sloped plane at its equivalent posture, one-way, at its step-over and cusp', () => {
    const a = finishAsk(teeth, threeAxis('plane'));
    expect(a.kind === 'ask' && a.request).toMatchObject({
      tool: { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 12, tiltAngleDeg: -3 },
      pattern: 'one-way',
      intervalMm: 1.5,
      scallopMm: 0.01,
      part: 'marks',
    });
    // Its x3p is named by the question asked (the slope and the passes), not the posture it stands on.
    if (a.kind !== 'ask') throw new Error('asked');
    expect(x3pFileName(a.request)).toBe('finish_R3_Rcr1_3-axis_slope30_raster30_L1.5_z4_fz0.1_mm.x3p');
    expect(x3pFileName(asked(teeth))).toMatch(/^finish_R3_Rcr1_rho5_tilt0_one-way_L[\d.]+_z4_fz0\.1_mm\.x3p$/);
  });

  it('refuses waterline on a surface of revolution and a doubly curved point in one line', () => {
    expect(finishAsk(teeth, threeAxis('revolution'))).toEqual({
      kind: 'refused',
      message: expect.stringMatching(/^Feed marks are not computed on waterline passes on surfaces of revolution yet/),
      surface: 'waterlineRevolution',
    });
    const curved = { ok: true, request: { mode: 'curved-forward' } } as unknown as PageReply;
    expect(finishAsk(teeth, curved)).toEqual({
      kind: 'refused',
      message: expect.stringMatching(/^Feed marks are not computed on doubly curved points yet/),
      surface: 'doublyCurved',
    });
  });

  it('where the areal parameters cannot be computed it answers ok: false in one plain line on fz, never throws (flat end upright, L = 2R)', () => {
    const flat = { toolRadiusMm: 3, cornerRadiusMm: 0, leadAngleDeg: 0, tiltAngleDeg: 0 };
    const reply = solve({ mode: 'forward', input: forwardInput(flat, 'one-way', 0.05) }) as PageReply;
    const request = asked(inputs({ flutes: 4, fz: 0.1 }), reply);
    const marks = finish(request);
    expect(marks.ok).toBe(true);
    const areal = finish({ ...request, part: 'areal' });
    if (areal.ok) throw new Error('answered');
    expect(areal.errors).toEqual([
      {
        field: 'fz',
        message:
          'The areal parameters are not defined here: thin slivers between the passes are cut by no tooth (the bottom edges miss them); try a smaller step-over.',
        failure: { kind: 'not-swept', part: 'areal' },
      },
    ]);
  });

  it('words a search that did not converge in one line per part, and leaves other errors alone', () => {
    expect(finishFailureWords(new Error(NOT_CONVERGED), 'areal')).toBe(
      'The areal parameters could not be computed for this feed: the event search did not converge; try a smaller fz.',
    );
    expect(finishFailureWords(new Error(NOT_CONVERGED), 'marks')).toBe(
      'The feed marks could not be computed for this feed: the event search did not converge; try a smaller fz.',
    );
    expect(finishFailureWords(new Error('other'), 'areal')).toBeNull();
    expect(finishFailureWords('x', 'areal')).toBeNull();
  });
});
