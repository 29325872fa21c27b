/**
 * Machined surface: the passes simulated on a height field (worker job `simulate`), or, while the
 * finish box answers the inputs on screen (flutes and fz given, on a plane), the surface the teeth
 * leave over several period cells (the finish job's areal answer, teethMap.ts), a caption
 * saying which; shown in 3D
 * coloured by height with a legend in µm (µin in inch) and the vertical exaggeration stated, a profilometer
 * trace across the passes with Rz, Ra, Rq marked, and one line comparing the simulated cusp with
 * the exact one and the simulation's stated resolution bound. It draws only a reply to the inputs
 * on screen; otherwise its numbers are hidden and it says why (updating, invalid, gave up).
 * No inline style: classes and SVG presentation attributes only (the page runs under
 * `style-src 'self'`).
 */

import { roughnessUnit } from '../../core/input/units';
import { autoExaggeration } from '../../core/output/drawingScale';
import type { ProcedureKey } from '../../core/procedures/procedures';
import { HEIGHT_RAMP } from '../../render/surfaceGrid';
import { SurfaceScene } from '../../render/surfaceMesh';
import type { SimulateReply } from '../../worker/simulate';
import { feedLength } from '../finishLength';
import { formatLenUnit, formatRoughness } from '../format';
import type { Shown } from '../freshness';
import type { SurfaceWords } from '../i18n/catalogue';
import { localDecimal } from '../i18n/langChoice';
import { catalogue, describeError, localize } from '../i18n/words';
import { setDetail } from '../i18n/workerReason';
import type { SurfaceDisplay } from '../simulation';
import type { Unit } from '../state';
import { onTeethSurface, type TeethShown } from '../teethMap';
import { onThemeChange } from '../theme';
import { html, svg, type TeachingView } from './common';
import { EN_SURFACE, exceptionDetail, exceptionIn } from './surfaceWords';
import './surface.css';

type SimulateOk = Extract<SimulateReply, { ok: true }>;

/** What opens and closes the simulation (the page's SimulationLoader). */
export interface SurfaceSource {
  setOpen(open: boolean): void;
  attach(display: SurfaceDisplay): void;
}

const TRACE_W = 600;
const TRACE_H = 190;
const PAD = { left: 8, right: 150, top: 14, bottom: 18 };

/**
 * The comparison line: simulated against exact cusp, and the stated bound, each a length with its
 * unit as the results give lengths (format.ts: µm or thou when small, never exponent notation).
 */
export function comparisonText(reply: SimulateOk, unit: Unit, words: SurfaceWords = EN_SURFACE): string {
  const s = reply.simulation;
  const fine = (mm: number) => formatLenUnit(mm, unit, 'fine');
  const diff = Math.abs(s.cuspHeightMm - reply.exact.cuspHeightMm);
  const within = diff <= s.resolutionBoundMm;
  return words.comparison(
    fine(s.cuspHeightMm),
    fine(reply.exact.cuspHeightMm),
    fine(diff),
    within,
    fine(s.resolutionBoundMm),
    `${s.cellsAcross} x ${s.cellsAlong}`,
    s.passes,
  );
}

/** The view's words in the language in force (English: surfaceWords.ts). */
function words(): SurfaceWords {
  return catalogue()?.surface ?? EN_SURFACE;
}

/** A text with the language in force's decimal sign. */
function local(text: string): string {
  return localDecimal(text, catalogue());
}

export class SurfaceView implements TeachingView, SurfaceDisplay {
  readonly id = 'surface' as const;
  readonly title = 'Machined surface';
  readonly element = html('div', { class: 'surface-view', 'data-testid': 'surface-view' });
  private readonly status = html('p', { class: 'view-note', 'data-testid': 'surface-status', role: 'status' });
  /** Which surface is shown: the teeth's (with its question) or the continuous passes. */
  private readonly shownCaption = html('p', { class: 'view-note surface-shown', 'data-testid': 'surface-shown' });
  private readonly sceneBox = html('div', { class: 'surface-3d' });
  private readonly exaggerationNote = html('p', { class: 'view-note', 'data-testid': 'surface-exaggeration' });
  private readonly legend = svg('svg', {
    class: 'surface-legend',
    'data-testid': 'surface-legend',
    viewBox: '0 0 300 34',
  });
  private readonly trace = svg('svg', {
    class: 'surface-trace',
    'data-testid': 'surface-trace',
    viewBox: `0 0 ${TRACE_W} ${TRACE_H}`,
    role: 'img',
    'aria-label': EN_SURFACE.traceLabel,
  });
  private readonly comparison = html('p', { class: 'view-note', 'data-testid': 'surface-comparison' });
  private scene: SurfaceScene | null = null;
  private drawn: { reply: SimulateOk; unit: Unit } | null = null;
  /** The teeth's surface current for the inputs on screen (drawn instead of the passes), or null. */
  private teeth: TeethShown | null = null;
  /** The view is open (its simulation runs only then, and only while no teeth's surface is shown). */
  private visible = false;
  /** The simulation's last state told (drawn again when the teeth's surface goes). */
  private told: { shown: Shown<SimulateReply>; unit: Unit; progress: number | null } | null = null;
  /** The language the view's words were last written in ('en': English). */
  private wordedIn = 'en';

