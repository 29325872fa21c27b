/**
 * The cross-feed profile's scale bars (SVG), in the user's unit at the bottom of the box shown:
 * across the feed at true scale, and for heights when they are exaggerated (the bar drawn k times
 * taller, and saying so). Redrawn with every zoom and pan, so they keep their size on screen.
 */
import { scaleBar } from '../../core/output/drawingScale';
import type { Unit } from '../state';
import { svg } from './common';
import type { Box } from './profileLayout';

/**
 * Draws the bars into `group` (emptied first) for the box `b` shown in a plot of height over width
 * `aspect` (the viewBox is fitted into the plot keeping its aspect, so one of its sides has room to
 * spare), heights exaggerated `k` times, texts `fontSize` high (display units).
 */
export function drawScaleBars(
  group: SVGGElement,
  b: Box,
  aspect: number,
  k: number,
  unit: Unit,
  fontSize: number,
): void {
  group.replaceChildren();
  const w = Math.max(b.w, b.h / aspect);
  const h = Math.max(b.h, b.w * aspect);
  const x0 = b.x + b.w / 2 - w / 2 + 0.03 * w;
  const yBase = b.y + b.h / 2 + h / 2 - 0.05 * h;
  const tick = 0.012 * w;
  const text = (x: number, y: number, label: string, testId: string, anchor = 'start') => {
    const t = svg('text', { x, y, class: 'dim-text scale-text', 'data-testid': testId, 'text-anchor': anchor });
    t.setAttribute('font-size', String(fontSize));
    t.textContent = label;
    group.append(t);
  };
  const across = scaleBar(0.2 * w, unit);
  if (across !== null) {
    const x1 = x0 + across.lengthMm;
    group.append(
      svg('polyline', {
        points: `${x0},${yBase - tick} ${x0},${yBase} ${x1},${yBase} ${x1},${yBase - tick}`,
        class: 'scale-line',
      }),
    );
    text(x0, yBase - 1.6 * tick, across.text, 'profile-scale-bar-x');
  }
  if (k === 1) return;
  const up = scaleBar((0.25 * h) / k, unit);
  if (up === null) return;
  const x = x0 + 0.3 * w;
  const y1 = yBase - k * up.lengthMm;
  group.append(
    svg('polyline', {
      points: `${x - tick},${y1} ${x},${y1} ${x},${yBase} ${x - tick},${yBase}`,
      class: 'scale-line',
    }),
  );
  text(x + tick, yBase - (k * up.lengthMm) / 2, `${up.text} high (drawn x${k})`, 'profile-scale-bar-z');
}
