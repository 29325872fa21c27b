/**
 * The target-Sa box (issue 29: "the inverse (target Sa) offered beside target Ra, with the curve of
 * pairs as a chart and the best pair marked"): for the Sa given, the pair (step-over L, feed per
 * tooth fz) with the largest L * fz as its headline, the Sa it leaves and the scallop h at that L as
 * its details, the curve of all pairs as a chart (L across, fz up, in the unit on screen) with the
 * best pair marked and its end L0 (fz -> 0, where Ra = Sa: the step-over the results above show),
 * and "use this pair", which puts L and fz into the inputs (solving for the scallop height at that
 * L: the results, the feed marks and the areal parameters then follow the pair as programmed).
 * Everything is the worker's answer (jobs/targetSa.ts, seconds of work: a waiting line meanwhile) to
 * the question the inputs on screen ask (targetSaRequest.ts), shown only while its request is still
 * that question (dashes meanwhile, never an earlier input's number). Loaded on the first target Sa.
 */
import { fromMm, type LengthUnit, NO_VALUE, unitSymbol } from '../core/input/units';
import { JobClient, type RestartInfo } from '../worker/client';
import type { FinishFieldMessage } from '../worker/finishProtocol';
import type { PageReply } from '../worker/pageProtocol';
import { sameTargetSaRequest, type TargetSaReply, type TargetSaRequest } from '../worker/targetSaProtocol';
import { FINISH_WATCHDOG_MS, startSolverWorker } from '../worker/workers';
import { detailsRow, html } from './dom';
import { feedLength } from './finishLength';
import type { FinishInputs } from './finishRequest';
import { formatLen, formatRoughness } from './format';
import { targetSaMessageIn } from './i18n/finishText';
import { catalogue, localize } from './i18n/words';
import { reasonDetail, reasonIn, setDetail } from './i18n/workerReason';
import { shopFeed } from './shopFeed';
import { targetSaAsk } from './targetSaRequest';
import { lineChart } from './views/lineChart';
import './views/chart.css';

/** The box's words (catalogue FinishPhrase). */
const TITLE = 'Target Sa: the best step-over and feed per tooth';
const WAITING = 'Computing the pairs of step-over and feed per tooth that leave this Sa (a few seconds)...';
const USE = 'use this pair';
const NOTE =
  'The pair with the largest L * fz (the area machined per tooth: the fastest finish at a given spindle speed) among those whose areal Sa is the target (plane, straight teeth, no runout). "use this pair" solves for the scallop height at that L with that fz, both rounded down.';
const CURVE = 'Every pair that leaves this Sa: the dot is the best, the curve ends at L0 where fz -> 0';

/** The worker's restart in the language in force (English here; the worker's reason worded by workerReason.ts). */
function restartWords(gaveUp: boolean, reason: string): string {
  const words = catalogue()?.finishText.targetSa;
  if (words !== undefined) return words.worker(gaveUp, reasonIn(reason, catalogue()));
  return gaveUp
    ? `No pair: its worker gave up (${reason}).`
    : `The target Sa's worker was restarted (${reason}); computing again...`;
}

/** A reply that answers. */
type Answered = Extract<TargetSaReply, { ok: true }>;

/** An output of the box, not a live region of its own (the box has one). */
function quietOutput(testId: string): HTMLOutputElement {
  return html('output', { 'data-testid': testId, 'aria-live': 'off' }, NO_VALUE);
}

/** The target-Sa box (see the module comment). */
export class TargetSaPanel {
  private readonly outputs = new Map<string, HTMLOutputElement>();
  private readonly message: HTMLElement;
  private readonly live: HTMLElement;
  private readonly use: HTMLButtonElement;
  private readonly figure: HTMLElement;
  private readonly answerParts: readonly HTMLElement[];
  /** The `targetSa` job on its own worker (seconds of work: the finish's watchdog). */
  private readonly client: JobClient<TargetSaRequest, TargetSaReply>;
  private wanted: TargetSaRequest | null = null;
  private busy: TargetSaRequest | null = null;
  private answer: Answered | null = null;
  private failed: Extract<TargetSaReply, { ok: false }> | null = null;
  /** The worker's restart (gave up, its reason), worded when drawn. */
  private note: { readonly gaveUp: boolean; readonly reason: string } | null = null;
  private unit: LengthUnit = 'mm';
  /** The chart drawn (its answer and unit), so that it is drawn once. */
  private charted: { answer: Answered; unit: LengthUnit } | null = null;
  /** The field messages last told to the page (JSON), so that it is told only of a change. */
  private toldFields = '[]';

