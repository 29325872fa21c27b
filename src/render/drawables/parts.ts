/**
 * What the 3D scene's drawables share: the state one update draws, their colours (and the theme's
 * names for them), and the parts they are made of: lines drawn over everything and filled in place,
 * the marked points, and the disposal of what they made. Each drawable (a module of this folder)
 * builds its objects once, updates them in place from a {@link DrawState}, and frees them.
 */
import {
  type BufferAttribute,
  type BufferGeometry,
  type Material,
  Mesh,
  MeshBasicMaterial,
  type Object3D,
  type SphereGeometry,
} from 'three';
import type { SceneGeometry } from '../../worker/protocol';
import { FatLine, FatLineMaterial } from '../fatLines';
import { drawHeightsInPlace, type HeightMap } from '../heightExaggeration';
import { legend } from '../labelLayer';
import type { SceneLabels } from '../sceneLabels';

/** What one update draws: the solved state, its labels, and the sizes the drawables share (mm). */
export interface DrawState {
  readonly geometry: SceneGeometry;
  readonly labels: SceneLabels;
  /** The heights drawn (exaggerated near a plane when the scallop is too low to see). */
  readonly map: HeightMap;
  readonly toolRadiusMm: number;
  readonly intervalMm: number;
  /** The radius of a marked point's dot. */
  readonly dotRadiusMm: number;
  /** The passes are drawn from x = fromMm to x = toMm along the feed. */
  readonly fromMm: number;
  readonly toMm: number;
}

/** A part of the scene: built once, updated in place, freed with `dispose`. */
export interface Drawable {
  /** Its objects, added to the scene once. */
  readonly objects: readonly Object3D[];
  update(state: DrawState): void;
  dispose(): void;
}

export const COLOURS = {
  section: 0xc2410c,
  loop: 0xd6336c,
  axis: 0x444444,
  dimension: 0x111111,
  contact: 0x1b7f3b,
  centre: 0x374151,
  pHp: 0xd6336c,
  trace: 0x7c3aed,
  path: 0x1b7f3b,
  tool: 0x4b5a6e,
  holder: 0x2b3442,
  ghost: 0x6c7a89,
  plane: 0xc9ced6,
  hPlane: 0x2f80ed,
  ridge: 0xb4235a,
  x: 0xd62828,
  y: 0x0f766e,
  z: 0x1d4ed8,
} as const;

/**
 * The stylesheet's custom property for each colour of the scene (theme.ts switches them with the
 * page's light or dark theme); the constants above are the light values and the fallback.
 */
export const THEMED_COLOURS: ReadonlyMap<number, string> = new Map([
  [COLOURS.section, '--scene-section'],
  [COLOURS.loop, '--scene-loop'],
  [COLOURS.axis, '--scene-axis'],
  [COLOURS.dimension, '--scene-dimension'],
  [COLOURS.contact, '--scene-contact'],
  [COLOURS.centre, '--scene-centre'],
  [COLOURS.trace, '--scene-trace'],
  [COLOURS.tool, '--scene-tool'],
  [COLOURS.holder, '--scene-holder'],
  [COLOURS.ghost, '--scene-ghost'],
  [COLOURS.plane, '--scene-plane'],
  [COLOURS.hPlane, '--scene-hplane'],
  [COLOURS.ridge, '--scene-ridge'],
  [COLOURS.x, '--scene-x'],
  [COLOURS.y, '--scene-y'],
  [COLOURS.z, '--scene-z'],
]);

/** Points of a circle drawn as a section (a cusp's, the traced one). */
export const SECTION_POINTS = 96;

/**
 * The width of the scene's lines (CSS px; a projector's reader at the back of a room): the marks of
 * the answer (paths, dimensions, sections, axes) and the thinner ones (outlines, grids).
 */
export const MARK_LINE_PX = 3;
export const THIN_LINE_PX = 2;

/** A line of up to `capacity` points, `widthPx` wide, drawn over everything (no depth test) on a halo, empty until written. */
export function lineOf(capacity: number, color: number, loop = false, widthPx = MARK_LINE_PX): FatLine {
  const line = new FatLine(capacity, new FatLineMaterial(color, widthPx, { overlay: true }), loop ? 'loop' : 'strip');
  line.renderOrder = 10;
  // Its halo (the background's colour, a pixel wider each side), drawn before every such line.
  const halo = new Mesh(line.geometry, new FatLineMaterial('halo', widthPx, { overlay: true }));
  halo.frustumCulled = false;
  halo.renderOrder = 9;
  line.add(halo);
  return line;
}

/** The points of a line (written in place, then {@link finishLine}d), or the vertex buffer of a points object. */
export function positionsOf(object: FatLine | { geometry: BufferGeometry }): Float32Array {
  if (object instanceof FatLine) return object.points;
  return (object.geometry.getAttribute('position') as BufferAttribute).array as Float32Array;
}

/**
 * Marks the first `count` points of a line (or points) object as written: drawn from the next
 * frame on. With `map`, their heights are first drawn through it (in place).
 */
export function finishLine(object: FatLine | { geometry: BufferGeometry }, count: number, map?: HeightMap): void {
  if (object instanceof FatLine) {
    object.finish(count, map);
    return;
  }
  const attr = object.geometry.getAttribute('position') as BufferAttribute;
  const n = Math.min(count, attr.count);
  if (map !== undefined) drawHeightsInPlace(map, attr.array as Float32Array, n);
  attr.needsUpdate = true;
  object.geometry.setDrawRange(0, n);
}

/** Writes `count` points (flat xyz) into a line (as many as it holds), heights drawn through `map`. */
export function writeLine(line: FatLine, points: ArrayLike<number>, count: number, map?: HeightMap): void {
  const arr = line.points;
  const n = Math.min(count, arr.length / 3);
  for (let i = 0; i < n * 3; i++) arr[i] = points[i] as number;
  line.finish(n, map);
}

/**
 * A marked point: a dot of `color` (the unit sphere `dot`, scaled by the drawable) drawn over
 * everything, that labels keep clear of, with its legend entry.
 */
export function markerOf(dot: SphereGeometry, color: number, key: string): Mesh {
  // Transparent (at full opacity): drawn after the translucent surfaces, not under them.
  const m = legend(new Mesh(dot, new MeshBasicMaterial({ color, depthTest: false, transparent: true })), key);
  m.renderOrder = 11;
  m.userData.marker = true;
  return m;
}

/** Frees the geometries, materials and textures of `objects` and of their descendants (each once). */
function disposeObjects(objects: readonly Object3D[]): void {
  const geometries = new Set<BufferGeometry>();
  const materials = new Set<Material>();
  for (const root of objects)
    root.traverse((o) => {
      const drawable = o as Partial<Mesh>;
      if (drawable.geometry) geometries.add(drawable.geometry);
      const m = drawable.material;
      if (Array.isArray(m)) for (const x of m) materials.add(x);
      else if (m) materials.add(m);
    });
  for (const g of geometries) g.dispose();
  for (const m of materials) {
    (m as Material & { map?: { dispose(): void } | null }).map?.dispose();
    m.dispose();
  }
}

/** A part of the scene that frees what it made with it: {@link disposeObjects} of its objects. */
export abstract class Disposer {
  abstract readonly objects: readonly Object3D[];

  dispose(): void {
    disposeObjects(this.objects);
  }
}
