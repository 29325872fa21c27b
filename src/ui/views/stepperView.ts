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
import { localDecimal } from '../i18n/langChoice';
import type { StepperWords } from '../i18n/teachWords';
import { catalogue } from '../i18n/words';
import { STEP_EVENT, type StepAction } from '../present';
import { html, type TeachingView, type TeachOk, untilted, type ViewContext } from './common';
import { DsGauge } from './dsGauge';
import { gaugeMax, groupSteps, type Step, sceneToleranceMm } from './stepGroups';
import { EN_STEPPER } from './stepperWords';
import './stepper.css';

export interface TraceDisplay {
  showTraceFrame(frame: TraceFrame | null): void;
}

/** The step-through's words in the language in force (English: stepperWords.ts). */
function words(): StepperWords {
  return catalogue()?.stepper ?? EN_STEPPER;
}

/** A text with the language in force's decimal sign. */
function local(text: string): string {
  return localDecimal(text, catalogue());
}

/** An angle given in radians as a number of degrees (formatRadAsDeg's), its unit left to the words. */
const degrees = (rad: number) => formatRadAsDeg(rad).replace(/ deg$/, '');

/**
 * The caption of one step, numbered as the counter numbers it ("Step k of N"); the paper's own
 * numbering is quoted as the boxes of its Figure 1, so no second "step" count appears. In `w`'s
 * language, with the point as decimal sign.
 */
export function traceCaption(step: Step, number: number, total: number, ctx: ViewContext, w = EN_STEPPER): string {
  const phase = step.frame.phase;
  const same = step.sameAsPrevious ? ` ${phase === 'approach' ? '' : w.same[phase]}` : '';
  return `${w.step(number, total)}${stepText(step, ctx, w)}${same}`;
}

function stepText(step: Step, ctx: ViewContext, w: StepperWords): string {
  const f = step.frame;
  // Lengths with their unit, µm or thou when small (format.ts).
  const fine = (mm: number) => formatLenUnit(mm, ctx.unit, 'fine');
  const len = (mm: number) => formatLenUnit(mm, ctx.unit);
  const rcr = ctx.data.forward.cornerRadiusMm;
  const gamma = degrees(f.ringAngleRad);
  const side = w.side(f.flank === 'right' ? 'right' : 'left');
  const merged = (what: 'sections' | 'passes') =>
    step.count > 1 ? w.merged(what, step.passFrom, step.passTo, step.count) : '';
  switch (f.phase) {
    case 'approach':
      return f.approachIndex === 0 && step.count === 1
        ? w.start(side, gamma, fine(f.dsMm ?? 0), len(rcr))
        : w.approach(side, merged('sections'), gamma, fine(f.dsMm ?? 0), fine(rcr - (f.dsMm ?? 0)));
    case 'single-contact':
      return f.found ? w.single(side, gamma) : w.noSingle(side);
    case 'search': {
      const [a, b] = f.rangeRad ?? [f.ringAngleRad, f.ringAngleRad];
      return w.search(
        side,
        f.sectionCount,
        degrees(a),
        degrees(b),
        gamma,
        f.outMm === null ? null : fine(f.outMm),
        merged('passes'),
      );
    }
    case 'converged':
      return f.flank === null
        ? closingCaption(ctx.data, ctx, fine, w)
        : w.flankConverged(side, f.flank === 'right' ? 'wR' : 'wL', fine(f.outMm ?? 0), gamma);
  }
}

