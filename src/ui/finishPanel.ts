/**
 * The finish box under the results (issue 29): beside the scallop h and Ra across the feed, the
 * feed marks hf along it and the areal Sa; the balanced feed fz* with a one-tap "use the balanced
 * feed"; the areal parameters Sa ... Sku; an x3p download of one period cell. Everything is the
 * worker's answer (jobs/finish.ts) to the question the inputs on screen ask (finishRequest.ts),
 * shown only while its request is still that question (dashes meanwhile, never an earlier input's
 * number); a refusal (a bad value, a surface where feed marks are not computed) is one line.
 * Loaded with its first question (finishLazy.ts), not with the first result.
 */
import type { FinishSurfaceKind } from '../core/finish/finishScope';
import { type LengthUnit, NO_VALUE } from '../core/input/units';
import type { RestartInfo } from '../worker/client';
import {
  type FinishFieldMessage,
  type FinishReply,
  type FinishRequest,
  MAP_SIZE,
  sameFinishRequest,
} from '../worker/finishProtocol';
import type { PageReply } from '../worker/pageProtocol';
import type { finishClient } from '../worker/workers';
import { detailsRow, html } from './dom';
import { feedLength } from './finishLength';
import { FinishProfileCharts } from './finishProfileCharts';
import { type FinishInputs, finishAsk, x3pFileName } from './finishRequest';
import { EN_FINISH } from './finishWords';
import { formatRoughness } from './format';
import type { FinishWords } from './i18n/catalogue';
import { finishMessageIn, finishScopeIn } from './i18n/finishText';
import { localDecimal } from './i18n/langChoice';
import { catalogue, localize } from './i18n/words';
import { reasonDetail, reasonIn, setDetail } from './i18n/workerReason';
import { balancedFeedFields } from './shopFeed';
import { publishTeethSurface } from './teethMap';

/** Points along each side of the x3p download's one cell (the 256 x 256). */
export const X3P_SIZE = 256;

/** The areal parameters' rows after Sa (shown once, beside Ra above them); their titles' words in finishWords.ts. */
const AREAL = ['Sq', 'Sz', 'Sp', 'Sv', 'Ssk', 'Sku'] as const;

/** The box's own sentences in the language in force (English: finishWords.ts). */
function words(): Pick<FinishWords, keyof typeof EN_FINISH> {
  return catalogue()?.finishText ?? EN_FINISH;
}

/**
 * An output of the box, not a live region of its own (an <output> is one by default): the box's one
 * live region says the answer once it is complete, not each number as it changes.
 */
function quietOutput(testId: string): HTMLOutputElement {
  return html('output', { 'data-testid': testId, 'aria-live': 'off' }, NO_VALUE);
}

/** A dimensionless number to 4 decimals, never -0. */
function plain(v: number): string {
  const t = v.toFixed(4);
  return Number(t) === 0 ? (0).toFixed(4) : t;
}

/** The finish box (see the module comment). */
export class FinishPanel {
  private readonly outputs = new Map<string, HTMLOutputElement>();
  private readonly message: HTMLElement;
  /** The polite live region (see the constructor). */
  private readonly live: HTMLElement;
  private readonly useBalanced: HTMLButtonElement;
  private readonly download: HTMLButtonElement;
  private readonly x3pStatus: HTMLElement;
  private wanted: FinishRequest | null = null;
  /** The latest answer of each part (shown only while it answers the question on screen). */
  private readonly answers = new Map<FinishRequest['part'], Extract<FinishReply, { ok: true }>>();
  /** The surface where feed marks are not computed, and the core's English line. */
  private refusal: { readonly surface: FinishSurfaceKind; readonly english: string } | null = null;
  /** The worker's refusal of a question (a bad value), with the question. */
  private failed: {
    readonly request: FinishRequest;
    readonly errors: readonly FinishFieldMessage[];
  } | null = null;
  /** The field messages last told to the page (JSON), so that it is told only of a change. */
  private toldFields = '[]';
  /** The parts that hold an answer (hidden while the surface is refused: its one line stands alone). */
  private answerParts: readonly HTMLElement[] = [];
  private raMm: number | null = null;
  private unit: LengthUnit = 'mm';
  /** The finish fields on screen (the balanced feed sets fz, or F at the spindle speed given). */
  private inputs: FinishInputs | null = null;
  /** The x3p asked (the question with its file), until its bytes come. */
  private x3pAsked: FinishRequest | null = null;
  /** The feed marks' worker and the areal parameters' (slower: they never hold the marks back). */
  private readonly client: ReturnType<typeof finishClient>;
  private readonly arealClient: ReturnType<typeof finishClient>;
  /** The cell's height map (issue 29: one cell, coloured by height, with its scale). */
  private readonly figure: HTMLElement;
  private readonly canvas: HTMLCanvasElement;
  private readonly scale: HTMLElement;
  /** The profiles along and across the feed (with the areal answer). */
  private readonly profiles: FinishProfileCharts;
  /** The map on the canvas (its reply), so that it is painted once. */
  private painted: Extract<FinishReply, { ok: true }> | null = null;
  /** The part each client computes now (until its reply). */
  private readonly busy = new Map<ReturnType<typeof finishClient>, FinishRequest>();
  /** A worker's restart or give-up (the worker's reason), said while the question on screen waits. */
  private note: { readonly gaveUp: boolean; readonly reason: string } | null = null;
  /** The x3p line: computing, none (the worker's refusals, or null), gave up, saved; or nothing yet. */
  private x3pLine:
    | { readonly kind: 'computing' }
    | { readonly kind: 'none'; readonly errors: readonly FinishFieldMessage[] | null }
    | { readonly kind: 'gaveUp'; readonly reason: string }
    | { readonly kind: 'saved'; readonly fileName: string; readonly size: number }
    | null = null;
  private x3pClient: ReturnType<typeof finishClient> | null = null;
  /** The areal rows' list (their titles follow the language). */
  private readonly arealList: HTMLElement;

