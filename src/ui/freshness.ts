/**
 * Whether what the page shows answers the inputs on screen. Pure (no DOM), one per kind of reply
 * (results, teaching views). The page asks `shown` and draws exactly that:
 *  - invalid: the inputs are invalid: dashes, and any picture marked stale;
 *  - current: the reply to the inputs on screen: its numbers;
 *  - pending: not answered yet: the last reply, if any, marked stale (never as if current);
 *  - failed: the worker gave up: as pending, and the page says so.
 * A reply counts only if its request equals the one wanted (samePageRequest), so a late or repeated
 * reply to an earlier input can never come back on screen.
 *
 * FreshJob adds when to ask: whenever what is shown is pending, the wanted request is asked of the
 * job's client, after every event (input, reply, restart, view opened). It keeps no memory of what
 * it asked before: the client alone skips a request equal to the one whose reply is still to come
 * (client.ts), so a reply dropped here (another input was on screen when it came) can never leave
 * the page waiting for a request nobody sends again (issue 17).
 */
import { type PageRequest, samePageRequest } from '../worker/pageProtocol';

export type Shown<Rep> =
  | { readonly kind: 'invalid'; readonly last: Rep | null }
  | { readonly kind: 'current'; readonly reply: Rep }
  | { readonly kind: 'pending'; readonly last: Rep | null }
  | { readonly kind: 'failed'; readonly last: Rep | null };

export class Freshness<Rep extends { readonly request: Req }, Req extends PageRequest = Rep['request']> {
  private wanted: Req | null = null;
  private last: Rep | null = null;
  private failed = false;

  /** The inputs changed: the request they ask, or null when they are invalid. */
  want(request: Req | null): Shown<Rep> {
    if (!samePageRequest(request, this.wanted)) this.failed = false;
    this.wanted = request;
    return this.shown;
  }

  /** A reply arrived; true when it answers the inputs on screen (and is now shown). */
  receive(reply: Rep): boolean {
    if (!samePageRequest(reply.request, this.wanted)) return false;
    this.last = reply;
    this.failed = false;
    return true;
  }

  /** The worker gave up on the wanted request. */
  fail(): void {
    if (this.wanted !== null) this.failed = true;
  }

  /** The request the inputs ask (null when invalid). */
  get request(): Req | null {
    return this.wanted;
  }

  get shown(): Shown<Rep> {
    if (this.wanted === null) return { kind: 'invalid', last: this.last };
    if (this.last !== null && samePageRequest(this.last.request, this.wanted))
      return { kind: 'current', reply: this.last };
    return { kind: this.failed ? 'failed' : 'pending', last: this.last };
  }
}

/** How a FreshJob asks its job's client, and when. */
export interface FreshJobOptions<Req extends PageRequest = PageRequest> {
  /**
   * Sends the wanted request to the job's client (JobClient.request, which does not send twice a
   * request whose reply is still to come). Called again after every event while nothing answers
   * the inputs on screen.
   */
  readonly ask: (request: Req) => void;
  /**
   * The wait after the wanted request changes before it is asked, in ms (0, the default: at once).
   * The teaching views wait for a slider being dragged to rest.
   */
  readonly settleMs?: number;
  /** Whether to ask at first (the Machined surface view asks only while it is open); default true. */
  readonly open?: boolean;
}

/**
 * One kind of reply kept fresh: what is shown (Freshness) and when to ask the job's client for the
 * inputs on screen. Invariant, after every call: while `shown` is pending and the job is open, the
 * wanted request has been asked of the client (or its settle wait runs), so its reply comes or the
 * client restarts, or gives up and `shown` turns to failed. Pure apart from the settle timer.
 */
export class FreshJob<Rep extends { readonly request: Req }, Req extends PageRequest = Rep['request']> {
  private readonly fresh = new Freshness<Rep, Req>();
  private open: boolean;
  private timer: ReturnType<typeof setTimeout> | null = null;

  constructor(private readonly options: FreshJobOptions<Req>) {
    this.open = options.open ?? true;
  }

  /** The inputs changed: the request they ask (null when invalid); asks it unless it is shown. */
  want(request: Req | null): Shown<Rep> {
    const before = this.fresh.request;
    const changed = request === null ? before !== null : !samePageRequest(request, before);
    this.fresh.want(request);
    const settleMs = this.options.settleMs ?? 0;
    if (changed && settleMs > 0) {
      if (this.timer !== null) clearTimeout(this.timer);
      this.timer = null;
      if (this.fresh.shown.kind === 'pending')
        this.timer = setTimeout(() => {
          this.timer = null;
          this.sync();
        }, settleMs);
    }
    this.sync();
    return this.fresh.shown;
  }

  /** A reply arrived; true when it answers the inputs on screen (and is now shown). */
  receive(reply: Rep): boolean {
    const shown = this.fresh.receive(reply);
    this.sync();
    return shown;
  }

  /**
   * The client gave up on `request` (RestartInfo.request): shown as failed if that is the wanted
   * request (until the inputs change); otherwise the wanted one is asked afresh.
   */
  gaveUp(request: Req | null): void {
    if (samePageRequest(request, this.fresh.request)) this.fresh.fail();
    this.sync();
  }

  /** Asks only while open (the Machined surface view simulates only while it is shown). */
  setOpen(open: boolean): void {
    this.open = open;
    this.sync();
  }

  /**
   * Asks for the wanted request unless it is shown, failed, closed or settling. Every event ends
   * here; the page calls it too after a reply that answers nothing (a cancelled simulation).
   */
  sync(): void {
    if (!this.open || this.timer !== null) return;
    const request = this.fresh.request;
    if (request !== null && this.fresh.shown.kind === 'pending') this.options.ask(request);
  }

  /** The request the inputs ask (null when invalid). */
  get request(): Req | null {
    return this.fresh.request;
  }

  get shown(): Shown<Rep> {
    return this.fresh.shown;
  }
}
