/**
 * Step-through of the paper's 3D procedure (Figure 1): replays the worker's trace in the 3D
 * scene (the section moving along the ring angle gamma, d_s against Rcr, the single-contact
 * section, the candidate points P_hp[i] and the converged P_hp), with a caption per step.
 */
import type { ProcedureKey, TraceFrame } from '../../worker/protocol';
import { html, type TeachingView, type ViewContext } from './common';

export interface TraceDisplay {
  showTraceFrame(frame: TraceFrame | null): void;
}

export class StepperView implements TeachingView {
  readonly id = 'stepper';
  readonly title = '3D procedure, step by step';
  readonly element = html('div', { class: 'view-stepper', 'data-testid': 'stepper' });
  private readonly caption = html('p', {
    class: 'stepper-caption',
    'data-testid': 'stepper-caption',
    'aria-live': 'polite',
  });
  private readonly counter = html('span', { class: 'stepper-counter', 'data-testid': 'stepper-counter' });
  private readonly meter = html('meter', {
    min: '0',
    max: '2',
    'aria-label': 'd_s relative to Rcr',
    'data-testid': 'stepper-ds',
  });
  private readonly meterText = html('span', { class: 'meter-text' });
  private readonly play = html('button', { type: 'button', 'data-testid': 'stepper-play' }, 'Play');
  private frames: readonly TraceFrame[] = [];
  private index = 0;
  private timer: ReturnType<typeof setInterval> | null = null;
  private visible = false;
  private rcr = 1;

  constructor(private readonly display: TraceDisplay) {
    const controls = html('div', { class: 'view-tools', role: 'group', 'aria-label': 'Step controls' });
    const first = html('button', { type: 'button', 'data-testid': 'stepper-first', 'aria-label': 'First step' }, '|<');
    const back = html('button', { type: 'button', 'data-testid': 'stepper-back', 'aria-label': 'Step back' }, '< Back');
    const forward = html(
      'button',
      { type: 'button', 'data-testid': 'stepper-forward', 'aria-label': 'Step forward' },
      'Forward >',
    );
    const last = html('button', { type: 'button', 'data-testid': 'stepper-last', 'aria-label': 'Last step' }, '>|');
    first.addEventListener('click', () => this.go(0));
    back.addEventListener('click', () => this.go(this.index - 1));
    forward.addEventListener('click', () => this.go(this.index + 1));
    last.addEventListener('click', () => this.go(this.frames.length - 1));
    this.play.addEventListener('click', () => (this.timer ? this.pause() : this.start()));
    controls.append(first, back, this.play, forward, last, this.counter);
    const ds = html('div', { class: 'stepper-ds' });
    ds.append(html('span', {}, 'd_s / Rcr: '), this.meter, this.meterText);
    this.element.append(
      html(
        'p',
        { class: 'view-note' },
        'The scene shows each section visited (purple), the candidate points P_hp[i] of each search pass, and the point found.',
      ),
      controls,
      ds,
      this.caption,
    );
  }

  update(ctx: ViewContext): void {
    this.pause();
    this.frames = ctx.reply.teaching?.frames ?? [];
    this.rcr = ctx.Rcr;
    this.go(Math.min(this.index, Math.max(0, this.frames.length - 1)));
  }

  private go(i: number): void {
    if (this.frames.length === 0) return;
    this.index = Math.max(0, Math.min(this.frames.length - 1, i));
    const f = this.frames[this.index] as TraceFrame;
    this.caption.textContent = f.caption;
    this.counter.textContent = `step ${this.index + 1} of ${this.frames.length}`;
    if (f.dsMm === null || this.rcr === 0) {
      this.meter.value = 0;
      this.meterText.textContent = ' (search: sections between the ends of the range)';
    } else {
      this.meter.value = Math.max(0, Math.min(2, f.dsMm / this.rcr + 1));
      this.meterText.textContent = ` d_s = ${f.dsMm.toFixed(4)} mm, Rcr = ${this.rcr} mm`;
    }
    if (this.visible) this.display.showTraceFrame(f);
    if (this.index === this.frames.length - 1) this.pause();
  }

  private start(): void {
    if (this.index >= this.frames.length - 1) this.go(0);
    this.play.textContent = 'Pause';
    this.timer = setInterval(() => this.go(this.index + 1), 700);
  }

  private pause(): void {
    if (this.timer !== null) clearInterval(this.timer);
    this.timer = null;
    this.play.textContent = 'Play';
  }

  setVisible(visible: boolean): void {
    this.visible = visible;
    if (!visible) this.pause();
    this.display.showTraceFrame(visible ? (this.frames[this.index] ?? null) : null);
  }

  highlight(_key: ProcedureKey | null): void {
    // The stepper shows the exact procedure only.
  }
}
