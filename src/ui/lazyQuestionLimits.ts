/**
 * The seam of the sliders' limits beyond a plane or a cylinder (questionLimits.ts, with the doubly
 * curved and three-axis solvers it calls): loaded on the first state that asks such a question,
 * not with the first result. Until it has loaded, the plane's or the cylinder's ranges stand in.
 */
import type { QuestionLimitsOf } from './questionLimits';
import type { CalculatorState } from './state';

/** Hands out questionLimitsOf once loaded; the first doubly curved or three-axis state starts the load. */
export class LazyQuestionLimits {
  private limitsOf: QuestionLimitsOf | null = null;
  private loading = false;

  /** @param loaded Called once the limits have loaded (the sliders are ranged again). */
  constructor(private readonly loaded: () => void) {}

  /** The limits for sliderRanges: null while not loaded (and then loading, if `state` needs them). */
  for(state: CalculatorState): QuestionLimitsOf | null {
    if (this.limitsOf === null && !this.loading && (state.machine === '3axis' || state.surface === 'curved')) {
      this.loading = true;
      void import('./questionLimits').then(({ questionLimitsOf }) => {
        this.limitsOf = questionLimitsOf;
        this.loaded();
      });
    }
    return this.limitsOf;
  }
}
