/**
 * The cross-feed profile's drawing (SVG), one drawing over the design surface: three passes L apart
 * (mirrored on alternate passes for zigzag) with the scallops shaded, the h pseudo surface, the ring
 * ellipse, each approximation's profile tangent at each contact, the cusp heights, the flanks'
 * widths, L and the tool centre O; on a curved surface also where the plane's answer and the
 * corrected procedures put the next pass.
 *
 * Everything is placed in surface coordinates (s across the feed along the surface, h radially
 * above it) and mapped to the section by surfaceGeometry.ts, the heights exaggerated by k and the
 * surface at true scale. A plane is the surface of infinite radius: there the map is (s, h) -> (s,
 * h) and each line along the surface is one straight segment. A new surface brings its section's
 * map and its pass profile (data), not a branch here: a doubly curved point brings the circle of
 * radius Rc and the pass its two flanks make (curvedProfileSection).
 */

import { PLANE } from '../../core/domain/surface';
import { lowestPassHeight, monotoneProfile, sectionRadiusMm } from '../../core/output/sectionProfile';
import { fromSurfaceSection, toSurfaceSection } from '../../core/output/surfaceGeometry';
import { PROCEDURE_KEYS, type ProcedureKey } from '../../core/procedures/procedures';
import type { Surface } from '../../core/surfaces/cylinder';
import type { CylinderCurves, ProfileCurveSet } from '../../worker/protocol';
import type { CurvedSectionData } from '../../worker/teachProtocol';
import { formatLenUnit } from '../format';
import type { Unit } from '../state';
import { svg, type TeachOk } from './common';
import { addLabel } from './profileLabels';
import { type Box, homeBox, type ProfileLayout } from './profileLayout';
import { SCALE_ROOM } from './profileScaleBars';
import { profileWords } from './profileWords';

/** What is drawn: one pass's profile on a surface (the worker's data, in surface coordinates). */
export interface ProfileSection {
  readonly surface: Surface;
  /** One pass's exact profile (flat s, h), from the left flank's widest point to the right one's. */
  readonly passProfile: Float64Array;
  /** The ring ellipse the pass profile is offset from (same coordinates), or null where it is not. */
  readonly ringEllipse: Float64Array | null;
  /**
   * Where the plane's answer and the corrected procedures put the next pass (none on a plane); at a
   * doubly curved point also each cylinder's (`cylinderAlong`, `cylinderAcross`).
   */
  readonly comparison: ReadonlyArray<{
    readonly key: CylinderCurves['comparison'][number]['key'] | 'cylinderAlong' | 'cylinderAcross';
    readonly intervalMm: number | null;
  }>;
}

/**
 * The section a reply's data draws: on a plane its plane profile; on a cylinder the curves the
 * worker gave in surface coordinates, the ring ellipse only where the pass profile is the plane
 * profile turned about the axis (axis along the feed; across it the tool is revolved instead).
 */
export function profileSection(data: TeachOk): ProfileSection {
  const c = data.cylinder;
  if (c === null)
    return { surface: PLANE, passProfile: data.curves.profile, ringEllipse: data.curves.ringEllipse, comparison: [] };
  return {
    surface: c.surface,
    passProfile: c.passProfile,
    ringEllipse: c.surface.axis === 'feed' ? c.ringEllipse : null,
    comparison: c.comparison,
  };
}

/**
 * The section at a doubly curved point (the worker's data/curvedSection.ts): across the feed the
 * circle of radius Rc, drawn as the cylinder of that radius with its axis along the feed; no ring
 * ellipse (the pass is not the plane profile turned about one axis).
 */
export function curvedProfileSection(data: CurvedSectionData): ProfileSection {
  return {
    surface: { kind: 'cylinder', radiusMm: data.crossRadiusMm, axis: 'feed' },
    passProfile: data.passProfile,
    ringEllipse: null,
    comparison: data.comparison,
  };
}

/** What the drawing needs besides its section. */
export interface ProfileDrawingInput {
  readonly section: ProfileSection;
  readonly exact: TeachOk['exact'];
  readonly approximations: ProfileCurveSet['approximations'];
  /** No tilt: the profile is symmetric, and the paper's L/2 is each flank's width. */
  readonly untilted: boolean;
  readonly unit: Unit;
  readonly layout: ProfileLayout;
  /**
   * The labels' height in display units at the home box (the view's text size there): the rows of
   * labels below the surface are spaced by it.
   */
  readonly labelSize: number;
}

/**
 * Below the surface, where no curve runs, the labels' rows (depths in label heights, display units
 * down from the surface): the cusp heights' baseline (each label beside a leader from its dimension),
 * the flanks' widths or L/2 and their dimension line, L and its line; then the scale bars' room (the
 * view draws them at the bottom of the box shown). The home box reaches {@link LABELS_DEPTH} down.
 */