  constructor(private readonly source: SurfaceSource) {
    this.element.append(
      this.shownCaption,
      this.status,
      this.sceneBox,
      this.exaggerationNote,
      this.legend,
      this.trace,
      this.comparison,
    );
    source.attach(this);
    onTeethSurface((teeth) => {
      this.teeth = teeth;
      this.source.setOpen(this.visible && teeth === null);
      if (teeth !== null) this.drawTeeth(teeth);
      else if (this.told !== null) {
        this.drawn = null;
        this.show(this.told.shown, this.told.unit, this.told.progress);
      } else this.caption(null);
    });
  }

  /**
   * The teaching data is not used: the view follows the simulation's own replies. Called again on a
   * language switch (panel.ts relabel): the view's words are written anew in the language in force.
   */
  update(): void {
    const lang = catalogue()?.lang ?? 'en';
    if (lang === this.wordedIn) return;
    this.wordedIn = lang;
    this.speak();
    if (this.teeth !== null) this.drawTeeth(this.teeth);
    else if (this.told !== null) {
      const { shown, unit, progress } = this.told;
      if (this.drawn !== null) this.drawReply(this.drawn.reply, this.drawn.unit, true);
      this.show(shown, unit, progress);
    } else this.caption(null);
  }

  /** The view's fixed words (its names) in the language in force, and its `lang` (its part of the views). */
  private speak(): void {
    const w = words();
    this.trace.setAttribute('aria-label', w.traceLabel);
    this.sceneBox.querySelector('canvas')?.setAttribute('aria-label', w.sceneLabel);
    const lang = catalogue()?.lang;
    if (lang === undefined) this.element.removeAttribute('lang');
    else this.element.lang = lang;
  }

  highlight(_key: ProcedureKey | null): void {}

  setVisible(visible: boolean): void {
    if (visible && this.scene === null) {
      const scene = new SurfaceScene(this.sceneBox);
      this.scene = scene;
      this.speak();
      scene.applyTheme();
      onThemeChange(() => scene.applyTheme());
    }
    this.visible = visible;
    // The passes are simulated only while they are what the open view shows.
    this.source.setOpen(visible && this.teeth === null);
    if (visible && this.teeth !== null) this.drawTeeth(this.teeth);
    else if (visible && this.drawn) this.drawReply(this.drawn.reply, this.drawn.unit, true);
  }

  /** Frames the 3D view drew (tests). */
  get frames(): number {
    return this.scene?.frames ?? 0;
  }

  show(shown: Shown<SimulateReply>, unit: Unit, progress: number | null): void {
    this.told = { shown, unit, progress };
    // The teeth's surface answers the inputs on screen: the simulation's words wait behind it.
    if (this.teeth !== null) return;
    this.caption(null);
    const current = shown.kind === 'current' ? shown.reply : null;
    this.element.classList.toggle('stale', current === null || !current.ok);
    this.element.setAttribute('aria-busy', String(shown.kind === 'pending'));
    const w = words();
    let text = '';
    if (shown.kind === 'invalid') text = w.invalid;
    else if (shown.kind === 'failed') text = w.failed;
    else if (shown.kind === 'pending') text = w.pending(progress === null ? null : Math.round(100 * progress));
    else if (current && !current.ok)
      text =
        current.reason === null && current.errors.length > 0
          ? current.errors.map((e) => describeError(e, unit)).join(' ')
          : current.reasonCode !== undefined
            ? w.reasons[current.reasonCode]
            : current.reason === null
              ? w.reasons.none
              : exceptionIn(current.reason, w);
    if (this.status.textContent !== text) this.status.textContent = text;
    this.status.hidden = text === '';
    // An exception's own text, left out of the sentence in the language, in the hover title.
    setDetail(this.status, current && !current.ok && current.reason !== null ? exceptionDetail(current.reason, w) : '');
    if (current?.ok) {
      this.comparison.textContent = local(comparisonText(current, unit, w));
      this.drawReply(current, unit, false);
    } else {
      // Never a number that does not answer the inputs on screen.
      this.comparison.textContent = '';
    }
  }

