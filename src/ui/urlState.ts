/**
 * The address bar holds the state: every change replaces the URL (no history entries), and the
 * embedded page's "Open full calculator" link carries the same state without `embed`.
 * Chromium ignores replaceState beyond about 200 calls in 10 s, which one fast slider drag or a
 * burst of events can reach, and the URL would then keep an old state: writes go at once up to
 * WRITES_PER_SECOND, and beyond that the last state is written as soon as the budget allows.
 */
import { type CalculatorState, toSearch } from './state';

const WRITES_PER_SECOND = 15;

export class UrlState {
  private pending: CalculatorState | null = null;
  private timer: ReturnType<typeof setTimeout> | null = null;
  /** Times of the writes in the last second. */
  private recent: number[] = [];

  constructor(
    private readonly extra: Readonly<Record<string, string>>,
    private readonly fullLink: HTMLAnchorElement | null,
  ) {}

  write(state: CalculatorState): void {
    this.pending = state;
    if (this.timer !== null) return; // a write is already waiting for the budget
    const now = performance.now();
    this.recent = this.recent.filter((t) => now - t < 1000);
    if (this.recent.length < WRITES_PER_SECOND) {
      this.recent.push(now);
      this.flush();
      return;
    }
    const wait = 1000 - (now - (this.recent[0] as number));
    this.timer = setTimeout(() => {
      this.timer = null;
      if (this.pending !== null) this.write(this.pending);
    }, wait);
  }

  private flush(): void {
    const state = this.pending;
    this.pending = null;
    if (state === null) return;
    window.history.replaceState(null, '', toSearch(state, this.extra) + window.location.hash);
    if (this.fullLink) this.fullLink.href = toSearch(state);
  }
}