const ROWS = {
  heightsLeader: 0.3,
  heightsText: 1.25,
  widthsLine: 1.9,
  widthsText: 3.15,
  intervalLine: 4.1,
  intervalText: 5.35,
} as const;
export const LABELS_DEPTH = 5.75 + SCALE_ROOM;

/** What a drawing leaves to the view. */
export interface ProfileDrawn {
  /** Everything drawn, with a margin (display coordinates). */
  readonly home: Box;
  /** The right cusp (display coordinates), where "Zoom to cusp" goes. */
  readonly cuspX: number;
  readonly cuspY: number;
}

/** A drawing's map from surface coordinates (s, h above the surface; mm) to display coordinates. */
interface SectionMap {
  /** The display point (x, y) of the point `hr` above the surface at `sMm`. */
  at(sMm: number, hr: number): [number, number];
  /** The same as SVG points text, `x,y`. */
  pt(sMm: number, hr: number): string;
  /** `n + 1` points from `from` to `to` along the surface, `hr(s)` above it, as `x,y` texts. */
  along(from: number, to: number, hr: (sMm: number) => number, n: number): string[];
  /** Segments for a line along the surface that `n` segments draw on a curved section (1 on a straight one). */
  segments(n: number): number;
}

/** Samples of the scallops' top (the lower envelope of the three passes). */
const ENVELOPE_SAMPLES = 600;

/**
 * Draws a section into `layer` (emptied first), each procedure's curves kept in `curves` (emptied
 * first) for highlighting.
 */
