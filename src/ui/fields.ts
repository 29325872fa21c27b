/**
 * The input side of the page: a slider paired with a number field for each value, the switches
 * (mode, unit, pass pattern) and the tool presets. It reports what the user did and draws the
 * state it is given (values, ranges in the user's unit, messages); it holds no state itself.
 */

import { FIELD_LABELS, FIELDS, fieldOfPageKey } from '../core/input/fields';
import { unitSymbol } from '../core/input/units';
import type { PassPattern } from '../core/input/validate';
import type { SurfaceAxis } from '../core/surfaces/cylinder';
import type { SolveMode } from '../worker/protocol';
import { html } from './dom';
import { dragEarly } from './sliderDrag';
import { sliderRanges } from './sliders';
import {
  type CalculatorState,
  FIELD_KEYS,
  type FieldKey,
  formatField,
  isLengthField,
  PRESETS,
  parseField,
  presetOf,
  type SurfaceKind,
  sizeIsDiameter,
  type Target,
  type ToolSize,
  type Unit,
} from './state';

export interface FieldEvents {
  /**
   * A field's text changed: typed (`typing` true: it may be half-typed, see typing.ts), or a slider
   * moved (then already formatted, and final).
   */
  readonly onField: (key: FieldKey, text: string, typing: boolean) => void;
  /** The user committed what they typed: Enter, or the field lost focus. */
  readonly onCommit: () => void;
  /** The tool size switch: radius R or diameter D. */
  readonly onSize: (size: ToolSize) => void;
  readonly onMode: (mode: SolveMode) => void;
  readonly onUnit: (unit: Unit) => void;
  readonly onPattern: (pattern: PassPattern) => void;
  readonly onTarget: (target: Target) => void;
  /** The design surface (plane, convex or concave cylinder) and a cylinder's axis. */
  readonly onSurface: (surface: SurfaceKind) => void;
  readonly onSurfaceAxis: (axis: SurfaceAxis) => void;
  /** A preset was chosen: R and Rcr in mm. */
  readonly onPreset: (preset: { readonly R: number; readonly Rcr: number }) => void;
}

const HINTS: Readonly<Record<FieldKey, string>> = {
  R: 'half the tool diameter',
  Rcr: '0 = flat end, R = ball end',
  rho: 'tool inclination along the feed',
  tilt: 'tool inclination across the feed; + leans the shank to +Y',
  h: 'height of the highest cusp left between passes',
  L: 'distance between adjacent cutter-contact paths',
  ra: 'target roughness across the feed; the scallop height follows',
  Rs: "the cylinder's radius, a positive number (convex or concave is chosen above)",
};

/** The tool size field's label and hint in diameter mode. */
const DIAMETER_LABEL = FIELDS.D.label;
const DIAMETER_HINT = 'as catalogues give it; D = 2R';

/** The test ids' names of fields whose key differs (the surface radius: input-surface-radius). */
const TEST_NAME: Partial<Readonly<Record<FieldKey, string>>> = { Rs: 'surface-radius' };

interface FieldView {
  readonly row: HTMLElement;
  readonly label: HTMLElement;
  readonly hint: HTMLElement;
  readonly slider: HTMLInputElement;
  readonly input: HTMLInputElement;
  readonly unitLabel: HTMLElement;
  readonly error: HTMLElement;
}

function must<T extends Element>(root: ParentNode, selector: string): T {
  const found = root.querySelector<T>(selector);
  if (!found) throw new Error(`missing element ${selector}`);
  return found;
}

export class FieldsPanel {
  private readonly fields = new Map<FieldKey, FieldView>();
  private readonly preset: HTMLSelectElement;

  constructor(
    private readonly root: HTMLElement,
    events: FieldEvents,
  ) {
    const container = must<HTMLElement>(root, '.fields');
    // The surface radius sits with the surface's switches.
    const surfaceFields = root.querySelector<HTMLElement>('.surface-fields') ?? container;
    for (const key of FIELD_KEYS)
      this.fields.set(key, this.buildField(key === 'Rs' ? surfaceFields : container, key, events));
    this.wireSwitch('mode', (v) => events.onMode(v === 'inverse' ? 'inverse' : 'forward'));
    this.wireSwitch('unit', (v) => events.onUnit(v === 'in' ? 'in' : 'mm'));
    this.wireSwitch('pattern', (v) => events.onPattern(v === 'zigzag' ? 'zigzag' : 'one-way'));
    this.wireSwitch('target', (v) => events.onTarget(v === 'ra' ? 'ra' : 'h'));
    this.wireSwitch('size', (v) => events.onSize(v === 'D' ? 'D' : 'R'));
    this.wireSwitch('surface', (v) => events.onSurface(v === 'convex' || v === 'concave' ? v : 'plane'));
    this.wireSwitch('surfaceAxis', (v) => events.onSurfaceAxis(v === 'cross' ? 'cross' : 'feed'));
    const select = must<HTMLSelectElement>(root, '[data-testid="preset"]');
    this.preset = select;
    PRESETS.forEach((p, i) => {
      select.append(html('option', { value: String(i) }, p.label));
    });
    select.addEventListener('change', () => {
      const preset = PRESETS[Number(select.value)];
      if (preset) events.onPreset(preset);
    });
  }

