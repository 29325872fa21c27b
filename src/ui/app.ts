/**
 * The calculator page: fields and sliders, URL state, results, and the 3D scene.
 * Validation runs here for immediate messages; all solving runs in the worker.
 */
import {
  describeInputError,
  type FieldName,
  type InputError,
  scallopHeightLimits,
  validateForward,
  validateInverse,
} from '../core/validate';
import { type CameraPreset, ToolScene } from '../render/scene';
import { SolverClient } from '../worker/client';
import type { ProcedureKey, SolveReply } from '../worker/protocol';
import { html } from './dom';
import {
  type CalculatorState,
  convertState,
  FIELD_KEYS,
  type FieldKey,
  formatField,
  MM_PER_INCH,
  PRESETS,
  parseField,
  parseUrl,
  toMm,
  toSearch,
  type Unit,
} from './state';
import type { TeachingPanel, ViewId } from './views/panel';

/** The teaching views' ids (kept here so the views' code can load lazily). */
const VIEW_IDS: readonly ViewId[] = ['profile', 'chart', 'tables', 'stepper', 'formulas'];

interface FieldSpec {
  readonly key: FieldKey;
  readonly label: string;
  readonly unit: 'length' | 'deg';
  readonly hint: string;
}

const SPECS: readonly FieldSpec[] = [
  { key: 'R', label: 'Tool radius R', unit: 'length', hint: 'half the tool diameter' },
  { key: 'Rcr', label: 'Corner radius Rcr', unit: 'length', hint: '0 = flat end, R = ball end' },
  { key: 'rho', label: 'Lead angle rho', unit: 'deg', hint: 'tool inclination along the feed' },
  { key: 'h', label: 'Scallop height h', unit: 'length', hint: 'cusp height left between passes' },
  { key: 'L', label: 'Step-over L', unit: 'length', hint: 'distance between adjacent passes' },
];

const NAMES: Record<ProcedureKey, string> = {
  exact: 'Exact (3D geometry)',
  sekine: 'Sekine et al. (Eqs. 4-8)',
  redonnet: 'Redonnet et al. (Eqs. 9, 8)',
  bedi: 'Bedi et al. (Eqs. 10-11)',
};

const DASH = '\u2014';

function must<T extends Element>(root: ParentNode, selector: string): T {
  const found = root.querySelector<T>(selector);
  if (!found) throw new Error(`missing element ${selector}`);
  return found;
}

interface FieldView {
  readonly spec: FieldSpec;
  readonly row: HTMLElement;
  readonly slider: HTMLInputElement;
  readonly input: HTMLInputElement;
  readonly unitLabel: HTMLElement;
  readonly error: HTMLElement;
}

export class CalculatorApp {
  private state: CalculatorState;
  private readonly fields = new Map<FieldKey, FieldView>();
  private readonly viewParam: ViewId | null;
  /** Procedure highlighted across the views (hover, focus or selection) and the one selected. */
  private highlighted: ProcedureKey | null = null;
  private selected: ProcedureKey | null = null;
  private readonly initialView: ViewId;
  private teachingRequested = false;
  private teachingTimer: ReturnType<typeof setTimeout> | null = null;
  private teachingAfterFrame = false;
  private readonly scene: ToolScene;
  private readonly client: SolverClient;
  private readonly viewsClient: SolverClient;
  private viewsTimer: ReturnType<typeof setTimeout> | null = null;
  private readonly embed: boolean;
  /** Loaded after the first result: the views' code (charts, typesetting) is not needed to start. */
  private teaching: TeachingPanel | null = null;
  private teachingContext: Parameters<TeachingPanel['update']>[0] | null = null;
  private noticeTimer: ReturnType<typeof setTimeout> | null = null;
  private lastReply: SolveReply | null = null;
  /** Time of the input event whose result is awaited (for the latency benchmark). */
  private pendingInputAt: number | null = null;
  readonly latencies: number[] = [];
  /** performance.now() when the first result was shown (cold-load benchmark). */
  private firstResultMs: number | null = null;

