/**
 * Test and benchmark probe, built only into the instrumented site (`vite build --mode e2e`, which
 * the browser tests and `npm run bench:web` use); the production build contains none of it.
 * Exposes `window.__pathInterval`: frames drawn, software rendering, input-to-frame latencies
 * (from each input event to the first frame that answers it), the time of the first result, the
 * active teaching view and the solver workers started.
 */
import { type AppObserver, CalculatorApp } from './app';

export interface Probe {
  frames(): number;
  softwareRendering(): boolean;
  latencies(): number[];
  firstResultMs(): number | null;
  activeView(): string | null;
  workerStarts(): number;
}

export function startWithProbe(root: HTMLElement): void {
  const latencies: number[] = [];
  let pendingInputAt: number | null = null;
  let firstResultMs: number | null = null;
  // Capture phase: the time of the event, before the page's own handler runs.
  window.addEventListener('input', () => (pendingInputAt = performance.now()), true);
  window.addEventListener('change', () => (pendingInputAt = performance.now()), true);
  const observer: AppObserver = {
    resultShown() {
      firstResultMs ??= performance.now();
    },
    frame(current) {
      if (current && pendingInputAt !== null) {
        latencies.push(performance.now() - pendingInputAt);
        pendingInputAt = null;
      }
    },
  };
  const app = new CalculatorApp(root, observer);
  const d = app.diagnostics;
  const probe: Probe = {
    frames: d.frames,
    softwareRendering: d.softwareRendering,
    latencies: () => [...latencies],
    firstResultMs: () => firstResultMs,
    activeView: d.activeView,
    workerStarts: d.workerStarts,
  };
  (window as unknown as { __pathInterval: Probe }).__pathInterval = probe;
}
