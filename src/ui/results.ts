import { formatPercent, type LengthUnit, NO_VALUE } from '../core/input/units';
import {
  APPROXIMATION_KEYS,
  CURVATURE_ROWS,
  PROCEDURE_KEYS,
  PROCEDURES,
  type ProcedureKey,
} from '../core/procedures/procedures';
import { type CurvedReply, isSolveReply, type PageReply, type ThreeAxisReply } from '../worker/pageProtocol';
import type { CurvatureRow, ProcedureRow, SolveMode, SolveReply } from '../worker/protocol';
import { setCopyValue } from './copy';
import { html, must } from './dom';
import { formatLen, formatLenUnit, formatSignedLenUnit } from './format';
import type { Shown } from './freshness';
import { OtherResults } from './resultsOther';
import { CROSS_AXIS_NOTE, curvatureNoteText, curvedMeaning, noteText, surfaceMeaning } from './resultsText';
import { ScrollCues } from './scrollCue';
import { setShownToolName } from './toolName';

export { curvatureNoteText, noteText, surfaceMeaning } from './resultsText';

type OkReply = Extract<SolveReply, { ok: true }>;

/** The headline's label with a target Sa: the step-over at fz -> 0, where the passes leave Ra = Sa. */
export const ZERO_FEED_LABEL = 'Step-over L0 (fz -> 0: Ra = Sa)';

/** Which kind of question the inputs on screen (or a reply) are: a plane's or cylinder's, a doubly curved point's, three-axis. */
export type QuestionKind = 'classic' | 'curved' | 'three-axis';

/** The kind of a reply's question. */
function kindOf(reply: PageReply): QuestionKind {
  if (isSolveReply(reply)) return 'classic';
  return reply.request.mode === 'three-axis' ? 'three-axis' : 'curved';
}

/** True when the reply answers a question on a cylinder whose axis runs across the feed. */
function crossAxis(reply: OkReply | null): boolean {
  const surface = reply?.request.input.surface;
  return surface?.kind === 'cylinder' && surface.axis === 'cross';
}

export class ResultsPanel {
  private readonly section: HTMLElement;
  private readonly headlineLabel: HTMLElement;
  private readonly headline: HTMLOutputElement;
  private readonly thead: HTMLElement;
  private readonly tbody: HTMLElement;
  private readonly notes: HTMLElement;
  private readonly cuspRow: HTMLElement;
  private readonly status: HTMLElement;
  /** What the table shows now (so an unchanged reply is not drawn again). */
  private drawn: { reply: PageReply | null; unit: LengthUnit; mode: SolveMode; leadOnly: boolean } | null = null;
  private readonly other: OtherResults;
  private readonly classicDetails: HTMLElement;
  private readonly classicOnly: readonly HTMLElement[];
  /** The shaded edge of the table's box while part of the table is scrolled out of it. */
  private readonly cues = new ScrollCues();
  /** The name of the tool the inputs hold, under the headline (hidden without one). */
  private readonly toolName: HTMLElement;
  /** The question the headline answers, in words, right under it (questionWords.ts; hidden without a current answer). */
  private readonly question: HTMLElement;

  constructor(private readonly root: HTMLElement) {
    this.section = must(root, '.results');
    this.headlineLabel = must(root, '[data-role="headline-label"]');
    this.headline = must(root, '[data-role="headline"]');
    this.thead = must(root, '.procedures thead');
    this.tbody = must(root, '.procedures tbody');
    // Focusable (keys scroll it) and named, as the paper tables' boxes (in the markup: no first-result code).
    const scroll = must<HTMLElement>(root, '[data-testid="procedures-scroll"]');
    if (scroll.parentElement) this.cues.watch(scroll, scroll.parentElement);
    this.notes = must(root, '[data-testid="table-notes"]');
    this.cuspRow = must(root, '[data-role="cusps"]');
    this.status = must(root, '[data-testid="results-status"]');
    this.other = new OtherResults(root);
    this.classicDetails = must(root, '.results .details[data-role="classic"]');
    this.classicOnly = [...root.querySelectorAll<HTMLElement>('[data-role="not-three-axis"]')];
    this.toolName = html('p', { class: 'tool-name', 'data-testid': 'result-tool-name' });
    this.toolName.hidden = true;
    // A long name wraps rather than widening the column (set from script: the page's CSP has no inline styles).
    this.toolName.style.overflowWrap = 'anywhere';
    this.toolName.style.margin = '0.25em 0 0';
    this.question = must(root, '[data-role="headline-question"]');
    this.question.after(this.toolName);
  }