export function drawProfile(
  layer: SVGGElement,
  curves: Map<ProcedureKey, SVGElement[]>,
  input: ProfileDrawingInput,
): ProfileDrawn {
  const { section, exact: ex } = input;
  const { surface, passProfile } = section;
  const { k, topMm: top, fromMm, toMm, d } = input.layout;
  const L = ex.intervalMm;
  const h = ex.cuspHeightMm;
  layer.replaceChildren();
  curves.clear();
  // A straight section: each line along the surface in one segment.
  const straight = !Number.isFinite(sectionRadiusMm(surface));
  const segments = (n: number) => (straight ? 1 : n);
  const xy: [number, number] = [0, 0];
  const at = (sMm: number, hr: number): [number, number] => {
    fromSurfaceSection(surface, sMm, k * hr, xy);
    return [xy[0], -xy[1]];
  };
  // The highest point of the profiles drawn (display y, up negative; the faint ring ellipse may run
  // out of the plot): the label above the drawing goes above it.
  let curvesTopY = Number.POSITIVE_INFINITY;
  const pt = (sMm: number, hr: number) => {
    fromSurfaceSection(surface, sMm, k * hr, xy);
    return `${xy[0]},${-xy[1]}`;
  };
  const along = (from: number, to: number, hr: (sMm: number) => number, n: number) => {
    const parts: string[] = [];
    for (let i = 0; i <= n; i++) {
      const sMm = from + ((to - from) * i) / n;
      parts.push(pt(sMm, hr(sMm)));
    }
    return parts;
  };
  const add = (tag: 'polyline' | 'polygon' | 'line', props: Record<string, string | number>) => {
    const e = svg(tag, props);
    layer.append(e);
    return e;
  };
  // The passes: contact at -L, 0, L; for zigzag the neighbours are mirror images.
  const mirrored = ex.pattern === 'zigzag';
  const centres = [-L, 0, L];
  const mirrors: (1 | -1)[] = [mirrored ? -1 : 1, 1, mirrored ? -1 : 1];
  const profile = monotoneProfile(passProfile);

  // Scallops: between the surface and the lower envelope of the three passes, kept within the band
  // drawn (where no pass reaches, as at the very edge of a flat end lying flat, the envelope is
  // +infinity: the drawing stops at its top, never at an infinite point).
  const envelope = along(
    -L,
    L,
    (sMm) => Math.min(lowestPassHeight(profile, centres, mirrors, sMm), top),
    ENVELOPE_SAMPLES,
  );
  const floor = along(L, -L, () => 0, segments(120));
  add('polygon', { points: [...envelope, ...floor].join(' '), class: 'scallop', 'data-testid': 'profile-scallop' });
  add('polyline', {
    points: along(fromMm, toMm, () => 0, segments(240)).join(' '),
    class: 'ground',
    'data-testid': 'profile-surface',
  });
  add('polyline', {
    points: along(fromMm, toMm, () => h, segments(240)).join(' '),
    class: 'hplane',
    'data-testid': 'profile-h-surface',
  });
  // The ring ellipse of the middle pass, faint.
  const ring = section.ringEllipse;
  if (ring !== null) {
    const parts: string[] = [];
    for (let i = 0; i + 1 < ring.length; i += 2) parts.push(pt(ring[i] as number, ring[i + 1] as number));
    add('polyline', { points: parts.join(' '), class: 'ring' });
  }
  const curve = (key: ProcedureKey, points: string) => {
    const line = add('polyline', { points, class: `curve curve-${key}`, 'data-procedure': key });
    for (const p of (line as SVGPolylineElement).points) curvesTopY = Math.min(curvesTopY, p.y);
    const list = curves.get(key) ?? [];
    list.push(line);
    curves.set(key, list);
  };
  // The approximations (symmetric: their right halves on both sides), tangent to the surface at each contact.
  for (const key of PROCEDURE_KEYS) {
    if (key === 'exact') continue;
    const pts = input.approximations[key];
    if (!pts) continue;
    for (const side of [1, -1]) {
      const local: number[] = [];
      for (let i = 0; i + 1 < pts.length; i += 2) {
        if ((pts[i + 1] as number) > top) break;
        local.push(side * (pts[i] as number), pts[i + 1] as number);
      }
      const onSurface = toSurfaceSection(surface, local);
      for (const c of centres) {
        const parts: string[] = [];
        for (let i = 0; i + 1 < onSurface.length; i += 2)
          parts.push(pt(c + (onSurface[i] as number), onSurface[i + 1] as number));
        curve(key, parts.join(' '));
      }
    }
  }
  // The exact profile of each pass, whole (both flanks).
  centres.forEach((c, j) => {
    const m = mirrors[j] as 1 | -1;
    const parts: string[] = [];
    for (let i = 0; i + 1 < passProfile.length; i += 2) {
      const hr = passProfile[i + 1] as number;
      if (hr <= top) parts.push(pt(c + m * (passProfile[i] as number), hr));
    }
    curve('exact', parts.join(' '));
  });
  // Where the plane's answer and the corrected procedures put the next pass: a mark on the
  // surface at their L, and for the plane's answer that pass's exact profile, dashed.
  for (const row of section.comparison) {
    if (row.intervalMm === null || !(row.intervalMm < toMm)) continue;
    const sMm = row.intervalMm;
    add('polyline', {
      points: [pt(sMm, 0), pt(sMm, 0.6 * top)].join(' '),
      class: 'curve comparison-mark',
      'data-curvature': row.key,
    });
    if (row.key === 'plane') {
      const m = mirrored ? -1 : 1;
      const parts: string[] = [];
      for (let i = 0; i + 1 < profile.length; i += 2) {
        const hr = profile[i + 1] as number;
        if (hr <= top) parts.push(pt(sMm + m * (profile[i] as number), hr));
      }
      add('polyline', {
        points: parts.join(' '),
        class: 'curve comparison-pass',
        'data-curvature': 'plane',
        'data-testid': 'profile-plane-pass',
      });
    }
  }
  // Home: everything drawn (the outer passes, the band, the labels below the surface and above it).
  let minX = Number.POSITIVE_INFINITY;
  let maxX = Number.NEGATIVE_INFINITY;
  let minY = Number.POSITIVE_INFINITY;
  let maxY = Number.NEGATIVE_INFINITY;
  const reach = (x: number, y: number) => {
    minX = Math.min(minX, x);
    maxX = Math.max(maxX, x);
    minY = Math.min(minY, y);
    maxY = Math.max(maxY, y);
  };
  for (const sMm of [fromMm, toMm, 0, -L, L, (fromMm + toMm) / 2]) for (const hr of [top, 0]) reach(...at(sMm, hr));
  const labels = drawDimensions(layer, input, { at, pt, along, segments }, Math.min(minY, curvesTopY));
  reach(minX, Math.min(minY, labels.topY));
  reach(minX, labels.bottomY);
  const [cuspX, cuspY] = at(ex.right.yMm, ex.right.heightMm);
  return { home: homeBox(minX, maxX, minY, maxY, d), cuspX, cuspY };
}

/**
 * Cusp heights (radially, each labelled below the surface at the end of a leader), the flanks'
 * widths to their cusps and L (along the surface, below it) and the tool centre O (labelled above the
 * band, whose top is at `bandTopY`). The labels below stand in rows ({@link ROWS}) under the lowest
 * point of the surface beneath them, so that a curved section never runs through a text; each
 * dimension line is the surface's own shape moved down to its row, its text under it. Returns how
 * high and how low the labels reach (display y).
 */
