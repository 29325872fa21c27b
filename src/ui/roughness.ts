/**
 * The roughness results: Rz, Ra, Rq of the surface left at the exact step-over (from the solve
 * reply: a plane's, a cylinder's, a doubly curved point's, heights along the normal there, or a
 * sloped plane's machined three-axis, the plane's at the equivalent lead and tilt), the
 * scallop height they come from when the target is Ra, and the rule of thumb
 * Ra ~ h/4 with its error. Drawn from the same Shown as the other results (dashes when invalid
 * or while no reply answers the inputs on screen; never a number for other inputs).
 */
import { formatPercent, type LengthUnit, NO_VALUE } from '../core/input/units';
import type { PageReply } from '../worker/pageProtocol';
import { detailsRow, html } from './dom';
import { formatLenUnit, formatRoughness } from './format';
import type { Shown } from './freshness';

/**
 * Why the rows show dashes for waterline passes on a surface of revolution (on a sloped plane the
 * rows are the plane's roughness at the equivalent lead and tilt).
 */
export const REVOLUTION_NOTE =
  'Rz, Ra and Rq are not given here: waterline passes on a surface of revolution change their spacing from level to level, so the profile has no period to measure them over; the scallop height h is the answer.';

/** The roughness rows under the results (see the module comment). */
export class RoughnessPanel {
  private readonly outputs = new Map<string, HTMLOutputElement>();
  private readonly heightRow: HTMLElement;
  private readonly rule: HTMLElement;

  /** Builds the block after the results' details list. */
  constructor(root: HTMLElement) {
    const list = html('dl', { class: 'details roughness', 'data-testid': 'roughness' });
    const row = (label: string, testId: string) => {
      const out = html('output', { 'data-testid': testId }, NO_VALUE);
      this.outputs.set(testId, out);
      return detailsRow(list, label, out).row;
    };
    row('Rz', 'result-rz');
    row('Ra', 'result-ra');
    row('Rq', 'result-rq');
    this.heightRow = row('h for this Ra', 'result-ra-height');
    this.heightRow.hidden = true;
    this.rule = html('p', { class: 'pct', 'data-testid': 'result-ra-rule' });
    const details = root.querySelector('.results .details');
    if (details) details.after(list, this.rule);
    else root.append(list, this.rule);
  }

  private set(testId: string, text: string): void {
    const e = this.outputs.get(testId);
    if (e && e.textContent !== text) e.textContent = text;
  }

  render(shown: Shown<PageReply>, unit: LengthUnit): void {
    // Only a reply to the inputs on screen: a stale one would show numbers for other inputs.
    // Waterline on a surface of revolution has none: dashes, and the note says why.
    const reply = shown.kind === 'current' && shown.reply.ok && 'roughness' in shown.reply ? shown.reply : null;
    const r = reply?.roughness ?? null;
    // Roughness in µm (mm) or µin (inch), as the Machined surface view gives it (format.ts).
    const rough = (mm: number | undefined) => (r === null || mm === undefined ? NO_VALUE : formatRoughness(mm, unit));
    const len = (mm: number | undefined) =>
      r === null || mm === undefined ? NO_VALUE : formatLenUnit(mm, unit, 'height');
    this.set('result-rz', rough(r?.rzMm));
    this.set('result-ra', rough(r?.raMm));
    this.set('result-rq', rough(r?.rqMm));
    const fromRa = reply?.request.mode === 'ra' || reply?.request.mode === 'curved-ra';
    this.heightRow.hidden = !fromRa;
    this.set('result-ra-height', fromRa ? len(r?.scallopHeightMm) : NO_VALUE);
    const revolution = reply !== null && reply.request.mode === 'three-axis' && r === null;
    const text = revolution
      ? REVOLUTION_NOTE
      : r === null || r.ruleErrorPercent === null
        ? ''
        : `Rule of thumb Ra ~ h/4 = ${formatRoughness(r.ruleOfThumbRaMm, unit)}: ${formatPercent(r.ruleErrorPercent)} % against the exact Ra.`;
    if (this.rule.textContent !== text) this.rule.textContent = text;
  }
}
