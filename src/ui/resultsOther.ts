/**
 * The results of the questions beyond a plane or a cylinder (results.ts draws those and calls
 * here): a doubly curved point (issue 19: L, the reaches, the cusps, and forward the comparison
 * rows: the plane, each cylinder, the usual correction, each with its deviation from exact and the
 * scallop its own L really leaves) and three-axis machining (issue 20: the programmed step first,
 * Lxy or dz, copyable; then L along the surface, the cusp and the equivalent lead and tilt).
 */

import { formatPercent, type LengthUnit, NO_VALUE } from '../core/input/units';
import type { DoublyCurvedRow } from '../core/procedures/compareDoublyCurved';
import { CORRECTED_KEYS, CURVATURE_ROWS, correctedRowKey } from '../core/procedures/procedures';
import type { CurvedReply, ThreeAxisReply } from '../worker/pageProtocol';
import type { SolveMode } from '../worker/protocol';
import { setCopyValue } from './copy';
import { html, must } from './dom';
import { formatAngle, formatLen, formatLenUnit, formatSignedLenUnit } from './format';

type CurvedOk = Extract<CurvedReply, { ok: true }>;
type ThreeAxisOk = Extract<ThreeAxisReply, { ok: true }>;

/** The test ids of the three-axis block while it is on screen (elsewhere neutral ones: ids stay unique). */
const STEP_ID = 'result-programmed-step';
const INTERVAL_ID = 'result-exact-interval';

/** Draws the three-axis block and the doubly curved table; the classic panel calls these. */
export class OtherResults {
  private readonly block: HTMLElement;
  private readonly stepRow: HTMLElement;
  private readonly stepLabel: HTMLElement;
  private readonly stepValue: HTMLOutputElement;
  private readonly interval: HTMLOutputElement;
  private readonly lead: HTMLOutputElement;
  private readonly tilt: HTMLOutputElement;
  private readonly cusp: HTMLOutputElement;

  constructor(root: HTMLElement) {
    this.block = must(root, '[data-role="three-axis"]');
    this.stepRow = must(root, '[data-role="step-row"]');
    this.stepLabel = must(root, '[data-role="step-label"]');
    this.stepValue = must(root, '[data-role="step-value"]');
    this.interval = must(root, '[data-role="surface-interval"]');
    this.lead = must(root, '[data-testid="result-equivalent-lead"]');
    this.tilt = must(root, '[data-testid="result-equivalent-tilt"]');
    this.cusp = must(root, '[data-testid="result-three-axis-cusp"]');
  }

  /** Shows or hides the three-axis block; hidden, its outputs give up the shared test ids. */
  showThreeAxis(shown: boolean): void {
    this.block.hidden = !shown;
    if (!shown) {
      this.stepValue.dataset.testid = 'three-axis-step';
      this.interval.dataset.testid = 'three-axis-interval';
    }
  }

  /**
   * The three-axis answer. The headline (label, output) is the programmed step forward, the cusp
   * height inverse; the block gives the step (inverse), L, the cusp and the posture.
   * @param current the reply answers the inputs on screen (only then is anything copyable).
   */
  threeAxis(
    headline: { label: HTMLElement; value: HTMLOutputElement },
    reply: ThreeAxisOk | null,
    passes: 'raster' | 'waterline',
    mode: SolveMode,
    unit: LengthUnit,
    current: boolean,
  ): void {
    const a = reply?.answer ?? null;
    const waterline = (a?.passes ?? passes) === 'waterline';
    const stepName = waterline ? 'Step-down dz' : 'Horizontal step Lxy';
    const stepMm = a === null ? null : waterline ? a.stepDownMm : a.horizontalStepMm;
    const forward =
      (reply === null ? mode : reply.request.input.quantity === 'h' ? 'forward' : 'inverse') === 'forward';
    const copy = (output: HTMLOutputElement, mm: number | null, resolution: 'length' | 'height' = 'length') =>
      setCopyValue(output, current && mm !== null ? formatLen(mm, unit, resolution) : null, unit);
    const text = (mm: number | null, resolution: 'length' | 'height' = 'length') =>
      mm === null ? NO_VALUE : formatLenUnit(mm, unit, resolution);
    if (forward) {
      headline.label.textContent = `${stepName} (as programmed)`;
      headline.value.dataset.testid = STEP_ID;
      headline.value.textContent = text(stepMm);
      copy(headline.value, stepMm);
      this.stepValue.dataset.testid = 'three-axis-step';
    } else {
      headline.label.textContent = 'Scallop height h';
      headline.value.dataset.testid = 'result-exact-height';
      headline.value.textContent = text(a?.cuspHeightMm ?? null, 'height');
      copy(headline.value, a?.cuspHeightMm ?? null, 'height');
      this.stepValue.dataset.testid = STEP_ID;
    }
    this.stepRow.hidden = forward;
    this.stepLabel.textContent = `${stepName} (as programmed)`;
    this.stepValue.textContent = text(stepMm);
    copy(this.stepValue, forward ? null : stepMm);
    this.interval.dataset.testid = INTERVAL_ID;
    this.interval.textContent = text(a?.intervalMm ?? null);
    copy(this.interval, a?.intervalMm ?? null);
    this.cusp.textContent = text(a?.cuspHeightMm ?? null, 'height');
    this.lead.textContent = formatAngle(a?.leadDeg ?? null);
    this.tilt.textContent = formatAngle(a?.tiltDeg ?? null);
  }

