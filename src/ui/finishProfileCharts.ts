/**
 * The finish box's profiles (issue 29): the height of the surface the teeth leave along the CC path
 * over two feed periods and across the feed over one period of the passes, at the x where the feed
 * marks stand highest (the worker's answer, core/finish/profiles.ts), each a small line chart
 * (views/lineChart.ts) with positions in the user's unit (mm, in) and heights in µm (µin in inch),
 * as the box's roughness numbers are given. Loaded with the finish box, not with the first result.
 */
import type { FinishProfile, FinishProfiles } from '../core/finish/profiles';
import { fromMm, type LengthUnit, roughnessUnit, unitSymbol } from '../core/input/units';
import { html } from './dom';
import { feedLength } from './finishLength';
import { lineChart } from './views/lineChart';
import './views/chart.css';

/** The captions' words (catalogue FinishPhrase). */
const ALONG = 'Along the CC path (y = 0), two feed periods';
const ACROSS = 'Across the feed, one period of the passes, where the feed marks stand highest:';

/** One chart's figure: its caption (the words, and for the across profile the x it stands at) and its chart. */
interface Figure {
  readonly figure: HTMLElement;
  readonly at: HTMLOutputElement | null;
}

function figure(testId: string, words: string, withAt: boolean): Figure {
  const el = html('figure', { class: 'finish-profile', 'data-testid': testId });
  const caption = html('figcaption', {});
  const phrase = html('span', { id: `${testId}-caption`, 'data-phrase': words }, words);
  caption.append(phrase);
  // Not a live region of its own (finishPanel.ts: the box has one).
  const at = withAt ? html('output', { 'data-testid': `${testId}-x`, 'aria-live': 'off' }) : null;
  if (at !== null) caption.append(' x = ', at);
  el.append(caption);
  return { figure: el, at };
}

/** The two profiles' charts, hidden without an answer (see the module comment). */
export class FinishProfileCharts {
  readonly element = html('div', { class: 'finish-profiles', 'data-testid': 'finish-profiles', hidden: '' });
  private readonly along = figure('finish-profile-along', ALONG, false);
  private readonly across = figure('finish-profile-across', ACROSS, true);
  private drawn: { profiles: FinishProfiles; unit: LengthUnit } | null = null;

  constructor() {
    this.element.append(this.along.figure, this.across.figure);
  }

  /** Draws the profiles of the answer on screen in `unit`, or hides them (null: none answers the inputs). */
  show(profiles: FinishProfiles | null, unit: LengthUnit): void {
    this.element.hidden = profiles === null;
    if (profiles === null || (this.drawn?.profiles === profiles && this.drawn.unit === unit)) return;
    this.drawn = { profiles, unit };
    this.chart(this.along, profiles.along, 'x');
    this.chart(this.across, profiles.across, 'y');
    if (this.across.at !== null) this.across.at.textContent = feedLength(profiles.acrossAtXMm, unit);
  }

  private chart(f: Figure, p: FinishProfile, axis: 'x' | 'y'): void {
    const unit = this.drawn?.unit ?? 'mm';
    const chart = lineChart({
      widthPx: 360,
      plotHeightPx: 110,
      x: Array.from(p.atMm, (mm) => fromMm(mm, unit)),
      logX: false,
      lines: [{ key: 'step', colourBy: 'series', values: Array.from(p.heightsMm) }],
      yFactor: roughnessUnit(unit).perMm,
      gaps: [],
      markerX: Number.NaN,
      xLabel: `${axis} (${unitSymbol(unit)})`,
      yLabel: `s (${roughnessUnit(unit).symbol})`,
      description: '',
    });
    // Named by its caption (in the language in force), not by an English label.
    chart.removeAttribute('aria-label');
    chart.setAttribute('aria-labelledby', `${f.figure.dataset.testid}-caption`);
    chart.dataset.testid = `${f.figure.dataset.testid}-chart`;
    f.figure.querySelector('svg')?.remove();
    f.figure.prepend(chart);
  }
}
