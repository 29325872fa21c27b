/**
 * The input side of the page: a slider paired with a number field for each value, the switches
 * (mode, unit, pass pattern) and the tool presets. It reports what the user did and draws the
 * state it is given (values, ranges in the user's unit, messages); it holds no state itself.
 */

import { FIELDS, type FieldSpec, fieldOfPageKey } from '../core/input/fields';
import { unitSymbol } from '../core/input/units';
import type { PassPattern } from '../core/input/validate';
import type { SurfaceAxis } from '../core/surfaces/cylinder';
import type { SliderLimits, SolveMode } from '../worker/protocol';
import { html, must } from './dom';
import { FINISH_KEYS, finishGiven, finishKeyOff, rateFzText } from './finishFields';
import { catalogue, fieldWords } from './i18n/words';
import type { Machine, Passes } from './machineState';
import { dragEarly } from './sliderDrag';
import { sliderRanges } from './sliders';
import {
  type CalculatorState,
  FIELD_KEYS,
  type FieldKey,
  formatField,
  PRESETS,
  parseField,
  presetOf,
  type SurfaceKind,
  sizeIsDiameter,
  type Target,
  type ToolSize,
  type Unit,
} from './state';
import {
  CURVED_PRESETS,
  type CurvedPreset,
  curvedPresetOf,
  PRESET_LABELS,
  RADIUS_SIDES,
  type RadiusKey,
  type RadiusSide,
  sideOf,
  WATERLINE_PRESETS,
  type WaterlinePreset,
  waterlinePresetOf,
} from './surfaceState';
import { ToolChips } from './toolChips';
import { selectOnTouchFocus } from './touchSelect';

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
  /** A preset was chosen: R and Rcr in mm; `unit`: the page switches to it (a first visit's tool of the other unit). */
  readonly onPreset: (preset: { readonly R: number; readonly Rcr: number }, unit?: Unit) => void;
  /** Five-axis or three-axis machining; three-axis raster or waterline passes. */
  readonly onMachine: (machine: Machine) => void;
  readonly onPasses: (passes: Passes) => void;
  /** A doubly curved point's radius turned convex, concave or straight. */
  readonly onSide: (key: RadiusKey, side: RadiusSide) => void;
  /** A surface preset (dome, bowl, saddle...) was chosen. */
  readonly onSurfacePreset: (preset: CurvedPreset | WaterlinePreset) => void;
}

const HINTS: Readonly<Record<FieldKey, string>> = {
  R: 'half the tool diameter',
  Rcr: '0 = flat end, R = ball end',
  rho: 'tool inclination along the feed',
  tilt: 'tool inclination across the feed; + leans the shank to +Y',
  h: 'height of the highest cusp left between passes',
  L: 'distance between adjacent cutter-contact paths',
  ra: 'target roughness across the feed; the scallop height follows',
  sa: 'areal roughness the teeth leave (plane); with z: the best L and fz',
  Rs: "the cylinder's radius, a positive number (convex or concave is chosen above)",
  slope: "the surface's slope from the horizontal at the contact (0 a flat floor)",
  psi: 'passes in plan from the fall line: 0 up and down the slope, 90 along the contour',
  Rf: 'principal radius along the feed, a positive number; its side is chosen beside it',
  Rc: 'principal radius across the feed, a positive number; its side is chosen beside it',
  Lxy: 'horizontal distance between adjacent raster passes, as the CAM system programs it',
  dz: 'vertical distance between adjacent levels (tool tips), as the CAM system programs it',
  z: 'teeth; with fz: the feed marks',
  fz: 'feed per tooth; empty: no feed marks',
  runout: 'radial runout (default 0)',
  runoutPhase: 'runout direction from tooth 0',
  passPhase: 'pass shift, a fraction of the feed period',
  F: 'with n: fz = F / (n z); off while fz is typed',
  n: 'spindle speed, with F',
};

/** The order of the form: the slope and raster angle sit where the lead and tilt do. */
const FORM_ORDER: readonly FieldKey[] = ['R', 'Rcr', 'rho', 'tilt', 'slope', 'psi', 'h', 'ra', 'sa', 'L', 'Lxy', 'dz'];

