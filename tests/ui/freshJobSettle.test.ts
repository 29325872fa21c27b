/**
 * FreshJob's settle wait (the teaching views wait for a dragged slider to rest before they ask):
 * a model-based property test. fast-check draws a sequence of inputs (a few values of h, or an
 * invalid input), replies to any of them, give-ups, direct syncs, the view opened and closed, and
 * time passing, against FreshJob on the test's clock; a small model of what is wanted, what was
 * answered and what was given up says after each step what FreshJob may and must have asked:
 *  - never: a request other than the one wanted, one already shown or given up, one asked while
 *    closed, or one asked before it was wanted unchanged for the settle wait (a drag's every step
 *    would go to the worker);
 *  - always: once the wanted request is pending, open and past its settle wait, it has been asked
 *    since it was wanted (else the page waits for a reply nobody asked).
 * freshnessModel.test.ts checks that the page ends on the right answer; this one checks when it asks.
 */
import fc from 'fast-check';
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { forwardInput, type ToolInput } from '../../src/core/index';
import { FreshJob } from '../../src/ui/freshness';
import type { SolveRequest } from '../../src/worker/protocol';

const SEED = 2611;
const RUNS = 300;

const TOOL: ToolInput = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 };
/** The inputs drawn from: h in mm, or null (invalid text: no request). */
const VALUES: readonly (number | null)[] = [0.05, 0.051, 0.052, null];
/** A request built afresh from its numbers each time (equal to an earlier one, never the same object). */
const requestOf = (h: number | null): SolveRequest | null =>
  h === null ? null : { mode: 'forward', input: forwardInput(TOOL, 'one-way', h) };
const hOf = (r: SolveRequest): number => (r.mode === 'forward' ? r.input.scallopHeightMm : Number.NaN);

type Cmd =
  | { readonly kind: 'want'; readonly value: number }
  | { readonly kind: 'receive'; readonly value: number }
  | { readonly kind: 'gaveUp'; readonly value: number }
  | { readonly kind: 'sync' }
  | { readonly kind: 'open'; readonly open: boolean }
  | { readonly kind: 'tick'; readonly ms: number };

const index = fc.nat(VALUES.length - 1);
const cmdArb: fc.Arbitrary<Cmd> = fc.oneof(
  { weight: 5, arbitrary: fc.record({ kind: fc.constant('want' as const), value: index }) },
  { weight: 3, arbitrary: fc.record({ kind: fc.constant('receive' as const), value: fc.nat(2) }) },
  { weight: 1, arbitrary: fc.record({ kind: fc.constant('gaveUp' as const), value: index }) },
  { weight: 1, arbitrary: fc.record({ kind: fc.constant('sync' as const) }) },
  { weight: 1, arbitrary: fc.record({ kind: fc.constant('open' as const), open: fc.boolean() }) },
  // Mostly steps shorter than the settle wait (150 ms), so that several events fall within one wait.
  { weight: 4, arbitrary: fc.record({ kind: fc.constant('tick' as const), ms: fc.integer({ min: 0, max: 100 }) }) },
  { weight: 1, arbitrary: fc.record({ kind: fc.constant('tick' as const), ms: fc.constantFrom(149, 150, 151, 400) }) },
);

/** What FreshJob should show and may ask, kept by the test alone (not by the page's own comparisons). */
interface Model {
  wanted: number | null;
  /** When the wanted request last changed (ms, the test's clock). */
  changedAt: number;
  /** The h of the reply last shown (a reply counts only when it answers what is wanted). */
  last: number | null;
  failed: boolean;
  open: boolean;
  /** Asks of the wanted request since it last changed. */
  asksSinceChange: number;
}

const kindOf = (m: Model) =>
  m.wanted === null ? 'invalid' : m.last === m.wanted ? 'current' : m.failed ? 'failed' : 'pending';

function run(settleMs: number, cmds: readonly Cmd[]): void {
  vi.clearAllTimers();
  const start = Date.now();
  const m: Model = { wanted: null, changedAt: start, last: null, failed: false, open: true, asksSinceChange: 0 };
  const ask = (request: SolveRequest) => {
    const h = hOf(request);
    const now = Date.now();
    const at = `ask of h = ${h} at t = ${now - start} ms (wanted ${m.wanted} since ${m.changedAt - start} ms)`;
    expect(h, at).toBe(m.wanted);
    expect(kindOf(m), at).toBe('pending');
    expect(m.open, at).toBe(true);
    expect(now - m.changedAt, `${at}: before the settle wait of ${settleMs} ms`).toBeGreaterThanOrEqual(settleMs);
    m.asksSinceChange++;
  };
  const job = new FreshJob<{ request: SolveRequest }>({ ask, settleMs });
  const want = (h: number | null) => {
    if (h !== m.wanted) {
      m.failed = false;
      m.wanted = h;
      m.changedAt = Date.now();
      m.asksSinceChange = 0;
    }
    job.want(requestOf(h));
  };
  want(VALUES[0] ?? null);
  for (const c of cmds) {
    switch (c.kind) {
      case 'want':
        want(VALUES[c.value] ?? null);
        break;
      case 'receive': {
        const h = VALUES[c.value] as number;
        if (h === m.wanted) {
          m.last = h;
          m.failed = false;
        }
        expect(job.receive({ request: requestOf(h) as SolveRequest })).toBe(h === m.wanted);
        break;
      }
      case 'gaveUp': {
        const h = VALUES[c.value] ?? null;
        if (h === m.wanted && h !== null) m.failed = true;
        job.gaveUp(requestOf(h));
        break;
      }
      case 'sync':
        job.sync();
        break;
      case 'open':
        m.open = c.open;
        job.setOpen(c.open);
        break;
      case 'tick':
        vi.advanceTimersByTime(c.ms);
        break;
    }
    expect(job.shown.kind, `after ${JSON.stringify(c)}`).toBe(kindOf(m));
    const settled = Date.now() - m.changedAt >= settleMs;
    if (kindOf(m) === 'pending' && m.open && settled)
      expect(m.asksSinceChange, `h = ${m.wanted} pending, open and settled, never asked`).toBeGreaterThan(0);
  }
}

beforeEach(() => {
  vi.useFakeTimers();
});
afterEach(() => {
  vi.clearAllTimers();
  vi.useRealTimers();
});

describe(`FreshJob asks only the wanted request, only after its settle wait, and always then (fast-check seed ${SEED}, ${RUNS} runs each)`, () => {
  for (const settleMs of [0, 150]) {
    it(`settle wait ${settleMs} ms (seed ${SEED})`, () => {
      fc.assert(
        fc.property(fc.array(cmdArb, { minLength: 5, maxLength: 40, size: 'medium' }), (cmds) => run(settleMs, cmds)),
        { seed: SEED, numRuns: RUNS },
      );
    });
  }

  it('a drag (h changing every 20 ms, settle wait 150 ms) asks nothing until it rests, then its last value once', () => {
    const asked: number[] = [];
    const job = new FreshJob<{ request: SolveRequest }>({ ask: (r) => asked.push(hOf(r)), settleMs: 150 });
    for (let i = 0; i < 20; i++) {
      job.want(requestOf(0.05 + i / 1000));
      vi.advanceTimersByTime(20);
      job.sync();
    }
    expect(asked).toEqual([]);
    vi.advanceTimersByTime(130);
    expect(asked).toEqual([0.069]);
  });
});