  constructor(private readonly root: HTMLElement) {
    const parsed = parseUrl(window.location.search);
    this.state = parsed.state;
    this.embed = parsed.embed;
    document.documentElement.classList.toggle('embed', this.embed);
    this.buildFields();
    this.buildPresets();
    this.scene = new ToolScene(must(root, '.scene'));
    this.scene.onFrame = () => this.frameRendered();
    this.client = new SolverClient({
      onReply: (reply) => this.showReply(reply),
      onRestart: (reason) => this.notify(`The solver was restarted: ${reason}. Your last request was repeated.`, 5000),
    });
    this.viewsClient = new SolverClient({
      onReply: (reply) => this.showViews(reply),
      onRestart: (reason) => this.notify(`The teaching views' solver was restarted: ${reason}.`, 5000),
    });
    const requested = VIEW_IDS.find((v) => v === parsed.view);
    const notices = [...parsed.notices];
    if (parsed.view !== null && !requested) notices.push(`view="${parsed.view}" is not one of ${VIEW_IDS.join(', ')}.`);
    this.viewParam = requested ?? null;
    this.initialView = requested ?? 'profile';
    document.documentElement.classList.toggle('single-view', this.embed && requested !== undefined);
    document.documentElement.dataset.view = requested ?? '';
    this.wireHighlight();
    this.wireSwitches();
    if (notices.length > 0) this.notify(`Some link values were replaced: ${notices.join(' ')}`, 0);
    this.syncAll();
    this.update();
    this.exposeTestHooks();
  }

  private buildFields(): void {
    const container = must<HTMLElement>(this.root, '.fields');
    for (const spec of SPECS) {
      const id = `field-${spec.key}`;
      const row = html('div', { class: 'field', 'data-field': spec.key });
      const label = html('label', { for: id }, spec.label);
      const slider = html('input', {
        type: 'range',
        'data-testid': `slider-${spec.key}`,
        'aria-label': `${spec.label} slider`,
        'aria-describedby': `${id}-error`,
      });
      const input = html('input', {
        id,
        type: 'text',
        inputmode: 'decimal',
        autocomplete: 'off',
        spellcheck: 'false',
        'data-testid': `input-${spec.key}`,
        'aria-describedby': `${id}-hint ${id}-error`,
      });
      const unitLabel = html('span', { class: 'unit' });
      const hint = html('span', { class: 'hint', id: `${id}-hint` }, spec.hint);
      const error = html('div', {
        class: 'error',
        id: `${id}-error`,
        role: 'alert',
        'data-testid': `error-${spec.key}`,
      });
      const line = html('div', { class: 'field-line' });
      line.append(slider, input, unitLabel);
      row.append(label, line, hint, error);
      container.append(row);
      this.fields.set(spec.key, { spec, row, slider, input, unitLabel, error });
      input.addEventListener('input', () => this.onField(spec.key, input.value, 'input'));
      slider.addEventListener('input', () => this.onField(spec.key, slider.value, 'slider'));
    }
  }

  private buildPresets(): void {
    const select = must<HTMLSelectElement>(this.root, '[data-testid="preset"]');
    PRESETS.forEach((p, i) => {
      select.append(html('option', { value: String(i) }, p.label));
    });
    select.addEventListener('change', () => {
      const preset = PRESETS[Number(select.value)];
      if (!preset) return;
      const k = this.state.unit === 'in' ? 1 / MM_PER_INCH : 1;
      this.state = {
        ...this.state,
        fields: { ...this.state.fields, R: formatField(preset.R * k), Rcr: formatField(preset.Rcr * k) },
      };
      this.pendingInputAt = performance.now();
      this.syncAll();
      this.update();
    });
  }