  /** The doubly curved comparison rows (forward), under the table's head; the notes they add. */
  curvedTable(thead: HTMLElement, tbody: HTMLElement, reply: CurvedOk | null, unit: LengthUnit): string[] {
    const headRow = html('tr');
    // Each length cell carries its unit (format.ts), as the plane's table.
    for (const h of ['Model', 'L', 'Deviation', 'Deviation [%]', 'Scallop it leaves'])
      headRow.append(html('th', { scope: 'col' }, h));
    thead.replaceChildren(headRow);
    tbody.replaceChildren();
    const notes: string[] = [];
    const add = (id: string, label: string, title: string, row: DoublyCurvedRow | 'exact' | null) => {
      const tr = html('tr', { 'data-curved': id, title });
      tr.append(html('th', { scope: 'row' }, label));
      const cell = (testId: string | null, t: string) => {
        const td = html('td');
        td.append(testId === null ? document.createTextNode(t) : html('output', { 'data-testid': testId }, t));
        tr.append(td);
      };
      const exactL = reply?.exact.intervalMm ?? null;
      if (row === 'exact' || row === null) {
        cell(`result-curved-${id}-L`, row === null ? NO_VALUE : formatLenUnit(exactL, unit));
        cell(null, NO_VALUE);
        cell(null, NO_VALUE);
        cell(null, row === null ? NO_VALUE : formatLenUnit(reply?.exact.cuspHeightMm ?? null, unit, 'height'));
      } else if (row.ok) {
        cell(`result-curved-${id}-L`, formatLenUnit(row.intervalMm, unit));
        cell(null, formatSignedLenUnit(row.deviationMm, unit));
        cell(null, formatPercent(row.deviationPercent));
        cell(`result-curved-${id}-real-h`, formatLenUnit(row.realScallopMm, unit, 'height'));
      } else {
        cell(`result-curved-${id}-L`, 'n/a');
        for (let i = 0; i < 3; i++) cell(null, NO_VALUE);
        notes.push(`${label}: ${row.notApplicable}`);
      }
      tbody.append(tr);
    };
    const c = reply?.comparison ?? null;
    add(
      'exact',
      'Exact (this doubly curved point)',
      'The exact step-over at this point.',
      reply === null ? null : 'exact',
    );
    if (reply !== null && c === null) return notes;
    add(
      'plane',
      'Plane, exact (both curvatures ignored)',
      'The exact answer on a plane at the same posture.',
      c?.plane ?? null,
    );
    add(
      'cylinderAlong',
      'Cylinder along the feed, exact (Rf ignored)',
      'The exact answer on the cylinder of radius Rc with its axis along the feed.',
      c?.cylinderAlong ?? null,
    );
    add(
      'cylinderAcross',
      'Cylinder across the feed, exact (Rc ignored)',
      'The exact answer on the cylinder of radius Rf with its axis across the feed.',
      c?.cylinderAcross ?? null,
    );
    for (const key of CORRECTED_KEYS) {
      const info = CURVATURE_ROWS[correctedRowKey(key)];
      add(
        correctedRowKey(key),
        `${info.shortLabel} (1/rho = 1/Reff + 1/Rc)`,
        'The usual correction: the effective radius combined with the radius across the feed.',
        c?.corrected[key] ?? null,
      );
    }
    return notes;
  }
}