  /**
   * Says which surface is shown: the teeth's, with its question (and how much longer lengths along
   * the feed are drawn, `stretch`), or the continuous passes.
   */
  private caption(teeth: TeethShown | null, stretch = 1): void {
    this.element.classList.toggle('teeth', teeth !== null);
    const phrase = (english: string) => {
      const span = html('span', {}, english);
      span.dataset.phrase = english;
      return span;
    };
    const parts: (HTMLElement | string)[] = [];
    if (teeth === null) parts.push(phrase('Continuous passes: the tool sweeps without teeth.'));
    else {
      const t = teeth.surface;
      const u = teeth.unit;
      parts.push(
        phrase("The teeth's surface (z teeth, fz per tooth, passes L apart; feed periods x pass periods shown):"),
        local(
          ` z = ${t.flutes}, fz = ${feedLength(t.feedPerToothMm, u)}, L = ${feedLength(t.intervalMm, u)}; ${t.feedPeriods} x ${t.crossPeriods}.`,
        ),
      );
      if (stretch > 1) parts.push(' ', phrase('Along the feed, lengths drawn longer by'), local(` x${stretch}.`));
    }
    // Its words follow the language: the key holds the language in force too.
    const key = `${catalogue()?.lang ?? 'en'} ${parts.map((p) => (typeof p === 'string' ? p : p.textContent)).join('')}`;
    if (this.shownCaption.dataset.english === key) return;
    this.shownCaption.dataset.english = key;
    this.shownCaption.replaceChildren(...parts);
    localize(this.shownCaption);
    // Inside the views (English, lang="en"), the caption speaks the language in force.
    const lang = catalogue()?.lang;
    if (lang === undefined) this.shownCaption.removeAttribute('lang');
    else this.shownCaption.lang = lang;
  }

  /**
   * Draws the teeth's surface: the ramp from its exact lowest point over its Sz, the legend 0 to Sz;
   * lengths along the feed drawn longer (a 1-2-5 factor, stated) so that the marks of a small fz show.
   */
  private drawTeeth(teeth: TeethShown): void {
    const t = teeth.surface;
    const across = t.acrossToMm - t.acrossFromMm;
    const stretch = autoExaggeration(across, t.alongLengthMm, 1);
    const drawn = { ...t, alongLengthMm: stretch * t.alongLengthMm };
    this.caption(teeth, stretch);
    this.element.classList.remove('stale');
    this.element.setAttribute('aria-busy', 'false');
    this.status.textContent = '';
    this.status.hidden = true;
    this.comparison.textContent = '';
    const k = autoExaggeration(Math.max(drawn.alongLengthMm, across), t.szMm, 0.12);
    this.exaggerationNote.textContent = local(
      words().exaggeration(k === 1 ? null : k, roughnessUnit(teeth.unit).symbol),
    );
    if (this.scene && !this.element.closest('[hidden]'))
      this.scene.update(drawn, k, { maxRows: t.cellsAlong, range: { lowMm: t.lowestMm, spanMm: t.szMm } });
    this.drawLegend(t.szMm, teeth.unit);
  }

  private drawReply(reply: SimulateOk, unit: Unit, force: boolean): void {
    if (!force && this.drawn?.reply === reply && this.drawn.unit === unit) return;
    this.drawn = { reply, unit };
    const s = reply.simulation;
    const size = Math.max(s.alongLengthMm, s.acrossToMm - s.acrossFromMm);
    let lo = Number.POSITIVE_INFINITY;
    let hi = Number.NEGATIVE_INFINITY;
    for (const z of s.heightsMm) {
      lo = Math.min(lo, z);
      hi = Math.max(hi, z);
    }
    const span = Number.isFinite(hi - lo) ? hi - lo : 0;
    const k = autoExaggeration(size, span, 0.12);
    this.exaggerationNote.textContent = local(words().exaggeration(k === 1 ? null : k, roughnessUnit(unit).symbol));
    if (this.scene && !this.element.closest('[hidden]')) this.scene.update(s, k);
    this.drawLegend(span, unit);
    this.drawTrace(reply, unit);
  }