  /** `clientOf`: workers.ts finishClient (the first script's, passed in). */
  constructor(
    private readonly box: HTMLElement,
    /** "use the balanced feed": the fields it sets (fz in mm, or the feed rate F in mm/min). */
    private readonly onFeed: (fields: { readonly fz: number } | { readonly F: number }) => void,
    private readonly clientOf: typeof finishClient,
    /** The worker's messages on the finish fields that answer the inputs on screen (shown on the fields too). */
    private readonly onFieldErrors: (errors: readonly FinishFieldMessage[]) => void = () => {},
  ) {
    this.client = clientOf(
      { onReply: (reply) => this.received(reply), onRestart: (info) => this.restarted(info) },
      sameFinishRequest,
    );
    this.arealClient = clientOf(
      { onReply: (reply) => this.received(reply), onRestart: (info) => this.restarted(info) },
      sameFinishRequest,
    );
    const list = html('dl', { class: 'details finish-details' });
    const row = (label: string, testId: string, title = '') => {
      const out = quietOutput(testId);
      this.outputs.set(testId, out);
      const { row: line, dd } = detailsRow(list, label, out, title === '' ? {} : { title });
      (line.firstElementChild as HTMLElement).dataset.phrase = label;
      return dd;
    };
    row('Scallop h (across the feed)', 'finish-h');
    row('Feed marks hf (along the CC path)', 'finish-hf');
    row('Ra (across the feed)', 'finish-ra');
    row('Sa (areal)', 'finish-sa');
    row('Feed period', 'finish-period');
    const balanced = row('Balanced feed fz* (hf = h)', 'finish-balanced');
    this.useBalanced = html(
      'button',
      {
        type: 'button',
        'data-testid': 'use-balanced-feed',
        'aria-disabled': 'true',
        'data-phrase': 'use the balanced feed',
      },
      'use the balanced feed',
    );
    balanced.append(' ', this.useBalanced);
    this.useBalanced.addEventListener('click', () => {
      if (this.useBalanced.getAttribute('aria-disabled') === 'true') return;
      const fz = this.answer('marks')?.feedMarks?.balancedFz;
      if (fz !== undefined && fz !== null && this.inputs !== null) this.onFeed(balancedFeedFields(fz, this.inputs));
    });
    const areal = html('dl', { class: 'details finish-areal', 'data-testid': 'finish-areal' });
    for (const symbol of AREAL) {
      const out = quietOutput(`finish-areal-${symbol}`);
      this.outputs.set(symbol, out);
      detailsRow(areal, symbol, out, { title: EN_FINISH.areal[symbol] });
    }
    this.arealList = areal;
    this.message = html('p', { class: 'finish-message', 'data-testid': 'finish-message' });
    // The box's one live region: what it waits for, why it refuses, or its answer once complete.
    this.live = html('p', { class: 'sr-only', 'data-testid': 'finish-live', role: 'status' });
    this.download = html(
      'button',
      { type: 'button', 'data-testid': 'download-x3p', disabled: '', 'data-phrase': 'Download x3p' },
      'Download x3p',
    );
    this.download.addEventListener('click', () => this.askX3p());
    this.x3pStatus = html('span', { class: 'lookup-note', 'data-testid': 'x3p-status', role: 'status' });
    const heading = html(
      'h2',
      { class: 'finish-title', 'data-phrase': 'Finish: the feed marks the teeth leave' },
      'Finish: the feed marks the teeth leave',
    );
    const noteText =
      'Areal parameters over one period cell (ISO 25178-2, no filter, the design plane as reference); straight teeth, M3. The x3p file holds that cell, 256 x 256 heights (ISO 25178-72).';
    const note = html('p', { class: 'lookup-note', 'data-phrase': noteText }, noteText);
    this.figure = html('figure', { class: 'finish-map', 'data-testid': 'finish-map', hidden: '' });
    this.canvas = html('canvas', {
      width: String(MAP_SIZE),
      height: String(MAP_SIZE),
      'data-testid': 'finish-map-image',
      role: 'img',
      'aria-label': EN_FINISH.mapLabel,
    });
    this.scale = html('figcaption', { 'data-testid': 'finish-map-scale' });
    this.figure.append(this.canvas, this.scale);
    this.profiles = new FinishProfileCharts();
    const tools = html('div', { class: 'finish-tools' });
    tools.append(this.download, ' ', this.x3pStatus);
    box.append(heading, list, areal, this.message, this.live, this.figure, this.profiles.element, note, tools);
    this.answerParts = [list, areal, note, tools];
  }

