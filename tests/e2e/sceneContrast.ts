/**
 * The 3D scene read from the back of a room (issue 28, point 7), measured from the pixels of a
 * screenshot: the contrast of the tool against the background and of each line drawn over the scene
 * against what lies beside it, the lines' widths, and the labels inside the canvas. Where to look
 * comes from the e2e probe (the camera, the tool, the lines' points), projected here with three.js.
 */
import type { Page } from 'playwright-core';
import { PerspectiveCamera, Vector3 } from 'three';
import { expect } from 'vitest';
import type { SceneFraming } from '../../src/render/scene';
import { countPixels } from './pixels';

/** The probe's camera as a three.js camera (to project points as the scene does). */
export function cameraOf(f: SceneFraming): PerspectiveCamera {
  const camera = new PerspectiveCamera(f.fovDeg, f.aspect, 1e-3, 1e6);
  camera.up.set(...f.up);
  camera.position.set(...f.position);
  camera.lookAt(new Vector3(...f.target));
  camera.updateMatrixWorld();
  camera.updateProjectionMatrix();
  return camera;
}

/**
 * The scene's camera and what it draws, from the e2e probe. Sent as one JSON string: Playwright
 * checks a returned array number by number, and the framed points are thousands of numbers (as an
 * array, the test file's own process spent 4.5 of its 17 CPU seconds checking them).
 */
export const framing = async (page: Page): Promise<SceneFraming | null> =>
  JSON.parse(
    await page.evaluate(() =>
      JSON.stringify(
        (
          window as unknown as { __pathInterval: { sceneFraming(): SceneFraming | null } }
        ).__pathInterval.sceneFraming(),
        // A non-finite number stays a string ("NaN"), not JSON's null: every assertion on it fails.
        (_key, value) => (typeof value === 'number' && !Number.isFinite(value) ? String(value) : value),
      ),
    ),
  ) as SceneFraming | null;

/** WCAG 2 relative luminance of an sRGB colour (0-255 channels). */
function luminance([r, g, b]: readonly number[]): number {
  const lin = (c: number) => {
    const s = c / 255;
    return s <= 0.04045 ? s / 12.92 : ((s + 0.055) / 1.055) ** 2.4;
  };
  return 0.2126 * lin(r ?? 0) + 0.7152 * lin(g ?? 0) + 0.0722 * lin(b ?? 0);
}

/** WCAG 2 contrast ratio of two colours (1 to 21). */
export function contrastRatio(a: readonly number[], b: readonly number[]): number {
  const [hi, lo] = [luminance(a), luminance(b)].sort((x, y) => y - x) as [number, number];
  return (hi + 0.05) / (lo + 0.05);
}

const median = (xs: readonly number[]): number => {
  const s = [...xs].sort((a, b) => a - b);
  return s.length === 0 ? Number.NaN : (s[Math.floor(s.length / 2)] as number);
};

/** What {@link measureScene} found. */
export interface SceneMeasure {
  /** The contrast of the tool's shank and holder against the background: the 20th percentile of the pixels sampled on them. */
  readonly toolContrast: number;
  /** Per line key (legend): samples read, the median contrast of the line's core against what is beside it, its median width (px). */
  readonly lines: Readonly<Record<string, { samples: number; contrast: number; widthPx: number }>>;
  /** The texts of the labels shown that run out of the canvas. */
  readonly labelsOutside: readonly string[];
}

/**
 * Measures the scene as shown (the page settled): a screenshot of the canvas, decoded in the page,
 * read at the tool's shank and across each line drawn over the scene.
 */
