/**
 * Step-through of the paper's 3D procedure (Figure 1) on both flanks: replays the worker's trace
 * in the 3D scene (the section moving along the ring angle gamma, d_s against Rcr, the
 * single-contact section, the candidate points P_hp[i] and the converged P_hp), with a caption
 * per step written here, in the user's unit.
 */

import { formatSignificant } from '../../core/input/units';
import type { ProcedureKey } from '../../core/procedures/procedures';
import type { TraceFrame } from '../../worker/protocol';
import { formatLenUnit, formatRadAsDeg } from '../format';
import { STEP_EVENT, type StepAction } from '../present';
import { html, type TeachingView, type TeachOk, untilted, type ViewContext } from './common';
import { DsGauge } from './dsGauge';
import { gaugeMax, groupSteps, type Step, sceneToleranceMm } from './stepGroups';
import './stepper.css';

export interface TraceDisplay {
  showTraceFrame(frame: TraceFrame | null): void;
}

/**
 * The caption of one step, numbered as the counter numbers it ("Step k of N"); the paper's own
 * numbering is quoted as the boxes of its Figure 1, so no second "step" count appears.
 */
export function traceCaption(step: Step, number: number, total: number, ctx: ViewContext): string {
  return `Step ${number} of ${total}. ${stepText(step, ctx)}${step.sameAsPrevious ? ` ${SAME_AS_PREVIOUS[step.frame.phase]}` : ''}`;
}

/** Why a step shows the previous step's section and point again. */
const SAME_AS_PREVIOUS: Record<TraceFrame['phase'], string> = {
  approach: '',
  'single-contact':
    'The scene hardly changes: the last approach section already lies on the single-contact one; this step confirms it (d_s = Rcr) and marks its point.',
  search: 'The scene hardly changes: the search starts from the single-contact point.',
  converged:
    'The scene shows the last search pass without its candidates: the search has stopped moving, so its best point is the answer for this flank.',
};