  /**
   * Names the question the headline's number answers (issue 28: "5-axis, lead 5°, tilt 0°, one-way,
   * plane", "3-axis, slope 30°, raster 30°"), or hides the line (null: a dash, no number to
   * name). While a new answer is on its way the old number keeps its own words (both marked out of
   * date with the panel), so a drag does not make the line come and go.
   */
  showQuestion(words: string | null): void {
    const text = words ?? '';
    if (this.question.textContent !== text) this.question.textContent = text;
    this.question.hidden = words === null;
  }

  /**
   * Names the tool the inputs hold (a saved or library tool) under the headline, as text; hidden
   * for none. The shop sheet reads the same name (toolName.ts shownToolName).
   */
  showToolName(name: string | null): void {
    setShownToolName(name);
    const text = name === null ? '' : `Tool: ${name}`;
    if (this.toolName.textContent !== text) this.toolName.textContent = text;
    this.toolName.hidden = name === null;
  }

  private set(testId: string, text: string): void {
    const e = this.root.querySelector(`[data-testid="${testId}"]`);
    if (e && e.textContent !== text) e.textContent = text;
  }

  /**
   * Draws what is shown. `mode` and `tiltDeg` are the inputs on screen (they label the headline
   * and the table while no reply answers them).
   */
  render(
    shown: Shown<PageReply>,
    unit: LengthUnit,
    mode: SolveMode,
    tiltDeg: number | null,
    typing = false,
    inputs: { readonly kind: QuestionKind; readonly passes: 'raster' | 'waterline'; readonly saTarget?: boolean } = {
      kind: 'classic',
      passes: 'raster',
    },
  ): void {
    const any = shown.kind === 'current' ? shown.reply : shown.kind === 'invalid' ? null : shown.last;
    // A stale reply is drawn as its own kind (marked stale); with none, the inputs' kind.
    const kind = any?.ok ? kindOf(any) : inputs.kind;
    const reply = any !== null && kindOf(any) === kind ? any : null;
    const ok = reply?.ok && isSolveReply(reply) ? reply : null;
    // A stale reply keeps its own mode (marked stale); nothing at all follows the inputs' mode.
    const drawMode: SolveMode = ok ? (ok.request.mode === 'inverse' ? 'inverse' : 'forward') : mode;
    const stale = shown.kind !== 'current';
    this.section.classList.toggle('stale', stale && ok !== null);
    this.section.setAttribute('aria-busy', String(shown.kind === 'pending'));
    this.status.textContent = typing
      ? 'Typing: the results follow when you pause or press Enter.'
      : shown.kind === 'pending' && ok
        ? 'Updating: these numbers are for the previous inputs.'
        : shown.kind === 'failed'
          ? ok
            ? 'Out of date: the solver gave up; these numbers are for earlier inputs.'
            : 'No answer: the solver gave up.'
          : '';
    this.status.hidden = this.status.textContent === '';
    this.other.showThreeAxis(kind === 'three-axis');
    this.classicDetails.hidden = kind === 'three-axis';
    for (const e of this.classicOnly) e.hidden = kind === 'three-axis';
    if (kind === 'three-axis') {
      const t =
        reply?.ok && reply.request.mode === 'three-axis' ? (reply as Extract<ThreeAxisReply, { ok: true }>) : null;
      const headline = { label: this.headlineLabel, value: this.headline };
      this.other.threeAxis(headline, t, inputs.passes, mode, unit, shown.kind === 'current');
      this.set(
        'no-scallop',
        t?.answer.noScallop && shown.kind === 'current'
          ? 'No scallop: a flat end on a flat floor lies flat, so L = 2R for any h.'
          : '',
      );
      must<HTMLElement>(this.root, '[data-testid="no-scallop"]').hidden = !(
        t?.answer.noScallop && shown.kind === 'current'
      );
      this.set('result-percent-diameter', '');
      // L/2 along the surface (in the hidden five-axis details: what answers, for any reader of the page).
      this.set('result-exact-half', t === null ? NO_VALUE : formatLenUnit(t.answer.intervalMm / 2, unit));
      this.setMeaning('');
      this.table(t, unit, drawMode, false);
      return;
    }
    if (kind === 'curved') {
      this.curved(reply?.ok ? (reply as Extract<CurvedReply, { ok: true }>) : null, shown, unit, mode);
      return;
    }
    const forward = drawMode === 'forward';
    // A target Sa's answer here is the curve's end L0 (the pair is the target-Sa box's): named so.
    this.headlineLabel.textContent = forward ? (inputs.saTarget ? ZERO_FEED_LABEL : 'Step-over L') : 'Scallop height h';
    this.headline.dataset.testid = forward ? 'result-exact-interval' : 'result-exact-height';
    const e = ok?.exact ?? null;
    const value = (mm: number | null | undefined, resolution: 'length' | 'height' = 'length') =>
      e === null ? NO_VALUE : formatLenUnit(mm ?? null, unit, resolution);
    this.headline.textContent = forward ? value(e?.intervalMm) : value(e?.cuspHeightMm, 'height');
    this.set('result-exact-half', e === null ? NO_VALUE : formatLenUnit(e.halfIntervalMm, unit));
    this.set('result-width-right', value(e?.widthRightMm));
    this.set('result-width-left', value(e?.widthLeftMm));
    this.set('result-contact-offset', e === null ? NO_VALUE : formatSignedLenUnit(e.contactOffsetMm, unit));
    this.set('result-centre-offset', e === null ? NO_VALUE : formatSignedLenUnit(-e.contactOffsetMm, unit));
    // Copy only what answers the inputs on screen, in the user's unit (copy.ts).
    const copyable = shown.kind === 'current' ? e : null;
    const copy = (testId: string, mm: number | undefined, resolution: 'length' | 'height' = 'length') => {
      const output = this.root.querySelector(`[data-testid="${testId}"]`);
      if (output)
        setCopyValue(output, copyable === null || mm === undefined ? null : formatLen(mm, unit, resolution), unit);
    };
    copy(
      this.headline.dataset.testid ?? '',
      forward ? copyable?.intervalMm : copyable?.cuspHeightMm,
      forward ? 'length' : 'height',
    );
    copy('result-exact-half', copyable?.halfIntervalMm);
    copy('result-centre-offset', copyable === null ? undefined : -copyable.contactOffsetMm);
    const flat = shown.kind === 'current' && e?.noScallop === true;
    this.set(
      'no-scallop',
      flat
        ? `No scallop: a flat end without lead or tilt lies flat on the plane and leaves no scallop at any step-over up to its diameter, so L = 2R = ${formatLenUnit(e.intervalMm, unit)} for any h.`
        : '',
    );
    must<HTMLElement>(this.root, '[data-testid="no-scallop"]').hidden = !flat;
    this.cuspsAndShare((ok?.request.input.pattern ?? null) === 'zigzag', e, value, ok?.request.input.toolRadiusMm);
    const leadOnly = (ok ? ok.request.input.tiltAngleDeg : (tiltDeg ?? 0)) !== 0;
    this.setMeaning(ok ? surfaceMeaning(ok.request.input.surface, unit) : '');
    this.table(ok, unit, drawMode, leadOnly);
  }

