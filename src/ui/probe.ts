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
  /** The same, from the time stamp of the pointer event behind each input (when the browser got it). */
  pointerLatencies(): number[];
  firstResultMs(): number | null;
  activeView(): string | null;
  workerStarts(): number;
}

export function startWithProbe(root: HTMLElement): void {
  const latencies: number[] = [];
  const pointerLatencies: number[] = [];
  let pendingInputAt: number | null = null;
  let pendingPointerAt: number | null = null;
  /** Time stamp of the latest pointer event (raw updates included): where a drag's input began. */
  let pointerAt: number | null = null;
  const onPointer = (e: Event) => {
    pointerAt = e.timeStamp;
  };
  for (const type of ['pointerdown', 'pointermove', 'pointerrawupdate']) window.addEventListener(type, onPointer, true);
  let firstResultMs: number | null = null;
  // Capture phase: the time of the event, before the page's own handler runs.
  window.addEventListener(
    'input',
    () => {
      pendingInputAt = performance.now();
      // A pointer event within the last 100 ms caused this input (keys leave none).
      pendingPointerAt = pointerAt !== null && pendingInputAt - pointerAt < 100 ? pointerAt : null;
    },
    true,
  );
  window.addEventListener(
    'change',
    () => {
      pendingInputAt = performance.now();
      pendingPointerAt = null;
    },
    true,
  );
  const observer: AppObserver = {
    resultShown() {
      firstResultMs ??= performance.now();
    },
    frame(current) {
      if (current && pendingInputAt !== null) {
        const now = performance.now();
        latencies.push(now - pendingInputAt);
        if (pendingPointerAt !== null) pointerLatencies.push(now - pendingPointerAt);
        pendingInputAt = null;
        pendingPointerAt = null;
      }
    },
  };
  const app = new CalculatorApp(root, observer);
  const d = app.diagnostics;
  const probe: Probe = {
    frames: d.frames,
    softwareRendering: d.softwareRendering,
    latencies: () => [...latencies],
    pointerLatencies: () => [...pointerLatencies],
    firstResultMs: () => firstResultMs,
    activeView: d.activeView,
    workerStarts: d.workerStarts,
  };
  (window as unknown as { __pathInterval: Probe }).__pathInterval = probe;
}