  private wireSwitches(): void {
    for (const radio of this.root.querySelectorAll<HTMLInputElement>('input[name="mode"]')) {
      radio.checked = radio.value === this.state.mode;
      radio.addEventListener('change', () => {
        if (!radio.checked) return;
        this.state = { ...this.state, mode: radio.value === 'inverse' ? 'inverse' : 'forward' };
        this.syncAll();
        this.update();
      });
    }
    for (const radio of this.root.querySelectorAll<HTMLInputElement>('input[name="unit"]')) {
      radio.checked = radio.value === this.state.unit;
      radio.addEventListener('change', () => {
        if (!radio.checked) return;
        this.state = convertState(this.state, radio.value === 'in' ? 'in' : 'mm');
        this.syncAll();
        this.update();
      });
    }
    for (const button of this.root.querySelectorAll<HTMLButtonElement>('[data-camera]')) {
      button.addEventListener('click', () => this.scene.setCamera(button.dataset.camera as CameraPreset));
    }
    for (const button of this.root.querySelectorAll<HTMLButtonElement>('[data-copy]')) {
      button.addEventListener('click', () => {
        const target = this.root.querySelector(`[data-testid="${button.dataset.copy}"]`);
        const text = target?.textContent ?? '';
        if (text && text !== DASH) void navigator.clipboard?.writeText(text).catch(() => undefined);
      });
    }
  }

  private onField(key: FieldKey, text: string, from: 'input' | 'slider'): void {
    this.pendingInputAt = performance.now();
    this.state = { ...this.state, fields: { ...this.state.fields, [key]: text } };
    const view = this.fields.get(key);
    if (view && from === 'slider') view.input.value = text;
    this.update();
  }

  /** Unit of lengths as shown. */
  private unitText(): string {
    return this.state.unit === 'mm' ? 'mm' : 'in';
  }

  /** Writes every field, slider range and label from the state. */
  private syncAll(): void {
    const forward = this.state.mode === 'forward';
    for (const view of this.fields.values()) {
      const { key } = view.spec;
      view.row.hidden = forward ? key === 'L' : key === 'h';
      view.unitLabel.textContent = view.spec.unit === 'deg' ? 'deg' : this.unitText();
      if (view.input.value !== this.state.fields[key]) view.input.value = this.state.fields[key];
    }
    for (const radio of this.root.querySelectorAll<HTMLInputElement>('input[name="unit"]'))
      radio.checked = radio.value === this.state.unit;
    for (const radio of this.root.querySelectorAll<HTMLInputElement>('input[name="mode"]'))
      radio.checked = radio.value === this.state.mode;
    this.syncSliders();
  }

  /** Slider ranges follow the other values (Rcr up to R, h up to the corner height). */
  private syncSliders(): void {
    const u = this.state.unit === 'in' ? MM_PER_INCH : 1;
    const num = (key: FieldKey) => parseField(this.state.fields[key]);
    const R = num('R');
    const Rcr = num('Rcr');
    const rho = num('rho');
    const rMm = R !== null && R > 0 ? toMm('R', R, this.state.unit) : 3;
    const rcrMm = Rcr !== null && Rcr >= 0 ? Math.min(toMm('Rcr', Rcr, this.state.unit), rMm) : rMm / 3;
    const rhoDeg = rho !== null && rho >= 0 && rho < 90 ? rho : 5;
    const limitMm = scallopHeightLimits({
      toolRadiusMm: rMm,
      cornerRadiusMm: rcrMm,
      leadAngleDeg: rhoDeg,
      tiltAngleDeg: 0,
    }).limitMm;
    const ranges: Record<FieldKey, [number, number, number]> = {
      R: [0.1 / u, 25 / u, 0.01 / u],
      Rcr: [0, rMm / u, 0.01 / u],
      rho: [0, 89.9, 0.1],
      h: [0.001 / u, Math.max(0.002, Math.min(limitMm * 0.999, 2)) / u, 0.001 / u],
      L: [0.01 / u, (2 * rMm * 0.999) / u, 0.001 / u],
    };
    for (const key of FIELD_KEYS) {
      const view = this.fields.get(key);
      if (!view) continue;
      const [min, max, step] = ranges[key];
      view.slider.min = formatField(min);
      view.slider.max = formatField(max);
      view.slider.step = String(Number(step.toPrecision(3)));
      const v = num(key);
      if (v !== null && view.slider !== document.activeElement) view.slider.value = String(v);
    }
  }

