/**
 * The address bar holds the state: the URL is replaced (no history entries) once the inputs
 * settle, URL_SETTLE_MS after the last change, and the embedded page's "Open full calculator" link
 * carries the same state without `embed` at once.
 * Why not at every change: replacing the URL costs the page 10-15 ms in Chromium (measured while
 * dragging a slider), on the path from an input to its answer; and Chromium ignores replaceState
 * beyond about 200 calls in 10 s, which one fast drag would reach, leaving an old state in the URL.
 * At most one write per settle time stays far below that. A page being hidden (closed, switched
 * away from) writes the waiting state at once.
 */
import { type CalculatorState, toSearch } from './state';

/** Quiet time after the last change before the URL is written (ms). */
export const URL_SETTLE_MS = 200;

export class UrlState {
  private pending: CalculatorState | null = null;
  /** The state the URL holds or is about to hold (null before the first write). */
  private latest: CalculatorState | null = null;
  private timer: ReturnType<typeof setTimeout> | null = null;
  /** The page's settings beside the state (`view`, `theme`, `present`...): a copy, changed by `setExtra`. */
  private readonly extra: Record<string, string>;

  constructor(
    extra: Readonly<Record<string, string>>,
    private readonly fullLink: HTMLAnchorElement | null,
  ) {
    this.extra = { ...extra };
    document.addEventListener('visibilitychange', () => {
      if (document.visibilityState === 'hidden') this.flush();
    });
  }

  write(state: CalculatorState): void {
    this.pending = state;
    this.latest = state;
    if (this.fullLink) this.fullLink.href = toSearch(state);
    if (this.timer !== null) clearTimeout(this.timer);
    this.timer = setTimeout(() => this.flush(), URL_SETTLE_MS);
  }

  /**
   * Sets (or, with null, removes) a page setting of the URL, such as `present=1`, and writes the
   * URL at once: a setting changes on a click or a key, not at every step of a drag.
   */
  setExtra(name: string, value: string | null): void {
    if (value === null) delete this.extra[name];
    else this.extra[name] = value;
    if (this.latest === null) return;
    this.pending = this.latest;
    this.flush();
  }

  private flush(): void {
    if (this.timer !== null) clearTimeout(this.timer);
    this.timer = null;
    const state = this.pending;
    this.pending = null;
    if (state === null) return;
    window.history.replaceState(null, '', toSearch(state, this.extra) + window.location.hash);
  }
}