  /** The zigzag's two cusp heights (dashes otherwise) and L as a share of the tool diameter (R mm). */
  private cuspsAndShare(
    zigzag: boolean,
    e: { readonly cuspHeightMm: number; readonly otherCuspHeightMm: number | null; readonly intervalMm: number } | null,
    value: (mm: number | null | undefined, resolution: 'length' | 'height') => string,
    R: number | undefined,
  ): void {
    this.cuspRow.hidden = !zigzag;
    this.set('result-cusp-height', zigzag ? value(e?.cuspHeightMm, 'height') : NO_VALUE);
    this.set('result-other-cusp-height', zigzag ? value(e?.otherCuspHeightMm, 'height') : NO_VALUE);
    this.set(
      'result-percent-diameter',
      e === null || R === undefined
        ? ''
        : `L = ${formatPercent((100 * e.intervalMm) / (2 * R), 1).replace(/^\+/, '')} % of the tool diameter`,
    );
  }

  private setMeaning(text: string): void {
    const meaning = this.root.querySelector<HTMLElement>('[data-testid="surface-meaning"]');
    if (!meaning) return;
    if (meaning.textContent !== text) meaning.textContent = text;
    meaning.hidden = text === '';
  }

  /** A doubly curved point's answer: the headline, the details (reaches, offset, cusps) and the comparison rows. */
  private curved(
    reply: Extract<CurvedReply, { ok: true }> | null,
    shown: Shown<PageReply>,
    unit: LengthUnit,
    mode: SolveMode,
  ): void {
    const e = reply?.exact ?? null;
    const forward =
      (reply === null ? mode : reply.request.mode === 'curved-inverse' ? 'inverse' : 'forward') === 'forward';
    this.headlineLabel.textContent = forward ? 'Step-over L' : 'Scallop height h';
    this.headline.dataset.testid = forward ? 'result-exact-interval' : 'result-exact-height';
    const value = (mm: number | null | undefined, resolution: 'length' | 'height' = 'length') =>
      e === null ? NO_VALUE : formatLenUnit(mm ?? null, unit, resolution);
    this.headline.textContent = forward ? value(e?.intervalMm) : value(e?.cuspHeightMm, 'height');
    const current = shown.kind === 'current' && e !== null;
    setCopyValue(
      this.headline,
      current ? formatLen(forward ? e.intervalMm : e.cuspHeightMm, unit, forward ? 'length' : 'height') : null,
      unit,
    );
    this.set('result-exact-half', e === null ? NO_VALUE : formatLenUnit(e.intervalMm / 2, unit));
    const half = this.root.querySelector('[data-testid="result-exact-half"]');
    if (half) setCopyValue(half, current ? formatLen(e.intervalMm / 2, unit) : null, unit);
    this.set('result-width-right', value(e?.halfWidthRightMm));
    this.set('result-width-left', value(e?.halfWidthLeftMm));
    this.set('result-contact-offset', e === null ? NO_VALUE : formatSignedLenUnit(e.contactOffsetMm, unit));
    this.set('result-centre-offset', e === null ? NO_VALUE : formatSignedLenUnit(-e.contactOffsetMm, unit));
    const centre = this.root.querySelector('[data-testid="result-centre-offset"]');
    if (centre) setCopyValue(centre, current ? formatLen(-e.contactOffsetMm, unit) : null, unit);
    this.set('no-scallop', '');
    must<HTMLElement>(this.root, '[data-testid="no-scallop"]').hidden = true;
    this.cuspsAndShare(e?.pattern === 'zigzag', e, value, reply?.request.input.toolRadiusMm);
    this.setMeaning(
      reply === null ? '' : curvedMeaning(reply.request.input.feedRadiusMm, reply.request.input.crossRadiusMm, unit),
    );
    this.table(reply, unit, forward ? 'forward' : 'inverse', false);
  }