function stepText(step: Step, ctx: ViewContext): string {
  const f = step.frame;
  // Lengths with their unit, µm or thou when small (format.ts).
  const fine = (mm: number) => formatLenUnit(mm, ctx.unit, 'fine');
  const len = (mm: number) => formatLenUnit(mm, ctx.unit);
  const rcr = ctx.data.forward.cornerRadiusMm;
  const gamma = formatRadAsDeg(f.ringAngleRad);
  const side = f.flank === 'right' ? 'Right flank (+Y)' : 'Left flank (-Y)';
  const width = f.flank === 'right' ? 'wR' : 'wL';
  const merged = (what: string, why: string) =>
    step.count > 1 ? ` ${what} ${step.passFrom} to ${step.passTo} shown as one (${step.count} ${why}).` : '';
  switch (f.phase) {
    case 'approach':
      return f.approachIndex === 0 && step.count === 1
        ? `${side}. Fig. 1, box 2 (Eq. 1): start at the section at ring angle gamma = ${gamma}, where the ring is h/2 above its lowest point; d_s = ${fine(f.dsMm ?? 0)} against Rcr = ${len(rcr)}.`
        : `${side}. Fig. 1, boxes 6-11: move along the ring towards d_s = Rcr.${merged('Sections', 'sections that the scene and the gauge show alike')} Section at gamma = ${gamma}: d_s = ${fine(f.dsMm ?? 0)} (Rcr - d_s = ${fine(rcr - (f.dsMm ?? 0))}).`;
    case 'single-contact':
      return f.found
        ? `${side}. Fig. 1, boxes 12-14: the section at gamma_scp = ${gamma} touches the h pseudo plane at a single point (d_s = Rcr). It bounds the search range.`
        : `${side}: every section meets the h pseudo plane (no single contact), so the search runs over the whole half ring.`;
    case 'search': {
      const [a, b] = f.rangeRad ?? [f.ringAngleRad, f.ringAngleRad];
      return `${side}. Fig. 1, boxes 16-25: ${f.sectionCount} sections from gamma = ${formatRadAsDeg(a)} to ${formatRadAsDeg(b)}; their farthest crossings P_hp[i] with the plane. Best: gamma = ${gamma}, ${f.outMm === null ? 'no crossing' : `${fine(f.outMm)} out from the contact`}; the range narrows to its neighbours.${merged('Search passes', 'passes: each narrows the range further, by less than the scene can show')}`;
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
    return `Fig. 1, box 26: converged. L/2 = ${fine(r.widthRightMm)} on each flank; the exact solver gives ${fine(r.exactWidthRightMm)}.`;
  }
  return `Fig. 1, box 26: converged on both flanks. wR = ${fine(r.widthRightMm)}, wL = ${fine(r.widthLeftMm)}; the exact solver gives wR = ${fine(r.exactWidthRightMm)}, wL = ${fine(r.exactWidthLeftMm)}.`;
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
  private readonly gauge = new DsGauge();
  private readonly play = html('button', { type: 'button', 'data-testid': 'stepper-play' }, 'Play');
  /** Said when the system asks for reduced motion: Play then shows one step per press. */
  private readonly motionNote = html(
    'p',
    { class: 'view-note', 'data-testid': 'stepper-motion-note', hidden: '' },
    'Reduced motion is on: Play shows the next step on each press instead of animating the steps.',
  );
  private readonly reducedMotion = window.matchMedia('(prefers-reduced-motion: reduce)');
  private steps: readonly Step[] = [];
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
    last.addEventListener('click', () => this.go(this.steps.length - 1));
    this.play.addEventListener('click', () => {
      // Reduced motion: no animation, one step per press.
      if (this.reducedMotion.matches) this.go(this.index >= this.steps.length - 1 ? 0 : this.index + 1);
      else if (this.timer) this.pause();
      else this.start();
    });
    const motion = () => {
      this.motionNote.hidden = !this.reducedMotion.matches;
      this.play.textContent = this.reducedMotion.matches ? 'Play (one step)' : 'Play';
      if (this.reducedMotion.matches) this.pause();
    };
    // A presenter's clicker (present.ts): one step per press, the playback paused.
    document.addEventListener(STEP_EVENT, (e) => {
      if (!this.visible) return;
      const action = (e as CustomEvent<StepAction>).detail;
      this.pause();
      const last = this.steps.length - 1;
      this.go(action === 'first' ? 0 : action === 'last' ? last : action === 'back' ? this.index - 1 : this.index + 1);
    });
    this.reducedMotion.addEventListener('change', motion);
    motion();
    controls.append(first, back, this.play, forward, last, this.counter);
    this.element.append(
      html(
        'p',
        { class: 'view-note' },
        'The scene shows each section visited (purple), the candidate points P_hp[i] of each search pass, and the point found, first on the right flank (+Y), then on the left. Steps that would look the same are shown as one.',
      ),
      controls,
      this.motionNote,
      this.gauge.element,
      this.caption,
    );
  }

  update(ctx: ViewContext): void {
    this.pause();
    this.ctx = ctx;
    const rcr = ctx.data.forward.cornerRadiusMm;
    this.steps = groupSteps(ctx.data.frames, sceneToleranceMm(ctx.data.forward.toolRadiusMm), rcr);
    this.gauge.setScale(
      gaugeMax(rcr > 0 ? ctx.data.frames.flatMap((f) => (f.dsMm === null ? [] : [f.dsMm / rcr])) : []),
    );
    if (ctx.data.cylinder !== null) {
      // The paper's procedure searches the torus against the h pseudo plane: a plane's construction.
      this.caption.textContent =
        "The paper's 3D procedure (Figure 1) searches the torus sections against the h pseudo plane, so it is shown for a plane only. On this cylinder the exact solver works on the cylinder itself (see the results and the Cross-feed profile); choose a plane to step through the procedure.";
      this.counter.textContent = '';
      this.gauge.show(null, '');
      this.display.showTraceFrame(null);
      return;
    }
    this.go(Math.min(this.index, Math.max(0, this.steps.length - 1)));
  }

  private go(i: number): void {
    const ctx = this.ctx;
    if (this.steps.length === 0 || ctx === null) return;
    this.index = Math.max(0, Math.min(this.steps.length - 1, i));
    const step = this.steps[this.index] as Step;
    const f = step.frame;
    this.caption.textContent = traceCaption(step, this.index + 1, this.steps.length, ctx);
    this.counter.textContent = `step ${this.index + 1} of ${this.steps.length}`;
    const rcr = ctx.data.forward.cornerRadiusMm;
    if (f.dsMm === null || rcr === 0) {
      this.gauge.show(null, ' no d_s here (search: sections between the ends of the range)');
    } else {
      this.gauge.show(
        f.dsMm / rcr,
        ` ${formatSignificant(f.dsMm / rcr, { digits: 5 })}: d_s = ${formatLenUnit(f.dsMm, ctx.unit, 'fine')}, Rcr = ${formatLenUnit(rcr, ctx.unit)}`,
      );
    }
    if (this.visible) this.display.showTraceFrame(f);
    if (this.index === this.steps.length - 1) this.pause();
  }

  private start(): void {
    if (this.index >= this.steps.length - 1) this.go(0);
    this.play.textContent = 'Pause';
    this.timer = setInterval(() => this.go(this.index + 1), 700);
  }

  private pause(): void {
    if (this.timer !== null) clearInterval(this.timer);
    this.timer = null;
    this.play.textContent = this.reducedMotion.matches ? 'Play (one step)' : 'Play';
  }

  setVisible(visible: boolean): void {
    this.visible = visible;
    if (!visible) this.pause();
    this.display.showTraceFrame(visible ? (this.steps[this.index]?.frame ?? null) : null);
  }

  highlight(_key: ProcedureKey | null): void {
    // The stepper shows the exact procedure only.
  }
}