function closingCaption(data: TeachOk, ctx: ViewContext, fine: (mm: number) => string, w: StepperWords): string {
  const r = data.traceResult;
  if (untilted(ctx)) return w.closingUntilted(fine(r.widthRightMm), fine(r.exactWidthRightMm));
  return w.closingTilted(
    fine(r.widthRightMm),
    fine(r.widthLeftMm),
    fine(r.exactWidthRightMm),
    fine(r.exactWidthLeftMm),
  );
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
  private readonly play = html('button', { type: 'button', 'data-testid': 'stepper-play' }, EN_STEPPER.play);
  /** Said when the system asks for reduced motion: Play then shows one step per press. */
  private readonly motionNote = html(
    'p',
    { class: 'view-note', 'data-testid': 'stepper-motion-note', hidden: '' },
    EN_STEPPER.motion,
  );
  private readonly intro = html('p', { class: 'view-note' }, EN_STEPPER.intro);
  private readonly controls = html('div', {
    class: 'view-tools',
    role: 'group',
    'aria-label': EN_STEPPER.names.controls,
  });
  private readonly first = html('button', { type: 'button', 'data-testid': 'stepper-first' }, '|<');
  private readonly back = html('button', { type: 'button', 'data-testid': 'stepper-back' });
  private readonly forward = html('button', { type: 'button', 'data-testid': 'stepper-forward' });
  private readonly last = html('button', { type: 'button', 'data-testid': 'stepper-last' }, '>|');
  private readonly reducedMotion = window.matchMedia('(prefers-reduced-motion: reduce)');
  private steps: readonly Step[] = [];
  private ctx: ViewContext | null = null;
  private index = 0;
  private timer: ReturnType<typeof setInterval> | null = null;
  private visible = false;

  constructor(private readonly display: TraceDisplay) {
    this.name(words());
    this.first.addEventListener('click', () => this.go(0));
    this.back.addEventListener('click', () => this.go(this.index - 1));
    this.forward.addEventListener('click', () => this.go(this.index + 1));
    this.last.addEventListener('click', () => this.go(this.steps.length - 1));
    this.play.addEventListener('click', () => {
      // Reduced motion: no animation, one step per press.
      if (this.reducedMotion.matches) this.go(this.index >= this.steps.length - 1 ? 0 : this.index + 1);
      else if (this.timer) this.pause();
      else this.start();
    });
    const motion = () => {
      this.motionNote.hidden = !this.reducedMotion.matches;
      this.playWords();
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
    this.controls.append(this.first, this.back, this.play, this.forward, this.last, this.counter);
    this.element.append(this.intro, this.controls, this.motionNote, this.gauge.element, this.caption);
  }

  /** The view's own words (buttons, names, notes) in `w`'s language, and its `lang`. */
  private name(w: StepperWords): void {
    const set = (e: HTMLElement, text: string) => {
      if (e.textContent !== text) e.textContent = text;
    };
    set(this.intro, w.intro);
    set(this.motionNote, w.motion);
    set(this.back, w.back);
    set(this.forward, w.forward);
    this.controls.setAttribute('aria-label', w.names.controls);
    this.first.setAttribute('aria-label', w.names.first);
    this.back.setAttribute('aria-label', w.names.back);
    this.forward.setAttribute('aria-label', w.names.forward);
    this.last.setAttribute('aria-label', w.names.last);
    this.gauge.label(w.gaugeLabel);
    this.playWords();
    const lang = catalogue()?.lang;
    if (lang === undefined) this.element.removeAttribute('lang');
    else this.element.lang = lang;
  }

  /** Play's word: Pause while playing, one step per press under reduced motion. */
  private playWords(): void {
    const w = words();
    this.play.textContent = this.timer !== null ? w.pause : this.reducedMotion.matches ? w.playOne : w.play;
  }

  update(ctx: ViewContext): void {
    this.pause();
    this.ctx = ctx;
    this.name(words());
    const rcr = ctx.data.forward.cornerRadiusMm;
    this.steps = groupSteps(ctx.data.frames, sceneToleranceMm(ctx.data.forward.toolRadiusMm), rcr);
    this.gauge.setScale(
      gaugeMax(rcr > 0 ? ctx.data.frames.flatMap((f) => (f.dsMm === null ? [] : [f.dsMm / rcr])) : []),
      local,
    );
    if (ctx.data.cylinder !== null) {
      // The paper's procedure searches the torus against the h pseudo plane: a plane's construction.
      this.caption.textContent = words().cylinder;
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
    const w = words();
    this.caption.textContent = local(traceCaption(step, this.index + 1, this.steps.length, ctx, w));
    this.counter.textContent = w.counter(this.index + 1, this.steps.length);
    const rcr = ctx.data.forward.cornerRadiusMm;
    if (f.dsMm === null || rcr === 0) {
      this.gauge.show(null, w.noDs);
    } else {
      this.gauge.show(
        f.dsMm / rcr,
        local(
          w.ds(
            formatSignificant(f.dsMm / rcr, { digits: 5 }),
            formatLenUnit(f.dsMm, ctx.unit, 'fine'),
            formatLenUnit(rcr, ctx.unit),
          ),
        ),
      );
    }
    if (this.visible) this.display.showTraceFrame(f);
    if (this.index === this.steps.length - 1) this.pause();
  }

  private start(): void {
    if (this.index >= this.steps.length - 1) this.go(0);
    this.timer = setInterval(() => this.go(this.index + 1), 700);
    this.playWords();
  }

  private pause(): void {
    if (this.timer !== null) clearInterval(this.timer);
    this.timer = null;
    this.playWords();
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
