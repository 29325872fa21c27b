/**
 * The seam of a panel a button opens (the shop sheet, shopSheet.ts; the lookup table's download,
 * lookupDownload.ts): the button follows the inputs at once (enabled while they make a valid
 * question); the panel's code loads on the first click, not with the first result.
 */
import type { LengthUnit } from '../core/input/units';
import type { PageRequest } from '../worker/pageProtocol';

/** A panel behind a button: it follows the inputs on screen and opens on a press. */
export interface ButtonPanel {
  want(request: PageRequest | null, unit: LengthUnit): void;
  /** What the first press asks (the panel answers the button's later presses itself). */
  open(): void;
}

/** Stands in for a button's panel until the button is first pressed; then hands it every call. */
export class LazyButton {
  private panel: ButtonPanel | null = null;
  private request: PageRequest | null = null;
  private unit: LengthUnit = 'mm';

  /** `load`: the panel's code, imported on the first press, making the panel of `button`. */
  constructor(
    private readonly button: HTMLButtonElement,
    load: (button: HTMLButtonElement) => Promise<ButtonPanel>,
  ) {
    button.disabled = true;
    const first = () => {
      button.removeEventListener('click', first);
      void load(button).then((panel) => {
        this.panel = panel;
        panel.want(this.request, this.unit);
        panel.open();
      });
    };
    button.addEventListener('click', first);
  }

  /** The inputs on screen changed: the question they ask (null: invalid or being typed), and the unit. */
  want(request: PageRequest | null, unit: LengthUnit): void {
    this.request = request;
    this.unit = unit;
    if (this.panel !== null) this.panel.want(request, unit);
    else this.button.disabled = request === null;
  }
}