  private update(): void {
    this.syncSliders();
    const extra: Record<string, string> = {};
    if (this.embed) extra.embed = '1';
    if (this.viewParam) extra.view = this.viewParam;
    window.history.replaceState(null, '', toSearch(this.state, extra) + window.location.hash);
    const fullLink = this.root.querySelector<HTMLAnchorElement>('[data-testid="open-full"]');
    if (fullLink) fullLink.href = toSearch(this.state);
    const { unit, mode, fields } = this.state;
    const mm = (key: FieldKey): number | string => {
      const v = parseField(fields[key]);
      return v === null ? fields[key] : toMm(key, v, unit);
    };
    const validation =
      mode === 'forward'
        ? validateForward({ R: mm('R'), Rcr: mm('Rcr'), rho: mm('rho'), h: mm('h') })
        : validateInverse({ R: mm('R'), Rcr: mm('Rcr'), rho: mm('rho'), interval: mm('L') });
    const errors = new Map<FieldKey, string>();
    if (!validation.ok) {
      for (const e of validation.errors) {
        const key = fieldOf(e.field);
        if (key !== null) errors.set(key, this.localise(e));
      }
    }
    for (const view of this.fields.values()) {
      const message = errors.get(view.spec.key) ?? '';
      if (view.error.textContent !== message) view.error.textContent = message;
      view.row.classList.toggle('invalid', message !== '');
      view.input.setAttribute('aria-invalid', String(message !== ''));
    }
    if (!validation.ok) {
      this.showInvalid();
      return;
    }
    const value = mode === 'forward' ? (mm('h') as number) : (mm('L') as number);
    const request = { mode, R: mm('R') as number, Rcr: mm('Rcr') as number, rho: mm('rho') as number, value };
    this.client.request(request);
    // The teaching views' data comes from a second worker, a moment later while a slider moves,
    // so it never delays the results and the 3D frame.
    // An embedded calculator without a teaching view shows none: skip their data.
    if (this.embed && this.viewParam === null) return;
    if (this.viewsTimer !== null) clearTimeout(this.viewsTimer);
    this.viewsTimer = setTimeout(() => {
      this.viewsTimer = null;
      this.viewsClient.request({ ...request, withViews: true });
    }, 150);
  }

  /** The message of an input error in the current unit, quoting what the user typed. */
  private localise(e: InputError): string {
    const key = fieldOf(e.field);
    const typed = key === null ? undefined : this.state.fields[key].trim();
    return describeInputError(e, this.state.unit, typed === undefined ? {} : { typed });
  }

  private showInvalid(): void {
    for (const id of ['result-exact-interval', 'result-exact-half']) this.setText(id, DASH);
    this.setText('result-percent-diameter', '');
    for (const row of this.root.querySelectorAll('.procedures tbody output')) row.textContent = DASH;
    this.scene.setStale(true);
  }

  private setText(testId: string, text: string): void {
    const e = this.root.querySelector(`[data-testid="${testId}"]`);
    if (e && e.textContent !== text) e.textContent = text;
  }

  /** Length in the current unit, 4 decimals in mm, 5 in inch. */
  private len(mm: number): string {
    return this.state.unit === 'mm' ? mm.toFixed(4) : (mm / MM_PER_INCH).toFixed(5);
  }

  /** Scallop height in the current unit: one decimal more than lengths (5 in mm, 6 in inch). */
  private height(mm: number): string {
    return this.state.unit === 'mm' ? mm.toFixed(5) : (mm / MM_PER_INCH).toFixed(6);
  }

  /** Signed deviation: a length (forward) or a height (inverse). */
  private signed(mm: number, isLength: boolean): string {
    const t = isLength ? this.len(mm) : this.height(mm);
    return mm >= 0 && !t.startsWith('-') ? `+${t}` : t;
  }

