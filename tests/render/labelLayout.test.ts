/** Placement of the 3D scene's labels (pure part of render/scene.ts). */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { type LabelRequest, type PixelRect, placeLabels, rectsIntersect } from '../../src/render/labelLayout';

const label = (x: number, y: number, side: readonly [number, number], priority = 1, w = 80, h = 14): LabelRequest => ({
  anchorXPx: x,
  anchorYPx: y,
  widthPx: w,
  heightPx: h,
  side,
  priority,
});

/** The boxes of the visible labels. */
function boxes(
  labels: readonly LabelRequest[],
  width: number,
  height: number,
  obstacles: PixelRect[] = [],
): PixelRect[] {
  return placeLabels(labels, width, height, obstacles).flatMap((p, i) => {
    const l = labels[i] as LabelRequest;
    if (!p.visible) return [];
    const cx = l.anchorXPx + p.dxPx;
    const cy = l.anchorYPx + p.dyPx;
    return [
      { left: cx - l.widthPx / 2, top: cy - l.heightPx / 2, right: cx + l.widthPx / 2, bottom: cy + l.heightPx / 2 },
    ];
  });
}

describe('scene labels', () => {
  it('a lone label sits on its preferred side, clear of its anchor', () => {
    const [below] = placeLabels([label(200, 100, [0, 1])], 400, 300);
    expect(below).toEqual({ dxPx: 0, dyPx: 7 + 6, visible: true });
    const [right] = placeLabels([label(200, 100, [1, 0])], 400, 300);
    expect(right).toEqual({ dxPx: 40 + 6, dyPx: 0, visible: true });
    const [centred] = placeLabels([label(200, 100, [0, 0])], 400, 300);
    expect(centred).toEqual({ dxPx: 0, dyPx: 0, visible: true });
  });

  it('two labels at one point: the more important keeps its side, the other moves clear (y0 and CC)', () => {
    const cc = label(200, 100, [0, 1], 9);
    const y0 = label(200, 100, [0, 1], 5, 110);
    const [a, b] = boxes([y0, cc], 400, 300);
    expect(placeLabels([y0, cc], 400, 300)[1]).toEqual({ dxPx: 0, dyPx: 13, visible: true });
    expect(rectsIntersect(a as PixelRect, b as PixelRect)).toBe(false);
  });

  it('a label near the edge turns inward; one whose anchor is off the scene is hidden', () => {
    const [p] = placeLabels([label(395, 100, [1, 0])], 400, 300);
    expect(p?.visible).toBe(true);
    expect(395 + (p?.dxPx ?? 0) + 40).toBeLessThanOrEqual(399);
    expect(placeLabels([label(-5, 100, [1, 0])], 400, 300)[0]?.visible).toBe(false);
  });

  it('keeps clear of obstacles (a badge)', () => {
    const badge = { left: 0, top: 270, right: 200, bottom: 300 };
    const [b] = boxes([label(100, 265, [0, 1])], 400, 300, [badge]);
    expect(rectsIntersect(b as PixelRect, badge)).toBe(false);
  });

  it('property: visible labels never intersect and never leave the box', () => {
    const side = fc.constantFrom<readonly [number, number]>([0, 1], [1, -0.8], [-1, -0.8], [0, -1], [0, 0], [1, 0]);
    const one = fc.record({
      anchorXPx: fc.double({ min: -20, max: 420, noNaN: true }),
      anchorYPx: fc.double({ min: -20, max: 320, noNaN: true }),
      widthPx: fc.double({ min: 8, max: 140, noNaN: true }),
      heightPx: fc.double({ min: 8, max: 18, noNaN: true }),
      side,
      priority: fc.integer({ min: 0, max: 10 }),
    });
    fc.assert(
      fc.property(fc.array(one, { maxLength: 14 }), (labels) => {
        const placed = boxes(labels, 400, 300);
        for (const r of placed) {
          expect(r.left).toBeGreaterThanOrEqual(1);
          expect(r.top).toBeGreaterThanOrEqual(1);
          expect(r.right).toBeLessThanOrEqual(399);
          expect(r.bottom).toBeLessThanOrEqual(299);
        }
        for (let i = 0; i < placed.length; i++)
          for (let j = i + 1; j < placed.length; j++)
            expect(rectsIntersect(placed[i] as PixelRect, placed[j] as PixelRect)).toBe(false);
      }),
    );
  });
});
