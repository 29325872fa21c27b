/**
 * The shop sheet's seam (shopSheet.ts, with the core's sheet and every solver it calls): the button
 * follows the inputs at once (enabled while they make a valid question); the sheet's code loads on
 * the first click, not with the first result.
 */
import type { LengthUnit } from '../core/input/units';
import type { PageRequest } from '../worker/pageProtocol';
import type { ShopSheetPanel } from './shopSheet';

/** Stands in for the ShopSheetPanel until the button is first pressed; then hands it every call. */
export class LazyShopSheet {
  private panel: ShopSheetPanel | null = null;
  private request: PageRequest | null = null;
  private unit: LengthUnit = 'mm';

  constructor(private readonly button: HTMLButtonElement) {
    button.disabled = true;
    const first = () => {
      button.removeEventListener('click', first);
      void import('./shopSheet').then(({ ShopSheetPanel }) => {
        // The panel answers the button's later clicks itself.
        const panel = new ShopSheetPanel(button);
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