/** The feed's fields, not used with a target Sa (fz is its answer): disabled, their hint says so. */
const SA_UNUSED: readonly FieldKey[] = ['fz', 'F', 'n'];
/** Their hint then (a finish phrase: put into the language in force). */
const SA_UNUSED_HINT = 'not used with a target Sa: fz is its answer';

/** True for the feed's fields a target Sa does not use. */
function unusedBySa(key: FieldKey): boolean {
  return SA_UNUSED.includes(key);
}

/** The teeth and their feed: always offered (optional; the finish says where it is not computed). */
const FINISH_SHOWN = { z: true, fz: true, F: true, n: true, runout: true, runoutPhase: true, passPhase: true } as const;

/**
 * The unit after a field: a length's symbol (with the registry's suffix: mm/min), the registry's
 * unit of a plain number (rpm; none for a count of teeth or a fraction), or degrees.
 */
function unitLabel(key: FieldKey, unit: Unit): string {
  const spec = FIELDS[fieldOfPageKey(key)] as FieldSpec;
  if (spec.kind === 'length') return unitSymbol(unit) + (spec.unit ?? '');
  return spec.kind === 'number' ? (spec.unit ?? '') : (catalogue()?.degrees ?? 'deg');
}

/** The fields shown with the surface's switches. */
const SURFACE_KEYS: readonly FieldKey[] = ['Rs', 'Rf', 'Rc'];

/** The tool size field's label and hint in diameter mode. */
const DIAMETER_LABEL = FIELDS.D.label;
const DIAMETER_HINT = 'as catalogues give it; D = 2R';
/** The corner radius's hint in diameter mode. */
const CORNER_HINT_DIAMETER = 'Rcr = 0 is a flat end, Rcr = D/2 is a ball end';

/** The test ids' names of fields whose key differs (the surface radius: input-surface-radius). */
const TEST_NAME: Partial<Readonly<Record<FieldKey, string>>> = {
  Rs: 'surface-radius',
  Rf: 'feed-radius',
  Rc: 'cross-radius',
  psi: 'raster-angle',
  Lxy: 'horizontal-step',
  dz: 'step-down',
  z: 'flutes',
  runoutPhase: 'runout-phase',
  passPhase: 'pass-phase',
  F: 'feed-rate',
  n: 'spindle-speed',
};

/** The sides' names in a radius's side box. */
const SIDE_LABEL: Readonly<Record<RadiusSide, string>> = { convex: 'convex', concave: 'concave', straight: 'straight' };

interface FieldView {
  readonly row: HTMLElement;
  readonly label: HTMLElement;
  readonly hint: HTMLElement;
  readonly slider: HTMLInputElement;
  readonly input: HTMLInputElement;
  readonly unitLabel: HTMLElement;
  readonly error: HTMLElement;
}

export class FieldsPanel {
  private readonly fields = new Map<FieldKey, FieldView>();
  private readonly preset: HTMLSelectElement;
  /** The catalogue tools of the unit on screen, one tap each (absent from a page without them). */
  /** The catalogue buttons (toolChips.ts; a first visit offers both units'). */
  readonly chips: ToolChips | null;
  private readonly surfacePreset: HTMLSelectElement;
  /** The presets the surface box lists now (five-axis or waterline). */
  private presetsShown: readonly string[] = [];
  private readonly sides = new Map<RadiusKey, HTMLSelectElement>();
  /** The last state drawn, with its messages (drawn again when the sliders' limits change). */
  private drawn: { state: CalculatorState; messages: ReadonlyMap<FieldKey, string> } | null = null;
  /** The teeth-and-feed box (a disclosure, closed while its optional fields are empty). */
  private readonly finishBox: HTMLDetailsElement | null;
  /** Whether the finish fields held text at the last render (the box opens when they start to). */
  private finishWasGiven = false;
  /** The sliders' limits: the worker's, beside its last reply (null: none yet). */
  private limits: SliderLimits | null = null;