  /** The inputs on screen and the answer to them (null while none is, or while typing). */
  show(inputs: FinishInputs, reply: PageReply | null): void {
    this.unit = inputs.unit;
    this.inputs = inputs;
    this.box.hidden = !inputs.given;
    const ask = finishAsk(inputs, reply);
    this.refusal = ask.kind === 'refused' ? { surface: ask.surface, english: ask.message } : null;
    const request = ask.kind === 'ask' ? ask.request : null;
    this.raMm = ask.kind === 'ask' ? ask.raMm : null;
    if (!sameFinishRequest(request, this.wanted)) {
      this.wanted = request;
      this.note = null;
      // The line of a file saved (or refused) belongs to the question it answered: gone with it.
      if (this.x3pAsked === null && this.x3pLine !== null) {
        this.x3pLine = null;
        this.x3pStatus.textContent = '';
      }
      if (request !== null) {
        this.ask(this.client, request);
        this.ask(this.arealClient, { ...request, part: 'areal' });
      }
    }
    this.draw();
  }

  /**
   * Asks `client` a part; a worker still busy with an earlier question is ended first (the core's
   * areal parameters can take minutes at a large feed: nobody waits for them any more).
   */
  private ask(client: ReturnType<typeof finishClient>, request: FinishRequest): void {
    const busy = this.busy.get(client);
    if (busy !== undefined && !sameFinishRequest(busy, request)) client.dispose();
    this.busy.set(client, request);
    client.request(request);
  }

  /** True when `request` is the question on screen (its feed marks or its areal parameters). */
  private current(request: FinishRequest): boolean {
    return this.wanted !== null && sameFinishRequest(request, { ...this.wanted, part: request.part });
  }

  private received(reply: FinishReply): void {
    for (const [client, asked] of this.busy) if (sameFinishRequest(asked, reply.request)) this.busy.delete(client);
    if (reply.request.x3p !== undefined || !this.current(reply.request)) return;
    this.note = null;
    if (reply.ok) this.answers.set(reply.request.part, reply);
    else this.failed = { request: reply.request, errors: reply.errors };
    this.draw();
  }

  /** The answer of one part to the question on screen, or null. */
  private answer(part: FinishRequest['part']): Extract<FinishReply, { ok: true }> | null {
    const a = this.answers.get(part);
    return a !== undefined && this.current(a.request) ? a : null;
  }

  private restarted(info: RestartInfo<FinishRequest>): void {
    if (info.request === null || !this.current(info.request)) return;
    this.note = { gaveUp: info.gaveUp, reason: info.reason };
    this.draw();
  }

  private set(key: string, text: string): void {
    const e = this.outputs.get(key);
    if (e !== undefined && e.textContent !== text) e.textContent = text;
  }