  /** The colour ramp's legend: heights in the roughness' unit (µm, or µin in inch), as the trace's Rz. */
  private drawLegend(spanMm: number, unit: Unit): void {
    const defs = svg('defs');
    const gradient = svg('linearGradient', { id: 'surface-ramp', x1: 0, x2: 1, y1: 0, y2: 0 });
    HEIGHT_RAMP.forEach(([r, g, b], i) => {
      const c = `rgb(${Math.round(255 * r)},${Math.round(255 * g)},${Math.round(255 * b)})`;
      gradient.append(svg('stop', { offset: i / (HEIGHT_RAMP.length - 1), 'stop-color': c }));
    });
    defs.append(gradient);
    const bar = svg('rect', { x: 10, y: 2, width: 340, height: 12, fill: 'url(#surface-ramp)' });
    const label = (x: number, anchor: string, text: string) => {
      const t = svg('text', { x, y: 30, 'text-anchor': anchor });
      t.textContent = text;
      return t;
    };
    this.legend.replaceChildren(
      defs,
      bar,
      label(10, 'start', local(formatRoughness(0, unit))),
      label(180, 'middle', local(formatRoughness(spanMm / 2, unit))),
      label(350, 'end', local(formatRoughness(spanMm, unit))),
    );
  }

  private drawTrace(reply: SimulateOk, unit: Unit): void {
    const s = reply.simulation;
    const t = s.trace;
    const n = t.length / 2;
    const L = reply.exact.intervalMm;
    const yMin = t[0] ?? 0;
    const yMax = t[2 * (n - 1)] ?? 1;
    // Heights over the measured span (first to last contact) for Rz's peak and valley lines.
    let zLo = Number.POSITIVE_INFINITY;
    let zHi = Number.NEGATIVE_INFINITY;
    let zAllHi = 0;
    for (let j = 0; j < n; j++) {
      const y = t[2 * j] as number;
      const z = t[2 * j + 1] as number;
      zAllHi = Math.max(zAllHi, z);
      if (y >= 0 && y <= (s.passes - 1) * L) {
        zLo = Math.min(zLo, z);
        zHi = Math.max(zHi, z);
      }
    }
    if (!Number.isFinite(zLo)) zLo = zHi = 0;
    const top = Math.max(zAllHi, zHi, 1e-12);
    const w = TRACE_W - PAD.left - PAD.right;
    const h = TRACE_H - PAD.top - PAD.bottom;
    const X = (y: number) => PAD.left + ((y - yMin) / (yMax - yMin || 1)) * w;
    const Z = (z: number) => PAD.top + h - (Math.min(z, top) / top) * h;
    const points: string[] = [];
    for (let j = 0; j < n; j++)
      points.push(`${X(t[2 * j] as number).toFixed(1)},${Z(t[2 * j + 1] as number).toFixed(1)}`);
    // Roughness as the results' rows give it (format.ts: µm in mm, µin in inch).
    const fine = (mm: number) => local(formatRoughness(mm, unit));
    const said = words();
    const r = s.roughness;
    const e = reply.exact.roughness;
    const line = (z: number, cls: string) =>
      svg('line', { x1: PAD.left, x2: PAD.left + w, y1: Z(z).toFixed(1), y2: Z(z).toFixed(1), class: cls });
    const text = (z: number, cls: string, label: string, dy = 4) => {
      const el = svg('text', { x: PAD.left + w + 6, y: (Z(z) + dy).toFixed(1), class: cls });
      el.textContent = label;
      return el;
    };
    const m = r.meanMm;
    const caption = svg('text', { x: PAD.left, y: TRACE_H - 4, class: 'trace-caption' });
    caption.textContent = said.traceCaption(s.passes, fine(e.rzMm), fine(e.raMm), fine(e.rqMm));
    this.trace.replaceChildren(
      line(zHi, 'rz'),
      line(zLo, 'rz'),
      line(m + r.rqMm, 'rq'),
      line(Math.max(0, m - r.rqMm), 'rq'),
      line(m + r.raMm, 'ra'),
      line(Math.max(0, m - r.raMm), 'ra'),
      line(m, 'mean'),
      svg('polyline', { points: points.join(' '), class: 'trace-line' }),
      text(zHi, 'rz', `Rz ${fine(r.rzMm)}`, 10),
      text(m + r.rqMm, 'rq', `Rq ${fine(r.rqMm)}`, -3),
      text(m + r.raMm, 'ra', `Ra ${fine(r.raMm)}`, 11),
      text(m, 'mean', said.meanLine),
      caption,
    );
  }
}
