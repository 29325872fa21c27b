/**
 * Step-through of the paper's 3D procedure (Figure 1) on both flanks: replays the worker's trace
 * in the 3D scene (the section moving along the ring angle gamma, d_s against Rcr, the
 * single-contact section, the candidate points P_hp[i] and the converged P_hp), with a caption
 * per step written here, in the user's unit.
 */
import type { ProcedureKey } from '../../core/procedures';
import { unitSymbol } from '../../core/units';
import type { TraceFrame } from '../../worker/protocol';
import { formatLen, formatRadAsDeg } from '../format';
import { html, type TeachingView, type TeachOk, untilted, type ViewContext } from './common';

export interface TraceDisplay {
  showTraceFrame(frame: TraceFrame | null): void;
}

/** The caption of one frame. */
export function traceCaption(f: TraceFrame, ctx: ViewContext): string {
  const u = unitSymbol(ctx.unit);
  const fine = (mm: number) => `${formatLen(mm, ctx.unit, 'fine')} ${u}`;
  const len = (mm: number) => `${formatLen(mm, ctx.unit)} ${u}`;
  const rcr = ctx.data.forward.cornerRadiusMm;
  const gamma = formatRadAsDeg(f.ringAngleRad);
  const side = f.flank === 'right' ? 'Right flank (+Y)' : 'Left flank (-Y)';
  const width = f.flank === 'right' ? 'wR' : 'wL';
  switch (f.phase) {
    case 'approach':
      return f.approachIndex === 0
        ? `${side}. Step 2 (Eq. 1): start at the section at ring angle gamma = ${gamma}, where the ring is h/2 above its lowest point; d_s = ${fine(f.dsMm ?? 0)} against Rcr = ${len(rcr)}.`
        : `${side}. Steps 6-11: move along the ring towards d_s = Rcr. Section at gamma = ${gamma}: d_s = ${fine(f.dsMm ?? 0)} (Rcr - d_s = ${fine(rcr - (f.dsMm ?? 0))}).`;
    case 'single-contact':
      return f.found
        ? `${side}. Steps 12-14: the section at gamma_scp = ${gamma} touches the h pseudo plane at a single point (d_s = Rcr). It bounds the search range.`
        : `${side}: every section meets the h pseudo plane (no single contact), so the search runs over the whole half ring.`;
    case 'search': {
      const [a, b] = f.rangeRad ?? [f.ringAngleRad, f.ringAngleRad];
      return `${side}. Steps 16-25: ${f.sectionCount} sections from gamma = ${formatRadAsDeg(a)} to ${formatRadAsDeg(b)}; their farthest crossings P_hp[i] with the plane. Best: gamma = ${gamma}, ${f.outMm === null ? 'no crossing' : `${fine(f.outMm)} out from the contact`}; the range narrows to its neighbours.`;
    }
    case 'converged':
      return f.flank === null
        ? closingCaption(ctx.data, ctx, fine)
        : `${side} converged: ${width} = ${fine(f.outMm ?? 0)} at gamma* = ${gamma}.`;
  }
}

function closingCaption(data: TeachOk, ctx: ViewContext, fine: (mm: number) => string): string {
  const r = data.traceResult;
  if (untilted(ctx)) {
    return `Step 26: converged. L/2 = ${fine(r.widthRightMm)} on each flank; the exact solver gives ${fine(r.exactWidthRightMm)}.`;
  }
  return `Step 26: converged on both flanks. wR = ${fine(r.widthRightMm)}, wL = ${fine(r.widthLeftMm)}; the exact solver gives wR = ${fine(r.exactWidthRightMm)}, wL = ${fine(r.exactWidthLeftMm)}.`;
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
  private ctx: ViewContext | null = null;
  private index = 0;
  private timer: ReturnType<typeof setInterval> | null = null;
  private visible = false;

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
        'The scene shows each section visited (purple), the candidate points P_hp[i] of each search pass, and the point found, first on the right flank (+Y), then on the left.',
      ),
      controls,
      ds,
      this.caption,
    );
  }

  update(ctx: ViewContext): void {
    this.pause();
    this.ctx = ctx;
    this.frames = ctx.data.frames;
    if (ctx.data.cylinder !== null) {
      // The paper's procedure searches the torus against the h pseudo plane: a plane's construction.
      this.caption.textContent =
        "The paper's 3D procedure (Figure 1) searches the torus sections against the h pseudo plane, so it is shown for a plane only. On this cylinder the exact solver works on the cylinder itself (see the results and the Cross-feed profile); choose a plane to step through the procedure.";
      this.counter.textContent = '';
      this.meter.value = 0;
      this.meterText.textContent = '';
      this.display.showTraceFrame(null);
      return;
    }
    this.go(Math.min(this.index, Math.max(0, this.frames.length - 1)));
  }

  private go(i: number): void {
    const ctx = this.ctx;
    if (this.frames.length === 0 || ctx === null) return;
    this.index = Math.max(0, Math.min(this.frames.length - 1, i));
    const f = this.frames[this.index] as TraceFrame;
    this.caption.textContent = traceCaption(f, ctx);
    this.counter.textContent = `step ${this.index + 1} of ${this.frames.length}`;
    const rcr = ctx.data.forward.cornerRadiusMm;
    if (f.dsMm === null || rcr === 0) {
      this.meter.value = 0;
      this.meterText.textContent = ' (search: sections between the ends of the range)';
    } else {
      const u = unitSymbol(ctx.unit);
      this.meter.value = Math.max(0, Math.min(2, f.dsMm / rcr + 1));
      this.meterText.textContent = ` d_s = ${formatLen(f.dsMm, ctx.unit, 'fine')} ${u}, Rcr = ${formatLen(rcr, ctx.unit)} ${u}`;
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
