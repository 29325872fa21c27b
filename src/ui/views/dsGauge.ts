/**
 * The step-through's d_s / Rcr gauge on an honest scale: a bar drawn linearly from 0, its scale
 * (0, 0.25, 0.5, ...) and the mark at 1 (d_s = Rcr, the single contact) always shown, and a scale
 * long enough for every frame of the trace, so no bar is clipped and none is exaggerated.
 */
import { html, svg } from './common';
import { GAUGE_TICK as TICK } from './stepGroups';

const LEFT = 12;
const TRACK = 276;

export class DsGauge {
  readonly element = html('div', { class: 'stepper-ds', 'data-testid': 'stepper-ds' });
  private readonly picture = svg('svg', {
    class: 'ds-gauge',
    viewBox: `0 0 ${LEFT * 2 + TRACK} 36`,
    'aria-hidden': 'true',
  });
  private readonly bar = svg('rect', { class: 'ds-bar', x: LEFT, y: 4, height: 12, width: 0 });
  private readonly text = html('span', { class: 'meter-text', 'data-testid': 'stepper-ds-text' });
  private readonly name = html('span', { class: 'ds-label' });
  private max = 1;

  constructor() {
    this.element.append(this.name, this.picture, this.text);
  }

  /** The gauge's label, in the language in force ("d_s / Rcr, linear from 0:"). */
  label(text: string): void {
    if (this.name.textContent !== text) this.name.textContent = text;
  }

  /** Draws the scale from 0 to `max` (a multiple of 0.25), its numbers written by `local` (the locale's decimal sign). */
  setScale(max: number, local: (text: string) => string = (t) => t): void {
    this.max = max;
    const x = (r: number) => LEFT + (r / max) * TRACK;
    const parts: SVGElement[] = [svg('rect', { class: 'ds-track', x: LEFT, y: 4, width: TRACK, height: 12 }), this.bar];
    for (let k = 0; k * TICK <= max + 1e-9; k++) {
      const r = k * TICK;
      const label = svg('text', { class: 'ds-tick', x: x(r), y: 31, 'text-anchor': 'middle' });
      label.textContent = r === 1 ? '1 = Rcr' : local(String(r));
      parts.push(svg('line', { class: r === 1 ? 'ds-mark' : 'ds-grid', x1: x(r), x2: x(r), y1: 2, y2: 20 }), label);
    }
    this.picture.replaceChildren(...parts);
    this.picture.dataset.max = String(max);
  }

  /** Shows a ratio (or none, with the reason in the text). */
  show(ratio: number | null, text: string): void {
    const r = ratio === null || !Number.isFinite(ratio) ? 0 : Math.max(0, Math.min(this.max, ratio));
    this.bar.setAttribute('width', ((r / this.max) * TRACK).toFixed(2));
    this.bar.dataset.ratio = ratio === null ? '' : String(ratio);
    this.text.textContent = text;
  }
}