  /** Draws the answer to the question on screen (or dashes), or its refusal in one line. */
  private draw(): void {
    const marks = this.answer('marks');
    const m = marks?.feedMarks ?? undefined;
    const s = this.answer('areal')?.areal ?? undefined;
    const u = this.unit;
    const height = (mm: number | undefined) => formatRoughness(mm ?? null, u);
    this.set('finish-h', height(marks?.request.scallopMm));
    this.set('finish-ra', height(marks === null ? undefined : (this.raMm ?? undefined)));
    this.set('finish-hf', height(m?.height));
    this.set('finish-sa', height(s?.Sa));
    this.set('finish-period', feedLength(m?.period ?? null, u));
    this.set(
      'finish-balanced',
      m === undefined
        ? NO_VALUE
        : m.balancedFz === null
          ? 'none: hf stays below h at every fz up to R'
          : feedLength(m.balancedFz, u),
    );
    for (const symbol of AREAL)
      this.set(
        symbol,
        s === undefined ? NO_VALUE : symbol === 'Ssk' || symbol === 'Sku' ? plain(s[symbol]) : height(s[symbol]),
      );
    // aria-disabled, not disabled: a press keeps the focus on the button while the new answer comes.
    this.useBalanced.setAttribute('aria-disabled', String(m === undefined || m.balancedFz === null));
    const balanced = this.outputs.get('finish-balanced');
    if (balanced !== undefined && m !== undefined && m.balancedFz === null)
      balanced.dataset.phrase = balanced.textContent ?? '';
    else if (balanced !== undefined) delete balanced.dataset.phrase;
    for (const part of this.answerParts) part.hidden = this.refusal !== null;
    // No file where the areal surface is refused (a flat end lying flat leaves slivers no tooth cuts).
    const arealRefused =
      this.failed !== null && this.failed.request.part === 'areal' && this.current(this.failed.request);
    this.download.disabled = marks === null || this.x3pAsked !== null || arealRefused;
    // The worker's refusals worded in the language in force (finishText.ts), on their fields too.
    const c = catalogue();
    const errors = this.failed !== null && this.current(this.failed.request) ? this.failed.errors : null;
    const worded = (errors ?? []).map((e) => ({ ...e, message: finishMessageIn(c, e, u) }));
    const failed = errors === null ? null : worded.map((e) => e.message).join(' ');
    const refusal = this.refusal === null ? null : finishScopeIn(c, this.refusal.surface, this.refusal.english);
    // The same messages on their fields (a bad fz is named where it was typed), only while current.
    const fieldErrors = worded;
    const told = JSON.stringify(fieldErrors);
    if (told !== this.toldFields) {
      this.toldFields = told;
      this.onFieldErrors(fieldErrors);
    }
    const pending = this.wanted !== null && (m === undefined || s === undefined);
    this.paint(this.answer('areal'));
    // The Machined surface view draws the teeth's surface while it answers the inputs on screen.
    const surface = this.refusal === null ? this.answer('areal')?.surface : undefined;
    publishTeethSurface(surface === undefined || surface === null ? null : { surface, unit: this.unit });
    this.profiles.show(this.refusal === null ? (this.answer('areal')?.profiles ?? null) : null, this.unit);
    // The worker's reason in the language in force (an exception's own text kept).
    const note = this.note === null ? null : words().worker(this.note.gaveUp, reasonIn(this.note.reason, catalogue()));
    const waiting = pending
      ? (note ??
        (m === undefined
          ? 'Computing the feed marks and the areal parameters...'
          : 'Computing the areal parameters...'))
      : '';
    const text = refusal ?? failed ?? waiting;
    if (this.message.textContent !== text) this.message.textContent = text;
    // An exception's own text, left out of the reason worded in the language, in the hover title.
    setDetail(this.message, text === note && this.note !== null ? reasonDetail(this.note.reason, c) : '');
    // The waiting lines are the box's own words (put into the language in force); a refusal is the worker's.
    if (text === waiting && text !== '' && this.note === null) this.message.dataset.phrase = text;
    else delete this.message.dataset.phrase;
    const gaveUp = pending && this.note?.gaveUp === true;
    this.message.classList.toggle('error', this.refusal !== null || failed !== null || gaveUp);
    localize(this.box);
    this.wordOwn();
    // Said once complete: the message while there is one, else the answer's main rows (as localized).
    const said = text !== '' || this.wanted === null ? text : this.summary();
    if (this.live.textContent !== said) this.live.textContent = said;
  }

  /** The answer's main rows, label and value as shown (in the language in force): hf, Sa, fz*. */
  private summary(): string {
    return ['finish-hf', 'finish-sa', 'finish-balanced']
      .map((id) => {
        const out = this.outputs.get(id);
        const label = out?.closest('dd')?.previousElementSibling?.textContent ?? '';
        return `${label}: ${out?.textContent ?? ''}`;
      })
      .join('; ');
  }

