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

import { lowestPassHeight, monotoneProfile, sectionRadiusMm } from '../../core/output/sectionProfile';
import { fromSurfaceSection, toSurfaceSection } from '../../core/output/surfaceGeometry';
import { PROCEDURE_KEYS, type ProcedureKey } from '../../core/procedures/procedures';
import type { Surface } from '../../core/surfaces/cylinder';
import { PLANE } from '../../core/surfaces/cylinder';
import type { CylinderCurves, ProfileCurveSet } from '../../worker/protocol';
import type { CurvedSectionData } from '../../worker/teachProtocol';
import { formatLenUnit } from '../format';
import type { Unit } from '../state';
import { svg, type TeachOk } from './common';
import { type Box, homeBox, type ProfileLayout } from './profileLayout';

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
}

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

  // Scallops: between the surface and the lower envelope of the three passes.
  const envelope = along(-L, L, (sMm) => lowestPassHeight(profile, centres, mirrors, sMm), ENVELOPE_SAMPLES);
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
      points: [pt(sMm, -0.15 * top), pt(sMm, 0.6 * top)].join(' '),
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
  drawDimensions(layer, input, { at, pt, along, segments });
  // Home: everything drawn (the outer passes, the band and the dimensions below the surface).
  let minX = Number.POSITIVE_INFINITY;
  let maxX = Number.NEGATIVE_INFINITY;
  let minY = Number.POSITIVE_INFINITY;
  let maxY = Number.NEGATIVE_INFINITY;
  for (const sMm of [fromMm, toMm, 0, -L, L, (fromMm + toMm) / 2]) {
    for (const hr of [top, -(5 * d) / k, 0]) {
      const [x, y] = at(sMm, hr);
      minX = Math.min(minX, x);
      maxX = Math.max(maxX, x);
      minY = Math.min(minY, y);
      maxY = Math.max(maxY, y);
    }
  }
  const [cuspX, cuspY] = at(ex.right.yMm, ex.right.heightMm);
  return { home: homeBox(minX, maxX, minY, maxY, d), cuspX, cuspY };
}

/** Cusp heights (radially), the flanks' widths to their cusps and L (along the surface below it), and the tool centre O. */
function drawDimensions(layer: SVGGElement, input: ProfileDrawingInput, map: SectionMap): void {
  const { at, pt, along, segments } = map;
  const { exact: ex, unit, section } = input;
  const { k, topMm: top, d } = input.layout;
  const L = ex.intervalMm;
  const y0 = ex.contactOffsetMm;
  /** A height `n` spacings below the surface. */
  const below = (n: number) => -(n * d) / k;
  // Every label a length with its unit (format.ts).
  const f = (mm: number) => formatLenUnit(mm, unit);
  const fh = (mm: number) => formatLenUnit(mm, unit, 'height');
  const { right, left } = ex;
  const name = (c: { heightMm: number }) => (c.heightMm >= Math.max(right.heightMm, left.heightMm) ? 'h' : "h'");
  const text = (x: number, y: number, label: string, cls = 'dim-text') => {
    const t = svg('text', { x, y, class: cls });
    t.textContent = label;
    layer.append(t);
  };
  const radial = (sMm: number, hr: number, label: string) => {
    const [a, b] = at(sMm, 0);
    const [c, e] = at(sMm, hr);
    layer.append(svg('line', { x1: a, y1: b, x2: c, y2: e, class: 'dim' }));
    text((a + c) / 2 + d / 2, (b + e) / 2, label);
  };
  const arcDim = (from: number, to: number, level: number, label: string) => {
    layer.append(
      svg('polyline', { points: along(from, to, () => below(level), segments(48)).join(' '), class: 'dim' }),
    );
    const [mx, my] = at((from + to) / 2, below(level));
    text(mx, my - d / 3, label);
  };
  radial(right.yMm, right.heightMm, `${name(right)} = ${fh(right.heightMm)}`);
  if (!input.untilted) radial(left.yMm, left.heightMm, `${name(left)} = ${fh(left.heightMm)}`);
  if (input.untilted || ex.pattern === 'zigzag') arcDim(0, L / 2, 2, `L/2 = ${f(L / 2)}`);
  else {
    arcDim(0, right.yMm, 2, `wR = ${f(right.yMm)}`);
    arcDim(left.yMm, 0, 2, `wL = ${f(-left.yMm)}`);
  }
  const arc = Number.isFinite(sectionRadiusMm(section.surface)) ? ' (arc)' : '';
  arcDim(0, L, 4, `L = ${f(L)}${arc}`);
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
    const [ox, oy] = at(onSurface[onSurface.length - 2] as number, onSurface[onSurface.length - 1] as number);
    text(ox + d / 3, oy + d, `O (y0 = ${f(y0)})`, 'dim-text centre-text');
  }
}
