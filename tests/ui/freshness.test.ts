/**
 * What the page may show: only a reply to the inputs on screen counts as current. Whatever order
 * replies arrive in (even a client that delivered stale ones), an earlier input's numbers never
 * come back as current, invalid inputs show none, and a solver that gave up leaves a stale mark.
 */
import { describe, expect, it } from 'vitest';
import { forwardInput, type ToolInput } from '../../src/core/index';
import { Freshness } from '../../src/ui/freshness';
import type { SolveRequest } from '../../src/worker/protocol';

const TOOL: ToolInput = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 };
const ask = (h: number): SolveRequest => ({ mode: 'forward', input: forwardInput(TOOL, 'one-way', h) });
/** A reply echoing a request built again from the same numbers (equal, not the same object). */
const reply = (h: number) => ({ request: ask(h), value: h });

describe('freshness of the shown results', () => {
  it('a reply counts only for the inputs it answers; before it arrives the last one is pending (stale)', () => {
    const f = new Freshness<ReturnType<typeof reply>>();
    expect(f.want(ask(0.05)).kind).toBe('pending');
    expect(f.receive(reply(0.05))).toBe(true);
    expect(f.shown).toEqual({ kind: 'current', reply: reply(0.05) });
    const s = f.want(ask(0.06));
    expect(s).toEqual({ kind: 'pending', last: reply(0.05) });
  });

  it('valid then invalid: a late reply to the valid input never shows (defect 1)', () => {
    const f = new Freshness<ReturnType<typeof reply>>();
    f.want(ask(0.06));
    f.want(null); // "abc" typed in the same task
    expect(f.receive(reply(0.06))).toBe(false);
    expect(f.shown.kind).toBe('invalid');
  });

  it('a burst of inputs with replies delivered out of order and late ends on the latest input alone', () => {
    const f = new Freshness<ReturnType<typeof reply>>();
    const hs = Array.from({ length: 30 }, (_, i) => 0.05 + i / 1000);
    for (const h of hs) f.want(ask(h));
    // A client that delivered every stale reply, newest first then the rest:
    for (const h of [...hs].reverse()) f.receive(reply(h));
    expect(f.shown).toEqual({ kind: 'current', reply: reply(hs[hs.length - 1] as number) });
    f.want(ask(0.2));
    for (const h of hs) f.receive(reply(h));
    expect(f.shown.kind).toBe('pending');
  });

  it('give-up: the solver failed on the inputs on screen: shown as failed (stale), until the inputs change', () => {
    const f = new Freshness<ReturnType<typeof reply>>();
    f.want(ask(0.05));
    f.receive(reply(0.05));
    f.want(ask(0.07));
    f.fail();
    expect(f.shown).toEqual({ kind: 'failed', last: reply(0.05) });
    // A reply to an older input does not clear it; new inputs are pending again.
    f.receive(reply(0.05));
    expect(f.shown.kind).toBe('failed');
    f.want(ask(0.08));
    expect(f.shown.kind).toBe('pending');
    // Going back to inputs already answered shows that answer at once.
    f.want(ask(0.05));
    expect(f.shown.kind).toBe('current');
  });
});