function drawDimensions(
  layer: SVGGElement,
  input: ProfileDrawingInput,
  map: SectionMap,
  bandTopY: number,
): { readonly topY: number; readonly bottomY: number } {
  const { at, pt, segments } = map;
  const { exact: ex, unit, section, labelSize: t } = input;
  const { topMm: top, d, fromMm, toMm } = input.layout;
  const L = ex.intervalMm;
  const y0 = ex.contactOffsetMm;
  // Every label a length with its unit (format.ts).
  const f = (mm: number) => formatLenUnit(mm, unit);
  const fh = (mm: number) => formatLenUnit(mm, unit, 'height');
  const { right, left } = ex;
  const name = (c: { heightMm: number }) => (c.heightMm >= Math.max(right.heightMm, left.heightMm) ? 'h' : "h'");
  /** The surface's lowest point on screen (largest y) from `from` to `to` (mm along it). */
  const lowest = (from: number, to: number) => {
    let y = Number.NEGATIVE_INFINITY;
    const n = segments(48);
    for (let i = 0; i <= n; i++) y = Math.max(y, at(from + ((to - from) * i) / n, 0)[1]);
    return y;
  };
  // Under the labels: from the left cusp to L, with room for their texts either side.
  const ground = lowest(Math.max(fromMm, Math.min(0, left.yMm) - 8 * t), Math.min(toMm, L + 8 * t));
  const rowY = (n: number) => ground + n * t;
  // A cusp's height: its dimension from the surface up, a leader from the surface down to its label's
  // row, the label beside the leader (outwards: right of the right cusp, left of the left one).
  const radial = (sMm: number, hr: number, label: string, side: 1 | -1) => {
    const [a, b] = at(sMm, 0);
    const [c, e] = at(sMm, hr);
    layer.append(svg('line', { x1: a, y1: b, x2: c, y2: e, class: 'dim' }));
    layer.append(svg('line', { x1: a, y1: b, x2: a, y2: rowY(ROWS.heightsLeader), class: 'dim leader' }));
    addLabel(layer, a + side * 0.3 * t, rowY(ROWS.heightsText), label, {
      align: side > 0 ? 'start' : 'end',
      row: 'heights',
    });
  };
  const dimension = (from: number, to: number, line: number, text: number, row: string, label: string) => {
    const shift = rowY(line) - lowest(from, to);
    const n = segments(48);
    const points: string[] = [];
    for (let i = 0; i <= n; i++) {
      const [x, y] = at(from + ((to - from) * i) / n, 0);
      points.push(`${x},${y + shift}`);
    }
    layer.append(svg('polyline', { points: points.join(' '), class: 'dim' }));
    addLabel(layer, at((from + to) / 2, 0)[0], rowY(text), label, { row });
  };
  radial(right.yMm, right.heightMm, `${name(right)} = ${fh(right.heightMm)}`, 1);
  if (!input.untilted) radial(left.yMm, left.heightMm, `${name(left)} = ${fh(left.heightMm)}`, -1);
  const { widthsLine, widthsText, intervalLine, intervalText } = ROWS;
  if (input.untilted || ex.pattern === 'zigzag')
    dimension(0, L / 2, widthsLine, widthsText, 'widths', `L/2 = ${f(L / 2)}`);
  else {
    dimension(0, right.yMm, widthsLine, widthsText, 'widths', `wR = ${f(right.yMm)}`);
    dimension(left.yMm, 0, widthsLine, widthsText, 'widths', `wL = ${f(-left.yMm)}`);
  }
  const arc = Number.isFinite(sectionRadiusMm(section.surface)) ? profileWords().arc : '';
  dimension(0, L, intervalLine, intervalText, 'interval', `L = ${f(L)}${arc}`);
  let topY = Number.POSITIVE_INFINITY;
  if (y0 !== 0) {
    // The tool centre O: -y0 across the feed in the contact's tangent plane.
    const n = segments(8);
    const local: number[] = [];
    for (let i = 0; i <= n; i++) local.push(-y0, (top * i) / n);
    const onSurface = toSurfaceSection(section.surface, local);
    const parts: string[] = [];
    for (let i = 0; i + 1 < onSurface.length; i += 2)
      parts.push(pt(onSurface[i] as number, onSurface[i + 1] as number));
    layer.append(svg('polyline', { points: parts.join(' '), class: 'centre-line' }));
    const [ox] = at(onSurface[onSurface.length - 2] as number, onSurface[onSurface.length - 1] as number);
    // Above the band drawn (every curve ends at its top), on its halo.
    addLabel(layer, ox + d / 3, bandTopY - 0.45 * t, `O (y0 = ${f(y0)})`, {
      align: 'start',
      cls: 'dim-text centre-text',
    });
    topY = bandTopY - 1.6 * t;
  }
  return { topY, bottomY: rowY(LABELS_DEPTH) };
}
