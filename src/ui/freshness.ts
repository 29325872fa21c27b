/**
 * Whether what the page shows answers the inputs on screen. Pure (no DOM), one per kind of reply
 * (results, teaching views). The page asks `shown` and draws exactly that:
 *  - invalid: the inputs are invalid: dashes, and any picture marked stale;
 *  - current: the reply to the inputs on screen: its numbers;
 *  - pending: not answered yet: the last reply, if any, marked stale (never as if current);
 *  - failed: the worker gave up: as pending, and the page says so.
 * A reply counts only if its request equals the one wanted (sameRequest), so a late or repeated
 * reply to an earlier input can never come back on screen.
 */
import { type SolveRequest, sameRequest } from '../worker/protocol';

export type Shown<Rep> =
  | { readonly kind: 'invalid'; readonly last: Rep | null }
  | { readonly kind: 'current'; readonly reply: Rep }
  | { readonly kind: 'pending'; readonly last: Rep | null }
  | { readonly kind: 'failed'; readonly last: Rep | null };

export class Freshness<Rep extends { readonly request: SolveRequest }> {
  private wanted: SolveRequest | null = null;
  private last: Rep | null = null;
  private failed = false;

  /** The inputs changed: the request they ask, or null when they are invalid. */
  want(request: SolveRequest | null): Shown<Rep> {
    if (!sameRequest(request, this.wanted)) this.failed = false;
    this.wanted = request;
    return this.shown;
  }

  /** A reply arrived; true when it answers the inputs on screen (and is now shown). */
  receive(reply: Rep): boolean {
    if (!sameRequest(reply.request, this.wanted)) return false;
    this.last = reply;
    this.failed = false;
    return true;
  }

  /** The worker gave up on the wanted request. */
  fail(): void {
    if (this.wanted !== null) this.failed = true;
  }

  /** The request the inputs ask (null when invalid). */
  get request(): SolveRequest | null {
    return this.wanted;
  }

  get shown(): Shown<Rep> {
    if (this.wanted === null) return { kind: 'invalid', last: this.last };
    if (this.last !== null && sameRequest(this.last.request, this.wanted)) return { kind: 'current', reply: this.last };
    return { kind: this.failed ? 'failed' : 'pending', last: this.last };
  }
}