  constructor(
    private readonly root: HTMLElement,
    events: FieldEvents,
  ) {
    const container = must<HTMLElement>(root, '.fields');
    // The surface radius sits with the surface's switches.
    const surfaceFields = root.querySelector<HTMLElement>('.surface-fields') ?? container;
    // The teeth and their feed (optional) sit in their own box.
    const finishFields = root.querySelector<HTMLElement>('.finish-fields') ?? container;
    this.finishBox = root.querySelector<HTMLDetailsElement>('details.finish-inputs');
    const order = [...FORM_ORDER, ...FIELD_KEYS.filter((k) => !FORM_ORDER.includes(k))];
    for (const key of order) {
      const box = SURFACE_KEYS.includes(key) ? surfaceFields : key in FINISH_SHOWN ? finishFields : container;
      this.fields.set(key, this.buildField(box, key, events));
    }
    for (const key of ['Rf', 'Rc'] as const) this.sides.set(key, this.buildSide(key, events));
    this.wireSwitch('machine', (v) => events.onMachine(v === '3axis' ? '3axis' : '5axis'));
    this.wireSwitch('passes', (v) => events.onPasses(v === 'waterline' ? 'waterline' : 'raster'));
    this.surfacePreset = must<HTMLSelectElement>(root, '[data-testid="surface-preset"]');
    this.surfacePreset.addEventListener('change', () => {
      const v = this.surfacePreset.value;
      const preset = [...CURVED_PRESETS, ...WATERLINE_PRESETS].find((p) => p === v);
      if (preset) events.onSurfacePreset(preset);
    });
    this.wireSwitch('mode', (v) => events.onMode(v === 'inverse' ? 'inverse' : 'forward'));
    this.wireSwitch('unit', (v) => events.onUnit(v === 'in' ? 'in' : 'mm'));
    this.wireSwitch('pattern', (v) => events.onPattern(v === 'zigzag' ? 'zigzag' : 'one-way'));
    this.wireSwitch('target', (v) => events.onTarget(v === 'ra' || v === 'sa' ? v : 'h'));
    this.wireSwitch('size', (v) => events.onSize(v === 'D' ? 'D' : 'R'));
    this.wireSwitch('surface', (v) =>
      events.onSurface(v === 'convex' || v === 'concave' || v === 'curved' ? v : 'plane'),
    );
    this.wireSwitch('surfaceAxis', (v) => events.onSurfaceAxis(v === 'cross' ? 'cross' : 'feed'));
    const select = must<HTMLSelectElement>(root, '[data-testid="preset"]');
    this.preset = select;
    const groups = { mm: html('optgroup', { label: 'metric (mm)' }), in: html('optgroup', { label: 'inch' }) };
    PRESETS.forEach((p, i) => {
      groups[p.sizedIn].append(html('option', { value: String(i) }, p.label));
    });
    select.append(groups.mm, groups.in);
    select.addEventListener('change', () => {
      const preset = PRESETS[Number(select.value)];
      if (preset) events.onPreset(preset);
    });
    const chips = root.querySelector<HTMLElement>('[data-testid="tool-chips"]');
    this.chips = chips === null ? null : new ToolChips(chips, events.onPreset);
  }