  constructor(
    private readonly box: HTMLElement,
    /** "use this pair": the step-over L and fz (mm), as a shop types them. */
    private readonly onUse: (pair: { readonly L: number; readonly fz: number }) => void,
    /** The worker's messages on the teeth fields that answer the inputs on screen. */
    private readonly onFieldErrors: (errors: readonly FinishFieldMessage[]) => void,
  ) {
    this.client = new JobClient<TargetSaRequest, TargetSaReply>({
      createWorker: () => startSolverWorker('path-interval-target-sa'),
      call: (api, r) => api.targetSa(r),
      same: sameTargetSaRequest,
      onReply: (reply) => this.received(reply),
      onRestart: (info) => this.restarted(info),
      watchdogMs: FINISH_WATCHDOG_MS,
    });
    const heading = html('h2', { class: 'finish-title', 'data-phrase': TITLE }, TITLE);
    const list = html('dl', { class: 'details finish-details' });
    const row = (label: string, testId: string) => {
      const out = quietOutput(testId);
      this.outputs.set(testId, out);
      const { row: line, dd } = detailsRow(list, label, out);
      (line.firstElementChild as HTMLElement).dataset.phrase = label;
      return dd;
    };
    row('Step-over L', 'target-sa-interval');
    const fz = row('Feed per tooth fz', 'target-sa-fz');
    this.use = html(
      'button',
      { type: 'button', 'data-testid': 'use-target-sa-pair', 'aria-disabled': 'true', 'data-phrase': USE },
      USE,
    );
    fz.append(' ', this.use);
    this.use.addEventListener('click', () => {
      const a = this.current();
      if (a === null) return;
      this.onUse({
        L: shopFeed(a.answer.best.intervalMm, this.unit),
        fz: shopFeed(a.answer.best.feedPerToothMm, this.unit),
      });
    });
    row('L * fz (area per tooth)', 'target-sa-area');
    row('Sa it leaves', 'target-sa-sa');
    row('Scallop h at this L', 'target-sa-h');
    row('L0 (fz -> 0: Ra = Sa)', 'target-sa-l0');
    this.figure = html('figure', { class: 'finish-profile', 'data-testid': 'target-sa-curve', hidden: '' });
    this.figure.append(html('figcaption', { id: 'target-sa-curve-caption', 'data-phrase': CURVE }, CURVE));
    this.message = html('p', { class: 'finish-message', 'data-testid': 'target-sa-message' });
    this.live = html('p', { class: 'sr-only', 'data-testid': 'target-sa-live', role: 'status' });
    const note = html('p', { class: 'lookup-note', 'data-phrase': NOTE }, NOTE);
    box.append(heading, list, this.message, this.live, this.figure, note);
    this.answerParts = [list, note];
  }

  /** The inputs on screen and the answer to them (null while none is, or while typing); `active`: target Sa chosen. */
  show(inputs: FinishInputs, reply: PageReply | null, active: boolean): void {
    this.unit = inputs.unit;
    this.box.hidden = !active;
    const request = active ? targetSaAsk(inputs, reply) : null;
    if (!sameTargetSaRequest(request, this.wanted)) {
      this.wanted = request;
      this.note = null;
      // A worker still busy with another question is ended (nobody waits for it any more); one busy
      // with this very question (asked again after a pause in typing) is left to finish it.
      if (request !== null && !sameTargetSaRequest(request, this.busy)) {
        if (this.busy !== null) this.client.dispose();
        this.busy = request;
        this.client.request(request);
      }
    }
    this.draw();
  }

  private received(reply: TargetSaReply): void {
    if (sameTargetSaRequest(reply.request, this.busy)) this.busy = null;
    // Shown only while it answers the question on screen (its request echoed).
    if (!sameTargetSaRequest(reply.request, this.wanted)) return;
    this.note = null;
    if (reply.ok) this.answer = reply;
    else this.failed = reply;
    this.draw();
  }

  private restarted(info: RestartInfo<TargetSaRequest>): void {
    if (info.request === null || !sameTargetSaRequest(info.request, this.wanted)) return;
    this.note = { gaveUp: info.gaveUp, reason: info.reason };
    this.draw();
  }

  /** The answer to the question on screen, or null. */
  private current(): Answered | null {
    return this.answer !== null && sameTargetSaRequest(this.answer.request, this.wanted) ? this.answer : null;
  }

  private set(key: string, text: string): void {
    const e = this.outputs.get(key);
    if (e !== undefined && e.textContent !== text) e.textContent = text;
  }