  private showReply(reply: SolveReply): void {
    this.lastReply = reply;
    if (this.firstResultMs === null && reply.ok) this.firstResultMs = performance.now();
    if (!reply.ok) {
      this.showInvalid();
      return;
    }
    const unit = this.unitText();
    const forward = reply.mode === 'forward';
    const L = 2 * reply.halfIntervalMm;
    must(this.root, '[data-role="headline-label"]').textContent = forward ? 'Step-over L' : 'Scallop height h';
    this.setText('result-exact-interval', `${forward ? this.len(L) : this.height(reply.scallopHeightMm)} ${unit}`);
    this.setText('result-exact-half', this.len(reply.halfIntervalMm));
    const R = toMm('R', parseField(this.state.fields.R) ?? 1, this.state.unit);
    this.setText('result-percent-diameter', `L = ${((100 * L) / (2 * R)).toFixed(1)} % of the tool diameter`);

    const table = must<HTMLTableElement>(this.root, '.procedures');
    const head = forward
      ? ['Procedure', `L/2 [${unit}]`, `Deviation [${unit}]`, 'Deviation [%]', `Scallop it leaves [${unit}]`]
      : ['Procedure', `h [${unit}]`, `Deviation [${unit}]`, 'Deviation [%]'];
    const thead = must<HTMLElement>(table, 'thead');
    const headHtml = `<tr>${head.map((h) => `<th scope="col">${h}</th>`).join('')}</tr>`;
    if (thead.innerHTML !== headHtml) thead.innerHTML = headHtml;
    const tbody = must<HTMLElement>(table, 'tbody');
    tbody.replaceChildren();
    const notes: string[] = [];
    for (const row of reply.rows) {
      const tr = html('tr', {
        'data-procedure': row.key,
        tabindex: '0',
        title: 'Click to select this procedure in every view',
      });
      tr.append(html('th', { scope: 'row' }, NAMES[row.key]));
      // The headline already carries result-exact-half: the table's exact row gets its own ids.
      const prefix = row.key === 'exact' ? 'table-exact' : `result-${row.key}`;
      const value = html(
        'output',
        { 'data-testid': `${prefix}-${forward ? 'half' : 'h'}` },
        row.valueMm === null ? 'n/a' : forward ? this.len(row.valueMm) : this.height(row.valueMm),
      );
      const cell = html('td');
      cell.append(value);
      tr.append(cell);
      tr.append(html('td', {}, row.deviationMm === null ? DASH : this.signed(row.deviationMm, forward)));
      tr.append(
        html(
          'td',
          {},
          row.deviationPercent === null
            ? DASH
            : `${row.deviationPercent >= 0 ? '+' : ''}${row.deviationPercent.toFixed(2)}`,
        ),
      );
      if (forward) {
        const real = html(
          'output',
          { 'data-testid': `${prefix}-real-h` },
          row.realScallopMm === null ? DASH : this.height(row.realScallopMm),
        );
        const td = html('td');
        td.append(real);
        tr.append(td);
      }
      if (row.note) {
        tr.title = row.note;
        notes.push(`${NAMES[row.key]}: ${row.note.replace(/^[^:]+: /, '')}`);
      }
      tbody.append(tr);
    }
    this.setText('table-notes', notes.join(' '));
    this.markRows();

    if (reply.geometry) {
      this.scene.update(reply.geometry, `L/2 = ${this.len(reply.geometry.halfIntervalMm)} ${unit}`);
      this.scene.setStale(false);
    } else {
      this.scene.setStale(true);
      this.setText(
        'table-notes',
        `${notes.join(' ')} No scallop: at rho = 0 the flat bottom covers L/2 <= R - Rcr.`.trim(),
      );
    }
  }

  private showViews(reply: SolveReply): void {
    if (!reply.ok || !reply.teaching) return;
    const num = (key: FieldKey) => toMm(key, parseField(this.state.fields[key]) ?? 0, this.state.unit);
    this.teachingContext = { reply, unit: this.state.unit, R: num('R'), Rcr: num('Rcr'), rho: num('rho') };
    this.scheduleTeaching();
  }

  /**
   * The teaching views update after the results and the 3D frame are out, so they never
   * delay them; their code loads only after the first result.
   */
  private scheduleTeaching(): void {
    if (!this.teachingRequested) {
      this.teachingRequested = true;
      void import('./views/panel').then(({ TeachingPanel }) => {
        this.teaching = new TeachingPanel(
          must(this.root, '[data-testid="teaching"]'),
          this.scene,
          (c) => this.loadCondition(c),
          this.initialView,
        );
        if (this.teachingContext) this.teaching.update(this.teachingContext);
        this.teaching.highlight(this.highlighted);
      });
      return;
    }
    // While a result is awaited, the views wait for its frame (see frameRendered).
    if (this.pendingInputAt !== null) {
      this.teachingAfterFrame = true;
      return;
    }
    if (this.teachingTimer !== null) return;
    this.teachingTimer = setTimeout(() => {
      this.teachingTimer = null;
      if (this.teaching && this.teachingContext) this.teaching.update(this.teachingContext);
    }, 0);
  }