  private buildField(container: HTMLElement, key: FieldKey, events: FieldEvents): FieldView {
    const id = `field-${key}`;
    const label = FIELD_LABELS[fieldOfPageKey(key)];
    const testName = TEST_NAME[key] ?? key;
    const row = html('div', { class: 'field', 'data-field': key });
    const slider = html('input', {
      type: 'range',
      'data-testid': `slider-${testName}`,
      'aria-label': `${label} slider`,
      'aria-describedby': `${id}-error`,
    });
    const input = html('input', {
      id,
      type: 'text',
      inputmode: 'decimal',
      autocomplete: 'off',
      spellcheck: 'false',
      'data-testid': `input-${testName}`,
      'aria-describedby': `${id}-hint ${id}-error`,
    });
    const unitLabel = html('span', { class: 'unit' });
    const hint = html('span', { class: 'hint', id: `${id}-hint` }, HINTS[key]);
    const labelElement = html('label', { for: id }, label);
    const error = html('div', { class: 'error', id: `${id}-error`, role: 'alert', 'data-testid': `error-${testName}` });
    const line = html('div', { class: 'field-line' });
    line.append(slider, input, unitLabel);
    row.append(labelElement, line, hint, error);
    container.append(row);
    input.addEventListener('input', () => events.onField(key, input.value, true));
    input.addEventListener('keydown', (e) => {
      if (e.key === 'Enter') events.onCommit();
    });
    input.addEventListener('blur', () => events.onCommit());
    // A slider's value in the user's unit, without float noise.
    slider.addEventListener('input', () => events.onField(key, formatField(Number(slider.value)), false));
    dragEarly(slider);
    return { row, label: labelElement, hint, slider, input, unitLabel, error };
  }

  private wireSwitch(name: string, on: (value: string) => void): void {
    for (const radio of this.root.querySelectorAll<HTMLInputElement>(`input[name="${name}"]`)) {
      radio.addEventListener('change', () => {
        if (radio.checked) on(radio.value);
      });
    }
  }

  /** Draws a state: values, visibility by mode, unit labels, slider ranges and the messages. */
  render(state: CalculatorState, messages: ReadonlyMap<FieldKey, string>): void {
    const ranges = sliderRanges(state);
    const forward = state.mode === 'forward';
    const plane = state.surface === 'plane';
    for (const [key, view] of this.fields) {
      const given = forward ? state.target : 'L';
      view.row.hidden = ((key === 'h' || key === 'ra' || key === 'L') && key !== given) || (key === 'Rs' && plane);
      view.unitLabel.textContent = isLengthField(key) ? unitSymbol(state.unit) : 'deg';
      if (key === 'R') {
        const diameter = sizeIsDiameter(state);
        view.label.textContent = diameter ? DIAMETER_LABEL : FIELD_LABELS.R;
        view.hint.textContent = diameter ? DIAMETER_HINT : HINTS.R;
        view.slider.setAttribute('aria-label', `${view.label.textContent} slider`);
      }
      if (view.input.value !== state.fields[key]) view.input.value = state.fields[key];
      const r = ranges[key];
      view.slider.min = r.min;
      view.slider.max = r.max;
      view.slider.step = r.step;
      const v = parseField(state.fields[key]);
      if (v !== null && view.slider !== document.activeElement) view.slider.value = String(v);
      const message = messages.get(key) ?? '';
      if (view.error.textContent !== message) view.error.textContent = message;
      view.row.classList.toggle('invalid', message !== '');
      view.input.setAttribute('aria-invalid', String(message !== ''));
    }
    const checked: Readonly<Record<string, string>> = {
      mode: state.mode,
      unit: state.unit,
      pattern: state.pattern,
      target: state.target,
      size: state.size ?? 'R',
      surface: state.surface,
      surfaceAxis: state.surfaceAxis,
    };
    // The preset box names the preset the tool fields hold, or "custom" once edited away from it.
    const preset = presetOf(state);
    const chosen = preset === null ? 'custom' : String(PRESETS.indexOf(preset));
    if (this.preset.value !== chosen) this.preset.value = chosen;
    // A plane has no radius and no axis: both are hidden (their values kept for the next cylinder).
    const axisSwitch = this.root.querySelector<HTMLElement>('[data-testid="surface-axis"]');
    if (axisSwitch) axisSwitch.hidden = plane;
    const targetSwitch = this.root.querySelector<HTMLElement>('[data-testid="target-switch"]');
    if (targetSwitch) targetSwitch.hidden = !forward;
    for (const [name, value] of Object.entries(checked))
      for (const radio of this.root.querySelectorAll<HTMLInputElement>(`input[name="${name}"]`))
        radio.checked = radio.value === value;
  }
}