  /** Draws the answer to the question on screen (or dashes), or its refusal in one line. */
  private draw(): void {
    const a = this.current();
    const u = this.unit;
    const best = a?.answer.best ?? null;
    this.set('target-sa-interval', best === null ? NO_VALUE : feedLength(best.intervalMm, u));
    this.set('target-sa-fz', best === null ? NO_VALUE : feedLength(best.feedPerToothMm, u));
    const area = best === null ? null : fromMm(fromMm(best.intervalMm * best.feedPerToothMm, u), u);
    const areaText = area === null ? NO_VALUE : formatLen(area, 'mm', 'fine');
    this.set('target-sa-area', area === null ? NO_VALUE : `${areaText} ${unitSymbol(u)}²`);
    this.set('target-sa-sa', formatRoughness(best?.saMm ?? null, u));
    this.set('target-sa-h', formatRoughness(a?.answer.bestScallopHeightMm ?? null, u));
    this.set('target-sa-l0', a === null ? NO_VALUE : feedLength(a.answer.zeroFeedIntervalMm, u));
    this.use.setAttribute('aria-disabled', String(a === null));
    // The worker's refusals worded in the language in force (finishText.ts), on their fields too.
    const c = catalogue();
    const errors =
      this.failed !== null && sameTargetSaRequest(this.failed.request, this.wanted)
        ? this.failed.errors.map((e) => ({ ...e, message: targetSaMessageIn(c, e, u) }))
        : null;
    const failed = errors === null ? null : errors.map((e) => e.message).join(' ');
    const told = JSON.stringify(errors);
    if (told !== this.toldFields) {
      this.toldFields = told;
      this.onFieldErrors(errors ?? []);
    }
    for (const part of this.answerParts) part.hidden = failed !== null;
    this.chart(failed === null ? a : null);
    const note = this.note === null ? null : restartWords(this.note.gaveUp, this.note.reason);
    const waiting = this.wanted !== null && a === null && failed === null ? (note ?? WAITING) : '';
    const text = failed ?? waiting;
    if (this.message.textContent !== text) this.message.textContent = text;
    // An exception's own text, left out of the reason worded in the language, in the hover title.
    setDetail(this.message, text === note && this.note !== null ? reasonDetail(this.note.reason, catalogue()) : '');
    if (text === WAITING) this.message.dataset.phrase = text;
    else delete this.message.dataset.phrase;
    this.message.classList.toggle('error', failed !== null || this.note?.gaveUp === true);
    this.box.setAttribute('aria-busy', String(waiting !== ''));
    localize(this.box);
    const said = text !== '' || a === null ? text : this.summary();
    if (this.live.textContent !== said) this.live.textContent = said;
  }

  /** The answer's headline, as shown: the pair and the Sa it leaves. */
  private summary(): string {
    return ['target-sa-interval', 'target-sa-fz', 'target-sa-sa']
      .map((id) => {
        const out = this.outputs.get(id);
        const label = out?.closest('dd')?.previousElementSibling?.textContent ?? '';
        return `${label}: ${out?.textContent ?? ''}`;
      })
      .join('; ');
  }

  /** The curve of pairs (L across, fz up, in the unit on screen), the best pair a dot and a dashed line, ending at (L0, 0). */
  private chart(a: Answered | null): void {
    this.figure.hidden = a === null;
    if (a === null || (this.charted?.answer === a && this.charted.unit === this.unit)) return;
    const unit = this.unit;
    this.charted = { answer: a, unit };
    const { best, curve, zeroFeedIntervalMm } = a.answer;
    // The curve's pairs with the best one, L ascending, and its end at fz = 0.
    const pairs = [...curve.filter((p) => p.intervalMm !== best.intervalMm), best].sort(
      (p, q) => p.intervalMm - q.intervalMm,
    );
    const x = [...pairs.map((p) => fromMm(p.intervalMm, unit)), fromMm(zeroFeedIntervalMm, unit)];
    const fz = [...pairs.map((p) => p.feedPerToothMm), 0];
    const symbol = unitSymbol(unit);
    const chart = lineChart({
      widthPx: 360,
      plotHeightPx: 140,
      x,
      logX: false,
      lines: [{ key: 'step', colourBy: 'series', values: fz }],
      yFactor: fromMm(1, unit),
      gaps: [],
      markerX: fromMm(best.intervalMm, unit),
      markerPoint: { x: fromMm(best.intervalMm, unit), y: best.feedPerToothMm },
      xLabel: `L (${symbol})`,
      yLabel: `fz (${symbol})`,
      description: '',
    });
    // Named by its caption (in the language in force), not by an English label.
    chart.removeAttribute('aria-label');
    chart.setAttribute('aria-labelledby', 'target-sa-curve-caption');
    chart.dataset.testid = 'target-sa-chart';
    this.figure.querySelector('svg')?.remove();
    this.figure.prepend(chart);
  }
}
