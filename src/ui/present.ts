/**
 * Presentation mode (issue 21, the teacher at a projector): the 3D scene and the open teaching view
 * fill the window, the headline answer above them in large type, no page chrome. `?present=1` or
 * the Present button turns it on; Escape or the same button turns it off, and the URL follows
 * (urlState.ts, as `view=` is kept). The inputs stay one click away: the Inputs button opens the
 * page's own inputs panel over the scene (the same fields, so nothing is duplicated); Escape then
 * closes that panel first, a second Escape leaves presentation mode. The layout itself is CSS
 * (present.css) keyed on the root element's `present` class.
 */
import { FIELDS } from '../core/input/fields';

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

const TOGGLE_TEXT = { on: 'Leave presentation (Esc)', off: 'Present' } as const;
const INPUTS_TEXT = { open: 'Hide inputs', closed: 'Inputs' } as const;

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

  private render(): void {
    this.html.classList.toggle('present', this.on);
    this.toggle.textContent = this.on ? TOGGLE_TEXT.on : TOGGLE_TEXT.off;
    this.inputsButton.hidden = !this.on;
    this.inputsButton.textContent = this.inputsOpen ? INPUTS_TEXT.open : INPUTS_TEXT.closed;
    this.inputsButton.setAttribute('aria-expanded', String(this.inputsOpen));
  }
}