  /** The language changed: the table is drawn anew at the next render (its words and decimal sign). */
  invalidate(): void {
    this.drawn = null;
  }

  private table(reply: PageReply | null, unit: LengthUnit, mode: SolveMode, leadOnly: boolean): void {
    const d = this.drawn;
    if (d && d.reply === reply && d.unit === unit && d.mode === mode && d.leadOnly === leadOnly) return;
    this.drawn = { reply, unit, mode, leadOnly };
    const tableElement = this.thead.parentElement;
    if (tableElement) tableElement.hidden = reply !== null && kindOf(reply) === 'three-axis';
    if (reply !== null && kindOf(reply) === 'three-axis') {
      this.thead.replaceChildren();
      this.tbody.replaceChildren();
      this.setNotes('');
      return;
    }
    if (reply !== null && kindOf(reply) === 'curved') {
      const c = reply.ok ? (reply as Extract<CurvedReply, { ok: true }>) : null;
      const notes = this.other.curvedTable(this.thead, this.tbody, c, unit);
      const inverse = c !== null && c.comparison === null;
      this.setNotes(
        [
          ...notes,
          inverse
            ? 'The comparison rows are given for the forward problem (a scallop height to the step-over).'
            : 'Each row beside the exact answer: the plane (both curvatures ignored), each cylinder (one radius ignored) and the usual correction 1/rho = 1/Reff + 1/Rc of each procedure with an effective radius, with its deviation from exact and the scallop its own L really leaves at this point.',
        ].join(' '),
      );
      return;
    }
    this.classicTable(reply?.ok && isSolveReply(reply) ? reply : null, unit, mode, leadOnly);
  }

  private setNotes(text: string): void {
    if (this.notes.textContent !== text) this.notes.textContent = text;
  }