export async function measureScene(page: Page): Promise<SceneMeasure> {
  const f = await framing(page);
  if (f === null || f.tool === null) throw new Error('no scene state');
  const canvas = page.getByTestId('scene-canvas');
  const png = await canvas.screenshot();
  const { labels, badges, box } = await page.evaluate(() => {
    const rect = (e: Element) => {
      const r = e.getBoundingClientRect();
      return { text: e.textContent ?? '', left: r.left, top: r.top, right: r.right, bottom: r.bottom };
    };
    const c = document.querySelector('[data-testid="scene-canvas"]') as HTMLElement;
    const shown = (selector: string) =>
      [...document.querySelectorAll(`[data-testid="scene"] ${selector}`)].filter((e) => {
        const r = e.getBoundingClientRect();
        return e.checkVisibility({ visibilityProperty: true }) && r.width > 0 && r.height > 0;
      });
    return {
      labels: shown('.scene-label').map(rect),
      badges: shown('.scene-scale, .stale-badge').map(rect),
      box: rect(c),
    };
  });
  const labelsOutside = labels
    .filter(
      (l) =>
        l.left < box.left - 0.5 || l.right > box.right + 0.5 || l.top < box.top - 0.5 || l.bottom > box.bottom + 0.5,
    )
    .map((l) => l.text);

  const camera = cameraOf(f);
  const width = box.right - box.left;
  const height = box.bottom - box.top;
  const toPx = (p: Vector3): [number, number] => {
    const q = p.clone().project(camera);
    return [((q.x + 1) / 2) * width, ((1 - q.y) / 2) * height];
  };
  // What covers the canvas: the labels and the badges.
  const covers = [...labels, ...badges];
  const nearLabel = ([x, y]: [number, number]) =>
    covers.some(
      (l) =>
        x + box.left > l.left - 6 &&
        x + box.left < l.right + 6 &&
        y + box.top > l.top - 6 &&
        y + box.top < l.bottom + 6,
    );
  // Samples on the shank and the holder: across the axis, square to the line of sight.
  const { centre, axis, radiusMm: R } = f.tool;
  const o = new Vector3(...centre);
  const a = new Vector3(...axis);
  const sight = new Vector3(...f.target).sub(new Vector3(...f.position)).normalize();
  let across = a.clone().cross(sight);
  if (across.length() < 0.2) across = new Vector3(1, 0, 0).applyQuaternion(camera.quaternion);
  across.normalize();
  const toolPoints: Array<[number, number]> = [];
  for (let t = 0.5; t < 1.72; t += 0.08)
    for (const u of [-0.85, -0.7, -0.55, -0.4, -0.25, 0.25, 0.4, 0.55, 0.7, 0.85]) {
      const p = toPx(
        o
          .clone()
          .addScaledVector(a, t * R)
          .addScaledVector(across, u * R),
      );
      if (!nearLabel(p)) toolPoints.push(p);
    }
  // Samples across each line, away from the labels and the canvas's edges.
  const OFFSETS = 12;
  const lineSamples: Array<{ key: string; widthPx: number; at: [number, number]; n: [number, number] }> = [];
  for (const line of f.lines) {
    const pts: Array<[number, number]> = [];
    for (let i = 0; i < line.points.length; i += 3)
      pts.push(toPx(new Vector3(line.points[i], line.points[i + 1], line.points[i + 2])));
    for (let i = 0; i + 1 < pts.length; i++) {
      const [p, q] = [pts[i] as [number, number], pts[i + 1] as [number, number]];
      const len = Math.hypot(q[0] - p[0], q[1] - p[1]);
      if (len < 2.5) continue;
      const mid: [number, number] = [(p[0] + q[0]) / 2, (p[1] + q[1]) / 2];
      if (mid[0] < 16 || mid[1] < 16 || mid[0] > width - 16 || mid[1] > height - 16 || nearLabel(mid)) continue;
      lineSamples.push({
        key: line.key,
        widthPx: line.widthPx,
        at: mid,
        n: [-(q[1] - p[1]) / len, (q[0] - p[0]) / len],
      });
    }
  }
  const requests: Array<[number, number]> = [[width - 6, 6], ...toolPoints];
  for (const s of lineSamples)
    for (let k = -OFFSETS; k <= OFFSETS; k++) requests.push([s.at[0] + k * s.n[0], s.at[1] + k * s.n[1]]);
  const { counts } = await countPixels(page, [png], { kind: 'at', points: requests });
  const colours = requests.map((_, i) => counts.slice(3 * i, 3 * i + 3));
  const background = colours[0] as number[];
  if (toolPoints.length < 10) throw new Error('the tool is covered by labels: no place to measure it');
  // The tool's pixels: a fifth of them may be crossed by the marks drawn over it (their halos).
  const toolContrasts = colours
    .slice(1, 1 + toolPoints.length)
    .map((c) => contrastRatio(c, background))
    .sort((x, y) => x - y);
  const toolContrast = toolContrasts[Math.floor(0.2 * toolContrasts.length)] as number;
  const perKey: Record<string, { contrast: number[]; width: number[] }> = {};
  let next = 1 + toolPoints.length;
  for (const s of lineSamples) {
    const across = colours.slice(next, next + 2 * OFFSETS + 1);
    next += 2 * OFFSETS + 1;
    const core = across[OFFSETS] as number[];
    const like = (c: number[] | undefined) =>
      c !== undefined &&
      Math.abs((c[0] as number) - (core[0] as number)) +
        Math.abs((c[1] as number) - (core[1] as number)) +
        Math.abs((c[2] as number) - (core[2] as number)) <=
        60;
    let lo = OFFSETS;
    while (lo > 0 && like(across[lo - 1])) lo--;
    let hi = OFFSETS;
    while (hi < 2 * OFFSETS && like(across[hi + 1])) hi++;
    // What lies beside the core each side: of the two pixels past its edge (the first may blend the
    // two where the view is antialiased), the one that differs most from it.
    const beside = (edge: number, step: 1 | -1) =>
      Math.max(
        ...[1, 2].map((d) =>
          contrastRatio(core, across[Math.min(2 * OFFSETS, Math.max(0, edge + step * d))] as number[]),
        ),
      );
    const left = beside(lo, -1);
    const right = beside(hi, 1);
    const entry = perKey[s.key] ?? { contrast: [], width: [] };
    perKey[s.key] = entry;
    entry.contrast.push(Math.min(left, right));
    entry.width.push(hi - lo + 1);
  }
  const lines: Record<string, { samples: number; contrast: number; widthPx: number }> = {};
  for (const [key, v] of Object.entries(perKey))
    lines[key] = { samples: v.contrast.length, contrast: median(v.contrast), widthPx: median(v.width) };
  return { toolContrast, lines, labelsOutside };
}