  /** Loads one of the paper's conditions (mm, degrees) into the calculator. */
  private loadCondition(c: { R: number; Rcr: number; rho: number; h: number }): void {
    const k = this.state.unit === 'in' ? 1 / MM_PER_INCH : 1;
    this.state = {
      ...this.state,
      mode: 'forward',
      fields: {
        ...this.state.fields,
        R: formatField(c.R * k),
        Rcr: formatField(c.Rcr * k),
        rho: formatField(c.rho),
        h: formatField(c.h * k),
      },
    };
    this.syncAll();
    this.update();
  }

  /** Hovering or focusing a procedure anywhere highlights it in the table, the profile and the charts. */
  private wireHighlight(): void {
    const keyOf = (target: EventTarget | null): ProcedureKey | null => {
      const el = target instanceof Element ? target.closest<HTMLElement>('[data-procedure]') : null;
      const key = el?.dataset.procedure;
      return key === 'exact' || key === 'sekine' || key === 'redonnet' || key === 'bedi' ? key : null;
    };
    // Hover or focus shows a procedure for a moment; a click (or Enter) on a results row selects it.
    this.root.addEventListener('mouseover', (e) => this.setHighlight(keyOf(e.target) ?? this.selected));
    this.root.addEventListener('focusin', (e) => this.setHighlight(keyOf(e.target) ?? this.selected));
    const select = (target: EventTarget | null) => {
      const row = target instanceof Element ? target.closest('.procedures tr[data-procedure]') : null;
      if (!row) return;
      const key = keyOf(row);
      this.selected = key === this.selected ? null : key;
      this.setHighlight(this.selected ?? key);
      this.markRows();
    };
    this.root.addEventListener('click', (e) => select(e.target));
    this.root.addEventListener('keydown', (e) => {
      if (e.key === 'Enter') select(e.target);
    });
  }

  private setHighlight(key: ProcedureKey | null): void {
    if (key === this.highlighted) return;
    this.highlighted = key;
    this.teaching?.highlight(key);
    this.markRows();
  }

  /** Marks the highlighted and the selected row of the results table. */
  private markRows(): void {
    for (const tr of this.root.querySelectorAll<HTMLElement>('.procedures tr[data-procedure]')) {
      tr.classList.toggle('emph', this.highlighted !== null && tr.dataset.procedure === this.highlighted);
      tr.classList.toggle('selected', tr.dataset.procedure === this.selected);
    }
  }

  private frameRendered(): void {
    if (this.pendingInputAt !== null && this.lastReply?.ok) {
      this.latencies.push(performance.now() - this.pendingInputAt);
      this.pendingInputAt = null;
    }
    if (this.teachingAfterFrame && this.pendingInputAt === null) {
      this.teachingAfterFrame = false;
      this.scheduleTeaching();
    }
  }

  private notify(message: string, ms: number): void {
    const box = must<HTMLElement>(this.root, '[data-testid="notice"]');
    box.textContent = message;
    box.hidden = false;
    if (this.noticeTimer !== null) clearTimeout(this.noticeTimer);
    if (ms > 0) this.noticeTimer = setTimeout(() => (box.hidden = true), ms);
  }

  private exposeTestHooks(): void {
    const hooks = {
      frames: () => this.scene.frames,
      softwareRendering: () => this.scene.softwareRendering,
      workerStarts: () => this.client.started,
      crashWorker: () => this.client.crash(),
      latencies: () => [...this.latencies],
      lastReplyOk: () => this.lastReply?.ok ?? null,
      firstResultMs: () => this.firstResultMs,
      activeView: () => this.teaching?.activeView ?? null,
    };
    (window as unknown as { __pathInterval: typeof hooks }).__pathInterval = hooks;
  }
}

function fieldOf(field: FieldName): FieldKey | null {
  if (field === 'interval') return 'L';
  return field === 'tilt' || field === 'pattern' || field === 'surfaceRadius' || field === 'surfaceAxis' ? null : field;
}

export type { Unit };