  private buildField(container: HTMLElement, key: FieldKey, events: FieldEvents): FieldView {
    const id = `field-${key}`;
    const label = FIELDS[fieldOfPageKey(key)].label;
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
      // Whole teeth: the phone's number pad without a decimal sign.
      inputmode: key === 'z' ? 'numeric' : 'decimal',
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
    selectOnTouchFocus(input);
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

  /**
   * A field's label, hint and slider name in the language in force (i18n/words.ts; English: the
   * registry's label and HINTS), the tool size's and the corner radius's as the size is given.
   */
  private word(view: FieldView, key: FieldKey, diameter: boolean, unusedBySa = false): void {
    const words = catalogue();
    const english = { label: FIELDS[fieldOfPageKey(key)].label, hint: HINTS[key] };
    let { label, hint } = fieldWords(key, english);
    if (unusedBySa) hint = words?.finish[SA_UNUSED_HINT] ?? SA_UNUSED_HINT;
    if (key === 'R' && diameter) {
      label = words?.diameter.label ?? DIAMETER_LABEL;
      hint = words?.diameter.hint ?? DIAMETER_HINT;
    }
    if (key === 'Rcr' && diameter) hint = words?.diameter.cornerHint ?? CORNER_HINT_DIAMETER;
    const slider = `${label}${words?.slider ?? ' slider'}`;
    if (view.label.textContent !== label) view.label.textContent = label;
    if (view.hint.textContent !== hint) view.hint.textContent = hint;
    if (view.slider.getAttribute('aria-label') !== slider) view.slider.setAttribute('aria-label', slider);
  }

  /** A radius's side box (convex, concave, straight), in its field's line. */
  private buildSide(key: RadiusKey, events: FieldEvents): HTMLSelectElement {
    const view = this.fields.get(key);
    const label = FIELDS[fieldOfPageKey(key)].label;
    const select = html('select', {
      'data-testid': `side-${TEST_NAME[key] ?? key}`,
      'aria-label': `${label}: convex, concave or straight`,
    });
    for (const side of RADIUS_SIDES) select.append(html('option', { value: side }, SIDE_LABEL[side]));
    select.addEventListener('change', () => {
      const side = RADIUS_SIDES.find((s) => s === select.value);
      if (side) events.onSide(key, side);
    });
    view?.unitLabel.after(select);
    return select;
  }

  private wireSwitch(name: string, on: (value: string) => void): void {
    for (const radio of this.root.querySelectorAll<HTMLInputElement>(`input[name="${name}"]`)) {
      radio.addEventListener('change', () => {
        if (radio.checked) on(radio.value);
      });
    }
  }

  /**
   * The sliders' limits (a reply's), for this render on: the state drawn is drawn again when they
   * change, unless `redraw` is false (the caller draws next).
   */
  rangeSliders(limits: SliderLimits | null, redraw = true): void {
    if (JSON.stringify(limits) === JSON.stringify(this.limits)) return;
    this.limits = limits;
    if (redraw && this.drawn !== null) this.render(this.drawn.state, this.drawn.messages);
  }

  /** Draws a state: values, visibility by mode, unit labels, slider ranges and the messages. */
  render(state: CalculatorState, messages: ReadonlyMap<FieldKey, string>): void {
    this.drawn = { state, messages };
    const ranges = sliderRanges(state, this.limits);
    // The teeth-and-feed box opens when its fields come to hold text (a link's z and fz, a library
    // tool's flutes); the user may close it again, and it stays as they left it while they do.
    const finishNow = finishGiven(state);
    if (finishNow && !this.finishWasGiven && this.finishBox !== null) this.finishBox.open = true;
    // A message on one of its fields opens it too (a closed box must not hide why there is no answer).
    if (this.finishBox !== null && !this.finishBox.open && FINISH_KEYS.some((k) => messages.has(k)))
      this.finishBox.open = true;
    this.finishWasGiven = finishNow;
    const rateFz = rateFzText(state);
    const forward = state.mode === 'forward';
    const five = state.machine === '5axis';
    const plane = state.surface === 'plane';
    const cylinder = five && (state.surface === 'convex' || state.surface === 'concave');
    const radii = five ? state.surface === 'curved' : state.passes === 'waterline';
    const given: FieldKey = forward ? state.target : five ? 'L' : state.passes === 'waterline' ? 'dz' : 'Lxy';
    const saTarget = given === 'sa';
    const shown: Readonly<Record<FieldKey, boolean>> = {
      R: true,
      Rcr: true,
      rho: five,
      tilt: five,
      slope: !five,
      psi: !five && state.passes === 'raster',
      h: given === 'h',
      ra: given === 'ra',
      sa: given === 'sa',
      L: given === 'L',
      Lxy: given === 'Lxy',
      dz: given === 'dz',
      Rs: cylinder,
      Rf: radii,
      Rc: radii,
      ...FINISH_SHOWN,
    };
    for (const [key, view] of this.fields) {
      view.row.hidden = !shown[key];
      if (key === 'Rf' || key === 'Rc') {
        const side = sideOf(state, key);
        const box = this.sides.get(key);
        if (box && box.value !== side) box.value = side;
        view.input.disabled = side === 'straight';
        view.slider.disabled = side === 'straight';
        // F and n while fz is typed: off (fz wins).
      } else view.input.disabled = view.slider.disabled = finishKeyOff(state, key) || (saTarget && unusedBySa(key));
      const unitText = unitLabel(key, state.unit);
      if (view.unitLabel.textContent !== unitText) view.unitLabel.textContent = unitText;
      this.word(view, key, sizeIsDiameter(state), saTarget && unusedBySa(key));
      // fz while the feed rate and spindle speed hold text: read-only, the fz they give (or empty).
      const text = key === 'fz' && rateFz !== null ? rateFz : state.fields[key];
      if (view.input.value !== text) view.input.value = text;
      if (key === 'fz') view.input.readOnly = view.slider.disabled = rateFz !== null;
      const r = ranges[key];
      view.slider.min = r.min;
      view.slider.max = r.max;
      view.slider.step = r.step;
      const v = parseField(state.fields[key]);
      if (v !== null && view.slider !== document.activeElement) view.slider.value = String(v);
      // An empty optional field (the teeth and feed): its slider says so, not the value its thumb rests at.
      if (v === null && state.fields[key].trim() === '')
        view.slider.setAttribute('aria-valuetext', catalogue()?.said.empty ?? 'empty');
      else view.slider.removeAttribute('aria-valuetext');
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
      machine: state.machine,
      passes: state.passes,
    };
    this.renderSurfaceSwitches(state, five, radii);
    // The preset box names the preset the tool fields hold, or "custom" once edited away from it.
    const preset = presetOf(state);
    const chosen = preset === null ? 'custom' : String(PRESETS.indexOf(preset));
    if (this.preset.value !== chosen) this.preset.value = chosen;
    this.chips?.render(state);
    // A plane has no radius and no axis: both are hidden (their values kept for the next cylinder).
    const axisSwitch = this.root.querySelector<HTMLElement>('[data-testid="surface-axis"]');
    if (axisSwitch) axisSwitch.hidden = plane || !cylinder;
    const targetSwitch = this.root.querySelector<HTMLElement>('[data-testid="target-switch"]');
    if (targetSwitch) targetSwitch.hidden = !forward;
    for (const [name, value] of Object.entries(checked))
      for (const radio of this.root.querySelectorAll<HTMLInputElement>(`input[name="${name}"]`))
        radio.checked = radio.value === value;
  }

  /**
   * The surface's switches by machine: five-axis the surface kind (plane, cylinders, doubly curved
   * point) and its presets; three-axis raster passes a sloped plane (said in words), waterline the
   * surface of revolution's presets and radii; the pass strategy switch only for three-axis.
   */
  private renderSurfaceSwitches(state: CalculatorState, five: boolean, radii: boolean): void {
    const toggle = (selector: string, hidden: boolean) => {
      const e = this.root.querySelector<HTMLElement>(selector);
      if (e) e.hidden = hidden;
    };
    toggle('[data-testid="surface-kind"]', !five);
    toggle('[data-testid="passes-switch"]', five);
    toggle('[data-testid="pattern-switch"]', !five);
    toggle('.surface-preset', !radii);
    const note = this.root.querySelector<HTMLElement>('[data-testid="surface-note"]');
    if (note) {
      const text =
        five || state.passes === 'waterline'
          ? ''
          : "Raster passes on a sloped plane: the slope and the raster angle set the tool's lead and tilt at the contact.";
      if (note.textContent !== text) note.textContent = text;
      note.hidden = text === '';
    }
    if (!radii) return;
    const presets: readonly string[] = five ? CURVED_PRESETS : WATERLINE_PRESETS;
    if (this.presetsShown !== presets) {
      this.presetsShown = presets;
      this.surfacePreset.replaceChildren(html('option', { value: 'custom' }, 'custom radii'));
      for (const p of presets)
        this.surfacePreset.append(html('option', { value: p }, PRESET_LABELS[p as CurvedPreset | WaterlinePreset]));
    }
    const chosen = (five ? curvedPresetOf(state) : waterlinePresetOf(state)) ?? 'custom';
    if (this.surfacePreset.value !== chosen) this.surfacePreset.value = chosen;
  }
}