  /**
   * Paints the areal answer's map (hidden without one): heights from the lowest (blue) to the
   * highest (orange), x along the feed to the right, y across it downwards, and its scale in words.
   */
  private paint(areal: Extract<FinishReply, { ok: true }> | null): void {
    const map = areal?.map ?? null;
    this.figure.hidden = map === null;
    if (areal === null || map === null) return;
    const r = areal.request;
    const u = this.unit;
    const period = this.answer('marks')?.feedMarks?.period ?? null;
    const across = r.intervalMm * (r.pattern === 'zigzag' ? 2 : 1);
    const text = localDecimal(
      words().mapScale(
        feedLength(period, u),
        feedLength(across, u),
        formatRoughness(areal.areal === null ? null : areal.areal.Sz, u),
      ),
      catalogue(),
    );
    if (this.scale.textContent !== text) this.scale.textContent = text;
    if (this.painted === areal) return;
    this.painted = areal;
    let low = Number.POSITIVE_INFINITY;
    let high = Number.NEGATIVE_INFINITY;
    for (const h of map) {
      low = Math.min(low, h);
      high = Math.max(high, h);
    }
    const span = high > low ? high - low : 1;
    const context = this.canvas.getContext('2d');
    if (context !== null) {
      const image = context.createImageData(MAP_SIZE, MAP_SIZE);
      map.forEach((h, k) => {
        const t = (h - low) / span;
        image.data.set([29 + t * (245 - 29), 78 + t * (158 - 78), 216 + t * (11 - 216), 255], 4 * k);
      });
      context.putImageData(image, 0, 0);
    }
  }

  /** The x3p of the question on screen: computed in the worker, saved when its bytes come. */
  private askX3p(): void {
    const current = this.answer('marks');
    if (current === null || this.x3pAsked !== null) return;
    const r = current.request;
    const fileName = x3pFileName(r);
    const request: FinishRequest = { ...r, x3p: { size: X3P_SIZE, fileName, comment: fileName.replace(/\.x3p$/, '') } };
    this.x3pAsked = request;
    this.download.disabled = true;
    this.x3pLine = { kind: 'computing' };
    this.wordOwn();
    this.x3pClient ??= this.clientOf(
      {
        onReply: (reply) => this.savedX3p(reply),
        onRestart: (info) => {
          if (!info.gaveUp) return;
          this.x3pAsked = null;
          this.x3pLine = { kind: 'gaveUp', reason: info.reason };
          this.wordOwn();
        },
      },
      sameFinishRequest,
    );
    this.x3pClient.request(request);
  }

  private savedX3p(reply: FinishReply): void {
    if (!sameFinishRequest(reply.request, this.x3pAsked)) return;
    this.x3pAsked = null;
    this.draw();
    const file = reply.request.x3p;
    if (!reply.ok || reply.x3p === null || file === undefined) {
      this.x3pLine = { kind: 'none', errors: reply.ok ? null : reply.errors };
      this.wordOwn();
      return;
    }
    const url = URL.createObjectURL(new Blob([reply.x3p as BlobPart], { type: 'application/zip' }));
    const link = document.createElement('a');
    link.href = url;
    link.download = file.fileName;
    document.body.append(link);
    link.click();
    link.remove();
    setTimeout(() => URL.revokeObjectURL(url), 10_000);
    this.x3pLine = { kind: 'saved', fileName: file.fileName, size: file.size };
    this.wordOwn();
  }

  /**
   * The box's own words that are not a `data-phrase` (finish words of the catalogue): the areal
   * rows' titles, the map's name, the x3p line; in the language in force.
   */
  private wordOwn(): void {
    const w = words();
    for (const dt of this.arealList.querySelectorAll<HTMLElement>('dt')) {
      const title = w.areal[dt.textContent as (typeof AREAL)[number]];
      const row = dt.parentElement;
      if (title !== undefined && row !== null && row.title !== title) row.title = title;
    }
    if (this.canvas.getAttribute('aria-label') !== w.mapLabel) this.canvas.setAttribute('aria-label', w.mapLabel);
    const line = this.x3pLine;
    const c = catalogue();
    const text =
      line === null
        ? (this.x3pStatus.textContent ?? '')
        : line.kind === 'computing'
          ? w.x3pComputing
          : line.kind === 'gaveUp'
            ? w.x3pGaveUp(reasonIn(line.reason, c))
            : line.kind === 'saved'
              ? w.x3pSaved(line.fileName, line.size)
              : w.x3pNone(
                  line.errors === null ? null : line.errors.map((e) => finishMessageIn(c, e, this.unit)).join(' '),
                );
    if (this.x3pStatus.textContent !== text) this.x3pStatus.textContent = text;
    setDetail(this.x3pStatus, line?.kind === 'gaveUp' ? reasonDetail(line.reason, c) : '');
  }
}
