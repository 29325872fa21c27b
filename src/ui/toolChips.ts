/**
 * The catalogue tools of the unit on screen as one-tap buttons (issue 21: on a phone a select box
 * takes two taps, open and choose; a button one). Each sets D and Rcr together, as the preset box
 * does; the one the tool fields hold is pressed. The metric tools show in mm, the inch tools in inch;
 * the preset box below keeps the whole list. It holds no state: it draws the state it is given.
 */
import { html } from './dom';
import type { CalculatorState } from './state';
import { PRESETS, type Preset, presetOf } from './toolPresets';

export class ToolChips {
  private readonly buttons: readonly { readonly preset: Preset; readonly button: HTMLButtonElement }[];
  private readonly legend: HTMLElement;

  /** Fills `group` (a fieldset) with a button per preset; `onPreset` gets the one tapped. */
  constructor(group: HTMLElement, onPreset: (preset: Preset) => void) {
    this.legend = html('legend', {}, 'Catalogue tools');
    const row = html('div', { class: 'tool-chip-row' });
    this.buttons = PRESETS.map((preset) => {
      const button = html(
        'button',
        { type: 'button', class: 'tool-chip', title: preset.label, 'aria-pressed': 'false' },
        preset.chip,
      );
      button.addEventListener('click', () => onPreset(preset));
      row.append(button);
      return { preset, button };
    });
    group.append(this.legend, row);
  }

  /** Shows the tools of the state's unit, the one its tool fields hold pressed. */
  render(state: CalculatorState): void {
    const held = presetOf(state);
    const legend = `Catalogue tools (${state.unit === 'in' ? 'inch' : 'mm'})`;
    if (this.legend.textContent !== legend) this.legend.textContent = legend;
    for (const { preset, button } of this.buttons) {
      button.hidden = preset.sizedIn !== state.unit;
      const pressed = String(preset === held);
      if (button.getAttribute('aria-pressed') !== pressed) button.setAttribute('aria-pressed', pressed);
    }
  }
}