/** The least contrast the issue asks of the tool and the lines against the background (WCAG's for graphics). */
export const LEAST_CONTRAST = 3;
/** The least width of a line (px). */
export const LEAST_LINE_PX = 2;

/**
 * Measures the scene ({@link measureScene}), logs the figures and checks them: the tool (unless
 * `tool` is false: a close-up inside it) and every line read (at least 3:1, lines at least 2 px,
 * the step-over's paths among them), no label outside the canvas.
 */
export async function expectLegible(page: Page, where: string, { tool = true } = {}): Promise<SceneMeasure> {
  const m = await measureScene(page);
  const lines = Object.entries(m.lines)
    .map(([k, v]) => `${k} ${v.contrast.toFixed(2)}:1 ${v.widthPx}px (${v.samples})`)
    .join(', ');
  console.log(`${where}: tool ${m.toolContrast.toFixed(2)}:1; ${lines}`);
  expect(m.labelsOutside, `${where}: labels outside the canvas`).toEqual([]);
  if (tool) {
    expect(m.toolContrast, `${where}: the tool against the background`).toBeGreaterThanOrEqual(LEAST_CONTRAST);
    // The paths at least (on a phone the labels may cover every free stretch of the dimensions).
    expect(Object.keys(m.lines), `${where}: the paths are measured`).toContain('path');
  }
  for (const [key, v] of Object.entries(m.lines)) {
    if (v.samples < 3) continue;
    expect(v.contrast, `${where}: the ${key} line against what is beside it`).toBeGreaterThanOrEqual(LEAST_CONTRAST);
    expect(v.widthPx, `${where}: the ${key} line's width`).toBeGreaterThanOrEqual(LEAST_LINE_PX);
  }
  return m;
}
