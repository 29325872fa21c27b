/**
 * Presentation mode (issue 21, the teacher at a projector): the 3D scene and the open teaching view
 * fill the window, the headline answer above them in large type, no page chrome. `?present=1` or
 * the Present button turns it on; Escape or the same button turns it off, and the URL follows
 * (urlState.ts, as `view=` is kept). The inputs stay one click away: the Inputs button opens the
 * page's own inputs panel over the scene (the same fields, so nothing is duplicated); Escape then
 * closes that panel first, a second Escape leaves presentation mode. The layout itself is CSS
 * (present.css) keyed on the root element's `present` class, and so are the buttons' words: each
 * holds both of its words in index.html (in the language in force, by their data-i18n), the CSS
 * shows the one for the mode.
 *
 * A presenter's clicker (issue 28) sends ArrowRight / PageDown / Space (next), ArrowLeft / PageUp /
 * Shift+Space (back), and Home / End: in presentation mode they drive the teaching step-through
 * wherever focus is (a button, a tab, the scene, nothing), before any other handler sees them (a
 * focused button would otherwise take Space, the tabs the arrows). A press while another view is
 * open first opens the step-through (the audience sees it), the next ones step. Decided: where
 * focus edits a value, the keys keep their own meaning: a text field, a select, an editable text,
 * and every control of the opened Inputs panel (its radios and sliders take arrows); with Ctrl,
 * Alt or Meta they are the browser's.
 */
import { FIELDS } from '../core/input/fields';

/** What a clicker's key asks of the step-through. */
export type StepAction = 'next' | 'back' | 'first' | 'last';

/** The event the step-through (views/stepperView.ts) takes its clicker steps from, on the document. */
export const STEP_EVENT = 'path-interval:step';

/** The clicker's keys (KeyboardEvent.key; Space is ' ') and what each asks. */
const CLICKER_KEYS: Readonly<Record<string, StepAction>> = {
  ArrowRight: 'next',
  PageDown: 'next',
  ' ': 'next',
  ArrowLeft: 'back',
  PageUp: 'back',
  Home: 'first',
  End: 'last',
};

/** Input types whose keys type text (or pick a value by keys): these keep the clicker's keys. */
const TEXT_INPUTS = new Set(['text', 'search', 'number', 'email', 'url', 'tel', 'password', 'date', 'time']);

/** True when a key pressed on `target` edits a value there (see the module's comment). */
function editsValue(target: EventTarget | null): boolean {
  if (!(target instanceof HTMLElement)) return false;
  if (target.isContentEditable || target instanceof HTMLTextAreaElement || target instanceof HTMLSelectElement)
    return true;
  if (target instanceof HTMLInputElement && TEXT_INPUTS.has(target.type)) return true;
  return target.closest('.controls') !== null;
}

/** The step a key event asks in presentation mode, or null when the key is not the clicker's. */
export function clickerStep(e: KeyboardEvent): StepAction | null {
  if (e.ctrlKey || e.altKey || e.metaKey || editsValue(e.target)) return null;
  const action = CLICKER_KEYS[e.key] ?? null;
  return action === 'next' && e.key === ' ' && e.shiftKey ? 'back' : action;
}

/** What the link's `present=` asks: on (`1`), off (absent), or off with a notice (anything else). */
export interface PresentChoice {
  readonly on: boolean;
  readonly notice: string | null;
}

/** Reads `present=` as parseUrl gives it (null when absent). */
export function parsePresent(text: string | null): PresentChoice {
  const { url, values } = FIELDS.present;
  if (text === null) return { on: false, notice: null };
  if ((values as readonly string[]).includes(text)) return { on: true, notice: null };
  return {
    on: false,
    notice: `${url}="${text.slice(0, 20)}" is not ${values.join(' or ')}; presentation mode is off.`,
  };
}

/** The page's side of presentation mode: told when it starts or ends (to write the URL). */
export interface PresentHost {
  changed(on: boolean): void;
}

export class PresentMode {
  private on = false;
  private readonly html = document.documentElement;

  constructor(
    private readonly toggle: HTMLButtonElement,
    private readonly inputsButton: HTMLButtonElement,
    private readonly host: PresentHost,
  ) {
    toggle.addEventListener('click', () => this.set(!this.on));
    inputsButton.addEventListener('click', () => this.setInputs(!this.inputsOpen));
    document.addEventListener('keydown', (e) => this.escape(e));
    // Capture, on the window: before a focused button, tab or view sees the clicker's keys.
    window.addEventListener('keydown', (e) => this.clicker(e), true);
    this.render();
  }

  /** True while presentation mode is on. */
  get active(): boolean {
    return this.on;
  }

  /** Turns presentation mode on or off (the inputs panel starts closed each time). */
  set(on: boolean): void {
    if (on === this.on) return;
    this.on = on;
    this.html.classList.remove('present-inputs');
    this.render();
    this.host.changed(on);
  }

  private get inputsOpen(): boolean {
    return this.html.classList.contains('present-inputs');
  }

  private setInputs(open: boolean): void {
    this.html.classList.toggle('present-inputs', open);
    this.render();
  }

  /** Escape closes the inputs panel if open (focus back on its button), else leaves the mode. */
  private escape(e: KeyboardEvent): void {
    if (e.key !== 'Escape' || !this.on || e.defaultPrevented) return;
    e.preventDefault();
    if (this.inputsOpen) {
      this.setInputs(false);
      this.inputsButton.focus();
      return;
    }
    this.set(false);
    this.toggle.focus();
  }

  /** A clicker key in presentation mode: opens the step-through, or asks it to step (STEP_EVENT). */
  private clicker(e: KeyboardEvent): void {
    if (!this.on) return;
    const action = clickerStep(e);
    const tab = document.querySelector<HTMLElement>('[role="tab"][data-view="stepper"]');
    if (action === null || tab === null) return;
    e.preventDefault();
    e.stopPropagation();
    if (tab.getAttribute('aria-selected') !== 'true') tab.click();
    else document.dispatchEvent(new CustomEvent<StepAction>(STEP_EVENT, { detail: action }));
  }

  private render(): void {
    this.html.classList.toggle('present', this.on);
    this.inputsButton.hidden = !this.on;
    this.inputsButton.setAttribute('aria-expanded', String(this.inputsOpen));
  }
}