  private classicTable(reply: OkReply | null, unit: LengthUnit, mode: SolveMode, leadOnly: boolean): void {
    const forward = mode === 'forward';
    // Each length cell carries its unit (format.ts): a tiny deviation reads in µm, never 1e-7.
    const head = forward
      ? ['Procedure', 'L/2', 'Deviation', 'Deviation [%]', 'Scallop it leaves']
      : ['Procedure', 'h', 'Deviation', 'Deviation [%]'];
    const headRow = html('tr');
    for (const h of head) headRow.append(html('th', { scope: 'col' }, h));
    this.thead.replaceChildren(headRow);
    const rows = new Map<ProcedureKey, ProcedureRow>();
    for (const r of reply?.rows ?? []) rows.set(r.key, r);
    const notes: string[] = [];
    this.tbody.replaceChildren();
    for (const key of PROCEDURE_KEYS) {
      const row = rows.get(key) ?? null;
      const info = PROCEDURES[key];
      const tr = html('tr', {
        'data-procedure': key,
        tabindex: '0',
        title: 'Click to select this procedure in every view',
      });
      tr.append(html('th', { scope: 'row' }, leadOnly && info.leadOnly ? `${info.label}, lead only` : info.label));
      // The headline carries result-exact-half: the table's exact row gets its own ids.
      const prefix = key === 'exact' ? 'table-exact' : `result-${key}`;
      const resolution = forward ? 'length' : 'height';
      const cell = (testId: string | null, text: string) => {
        const td = html('td');
        td.append(testId === null ? document.createTextNode(text) : html('output', { 'data-testid': testId }, text));
        tr.append(td);
      };
      const none = reply === null ? NO_VALUE : 'n/a';
      cell(
        `${prefix}-${forward ? 'half' : 'h'}`,
        row?.valueMm == null ? none : formatLenUnit(row.valueMm, unit, resolution),
      );
      cell(null, row?.deviationMm == null ? NO_VALUE : formatSignedLenUnit(row.deviationMm, unit, resolution));
      cell(null, row?.deviationPercent == null ? NO_VALUE : formatPercent(row.deviationPercent));
      if (forward) cell(`${prefix}-real-h`, formatLenUnit(row?.realScallopMm ?? null, unit, 'height'));
      if (row?.note) {
        const text = noteText(key, row.note, unit);
        tr.title = text;
        notes.push(text);
      }
      this.tbody.append(tr);
    }
    const curvature = reply?.curvature ?? null;
    if (curvature !== null) this.curvatureRows(curvature, unit, forward, head.length, notes);
    const lead = leadOnly
      ? `With tilt, ${APPROXIMATION_KEYS.filter((k) => PROCEDURES[k].leadOnly)
          .map((k) => PROCEDURES[k].shortLabel)
          .join(', ')} are lead-only models: applied with the lead angle alone, the tilt ignored.`
      : '';
    const noScallop = reply?.exact.noScallop
      ? 'No scallop: a flat end lying flat leaves none at any step-over up to its diameter, so L = 2R.'
      : '';
    const curved =
      curvature === null
        ? ''
        : 'On a cylinder the procedures above are applied as on a plane (they ignore the curvature); the rows below them give the exact answer for a plane at the same input (the curvature ignored) and the usual correction 1/rho = 1/Reff + 1/Rs of each procedure with an effective radius, each beside the exact answer on the cylinder.';
    const across = curvature !== null && crossAxis(reply) ? CROSS_AXIS_NOTE : '';
    const text = [noScallop, ...notes, reply ? lead : '', curved, across].filter((t) => t !== '').join(' ');
    if (this.notes.textContent !== text) this.notes.textContent = text;
  }

  /** The rows a cylinder adds, under a heading row: the plane's answer and the corrected procedures. */
  private curvatureRows(
    rows: readonly CurvatureRow[],
    unit: LengthUnit,
    forward: boolean,
    columns: number,
    notes: string[],
  ): void {
    const head = html('tr', { class: 'curvature-head' });
    head.append(
      html(
        'th',
        { scope: 'colgroup', colspan: String(columns) },
        'On the cylinder: curvature ignored, or corrected the usual way',
      ),
    );
    this.tbody.append(head);
    const resolution = forward ? 'length' : 'height';
    for (const row of rows) {
      const info = CURVATURE_ROWS[row.key];
      const tr = html('tr', { 'data-curvature': row.key, title: info.assumes });
      tr.append(html('th', { scope: 'row' }, info.label));
      const cell = (testId: string | null, text: string) => {
        const td = html('td');
        td.append(testId === null ? document.createTextNode(text) : html('output', { 'data-testid': testId }, text));
        tr.append(td);
      };
      cell(
        `result-${row.key}-${forward ? 'half' : 'h'}`,
        row.valueMm === null ? 'n/a' : formatLenUnit(row.valueMm, unit, resolution),
      );
      cell(null, row.deviationMm === null ? NO_VALUE : formatSignedLenUnit(row.deviationMm, unit, resolution));
      cell(null, row.deviationPercent === null ? NO_VALUE : formatPercent(row.deviationPercent));
      if (forward) cell(`result-${row.key}-real-h`, formatLenUnit(row.realScallopMm, unit, 'height'));
      if (row.note && !(row.note.kind === 'reason' && row.note.text === '')) {
        const text = curvatureNoteText(row.key, row.note, unit);
        tr.title = text;
        notes.push(text);
      }
      this.tbody.append(tr);
    }
  }
}
