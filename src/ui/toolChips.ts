/**
 * The catalogue tools as one-tap buttons (issue 21: on a phone a select box takes two taps, open and
 * choose; a button one). Each sets D and Rcr together, as the preset box does; the one the tool
 * fields hold is pressed. Each tool is named in its own unit (metric tools in mm, inch tools in
 * inch): the tools of the page's unit show, and on a first visit (no unit chosen yet on this
 * device, {@link ToolChips.offerBothUnits}) those of the other unit too, after them, until a unit is
 * chosen (the unit switch, or a tool); a tap on one of those also takes the page to its unit, in the same tap (issue 28: an inch
 * shop's first job without a tap on the unit switch). The preset box below keeps the whole list. It
 * holds no state beyond that offer: it draws the state it is given.
 */
import { html } from './dom';
import type { CalculatorState } from './state';
import type { Unit } from './stateTypes';
import { PRESETS, type Preset, presetOf } from './toolPresets';

export class ToolChips {
  private readonly buttons: readonly { readonly preset: Preset; readonly button: HTMLButtonElement }[];
  private readonly legend: HTMLElement;
  /** Whether the other unit's tools show too (a first visit). */
  private bothUnits = false;
  /** The unit last drawn (null before the first): a tap on a tool of another unit takes the page to the tool's. */
  private unit: Unit | null = null;

  /**
   * Fills `group` (a fieldset) with a button per preset; `onPreset` gets the one tapped, and the
   * tool's unit when it is not the page's (the page then switches to it).
   */
  constructor(group: HTMLElement, onPreset: (preset: Preset, unit?: Unit) => void) {
    this.legend = html('legend', {}, 'Catalogue tools');
    const row = html('div', { class: 'tool-chip-row' });
    this.buttons = PRESETS.map((preset) => {
      const button = html(
        'button',
        { type: 'button', class: 'tool-chip', title: preset.label, 'aria-pressed': 'false' },
        preset.chip,
      );
      button.addEventListener('click', () => {
        // A tool chosen is a unit chosen: its unit's tools only from now on.
        this.bothUnits = false;
        onPreset(preset, preset.sizedIn === this.unit ? undefined : preset.sizedIn);
      });
      row.append(button);
      return { preset, button };
    });
    group.append(this.legend, row);
  }

  /** Shows the other unit's tools too (each in its own unit), until the page's unit changes (or called with false). */
  offerBothUnits(on: boolean): void {
    this.bothUnits = on;
  }

  /** Shows the tools of the state's unit (and of the other, when offered), the one its tool fields hold pressed. */
  render(state: CalculatorState): void {
    // A unit chosen (the switch, or a tool of the other unit): its tools only from now on.
    if (this.unit !== null && state.unit !== this.unit) this.bothUnits = false;
    this.unit = state.unit;
    const held = presetOf(state);
    const legend = `Catalogue tools (${this.bothUnits ? 'mm, inch' : state.unit === 'in' ? 'inch' : 'mm'})`;
    if (this.legend.textContent !== legend) this.legend.textContent = legend;
    for (const { preset, button } of this.buttons) {
      button.hidden = preset.sizedIn !== state.unit && !this.bothUnits;
      const pressed = String(preset === held);
      if (button.getAttribute('aria-pressed') !== pressed) button.setAttribute('aria-pressed', pressed);
    }
  }
}
