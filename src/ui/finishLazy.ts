/**
 * The finish box's seam (finishPanel.ts, with its worker client): hidden while no tooth or feed is
 * given; its code loads with the first finish question, not with the first result.
 */
import type { FinishField } from '../core/finish/finishInput';
import { FINISH_FIELD_IDS } from '../core/input/fields';
import type { FinishFieldMessage, FinishValue } from '../worker/finishProtocol';
import type { PageReply } from '../worker/pageProtocol';
import { finishClient } from '../worker/workers';
import { FINISH_KEYS, finishGiven, finishKeyOff } from './finishFields';
import type { FinishPanel } from './finishPanel';
import type { FinishInputs } from './finishRequest';
import { type CalculatorState, type FieldKey, fieldInMm } from './state';

/** The core's finish fields (the registry's ids are the core's names), in the order of FINISH_KEYS. */
const FINISH_FIELDS = FINISH_FIELD_IDS as readonly FinishField[];

/** The finish fields of a state (written lengths already plain): in mm and degrees, and as typed. */
export function finishInputs(state: CalculatorState): FinishInputs {
  const values = {} as Record<FinishField, FinishValue>;
  const typed = {} as Record<FinishField, string>;
  FINISH_FIELDS.forEach((field, i) => {
    const key = FINISH_KEYS[i] as (typeof FINISH_KEYS)[number];
    // The feed rate and spindle speed while fz is typed: off (finishFields.ts finishKeyOff).
    const text = finishKeyOff(state, key) ? '' : state.fields[key].trim();
    typed[field] = text;
    values[field] = text === '' ? undefined : fieldInMm(state, key);
  });
  // With a target Sa the feed is its answer: the finish box asks nothing (the target-Sa box answers).
  const saTarget = state.mode === 'forward' && state.target === 'sa';
  return { given: finishGiven(state) && !saTarget, values, typed, unit: state.unit };
}

/** The worker's messages on finish fields, by the fields' page keys. */
export function finishKeyMessages(errors: readonly FinishFieldMessage[]): ReadonlyMap<FieldKey, string> {
  return new Map(errors.map((e) => [FINISH_KEYS[FINISH_FIELDS.indexOf(e.field)] as FieldKey, e.message]));
}

/** Stands in for the FinishPanel until teeth or a feed are first given; then hands it every call. */
export class LazyFinish {
  private panel: FinishPanel | null = null;
  private loading = false;
  private last: { inputs: FinishInputs; reply: PageReply | null } | null = null;

  constructor(
    private readonly box: HTMLElement | null,
    /** "use the balanced feed": the fields it sets (fz in mm, or the feed rate F in mm/min). */
    private readonly onFeed: (fields: { readonly fz: number } | { readonly F: number }) => void,
    /** The worker's messages on the finish fields, by page key (empty: none), for the fields. */
    private readonly onFieldErrors: (messages: ReadonlyMap<FieldKey, string>) => void = () => {},
  ) {}

  /** The inputs on screen, and the answer to them (null while none is, or while typing). */
  show(state: CalculatorState, reply: PageReply | null): void {
    const inputs = finishInputs(state);
    this.last = { inputs, reply };
    const box = this.box;
    if (this.panel !== null) this.panel.show(inputs, reply);
    else if (box !== null && inputs.given && !this.loading) {
      this.loading = true;
      void import('./finishPanel').then(({ FinishPanel }) => {
        this.panel = new FinishPanel(box, this.onFeed, finishClient, (errors) =>
          this.onFieldErrors(finishKeyMessages(errors)),
        );
        if (this.last !== null) this.panel.show(this.last.inputs, this.last.reply);
      });
    }
  }
}
