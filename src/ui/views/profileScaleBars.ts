/**
 * The cross-feed profile's scale bars (SVG), in the user's unit at the bottom of the box shown:
 * across the feed at true scale, and for heights when they are exaggerated (the bar drawn k times
 * taller, and saying so). Redrawn with every zoom and pan, so they keep their size on screen.
 */
import { scaleBar } from '../../core/output/drawingScale';
import type { Unit } from '../state';
import { svg } from './common';
import { addLabel } from './profileLabels';
import type { Box } from './profileLayout';
import { profileWords } from './profileWords';

/**
 * Draws the bars into `group` (emptied first) for the box `b` shown in a plot of height over width
 * `aspect` (the viewBox is fitted into the plot keeping its aspect, so one of its sides has room to
 * spare), heights exaggerated `k` times, texts `fontSize` high (display units). They stand in the
 * bottom {@link SCALE_ROOM} text heights of what is shown, the room the drawing leaves below its
 * labels (profileDrawing.ts LABELS_DEPTH); the texts are labels (profileLabels.ts), placed with the others.
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
  const yBase = b.y + b.h / 2 + h / 2 - 0.5 * fontSize;
  const tick = 0.4 * fontSize;
  const across = scaleBar(0.2 * w, unit);
  if (across !== null) {
    const x1 = x0 + across.lengthMm;
    group.append(
      svg('polyline', {
        points: `${x0},${yBase - tick} ${x0},${yBase} ${x1},${yBase} ${x1},${yBase - tick}`,
        class: 'scale-line',
      }),
    );
    addLabel(group, x0, yBase - tick - 0.3 * fontSize, across.text, {
      align: 'start',
      cls: 'dim-text scale-text',
      testId: 'profile-scale-bar-x',
    });
  }
  if (k === 1) return;
  // No taller than the room (less a margin), so that it stays below the labels above it.
  const up = scaleBar(Math.min(0.25 * h, (SCALE_ROOM - 1) * fontSize) / k, unit);
  if (up === null) return;
  // Right of the bar across and of its text (at most about 4.5 text heights long), whatever their size.
  const x = Math.max(x0 + 0.3 * w, x0 + Math.max(across?.lengthMm ?? 0, 4.5 * fontSize) + fontSize);
  const y1 = yBase - k * up.lengthMm;
  group.append(
    svg('polyline', {
      points: `${x - tick},${y1} ${x},${y1} ${x},${yBase} ${x - tick},${yBase}`,
      class: 'scale-line',
    }),
  );
  addLabel(group, x + tick, yBase - 0.1 * fontSize, profileWords().high(up.text, k), {
    align: 'start',
    cls: 'dim-text scale-text',
    testId: 'profile-scale-bar-z',
  });
}

/** The text heights at the bottom of the box shown that the bars take. */
export const SCALE_ROOM = 2.6;
