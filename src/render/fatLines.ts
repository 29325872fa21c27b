/**
 * Lines of a given width in CSS pixels (WebGL draws `gl.LINES` 1 px wide whatever is asked): each
 * segment a screen-space quad, two triangles whose four corners are pushed across the segment's
 * direction on screen by half the width in the vertex shader. A {@link FatLine} holds its points
 * (flat xyz, written in place by its owner) and, on {@link FatLine.finish}, writes its quads' corners:
 * the same buffers each time, up to the capacity it was made with (no allocation per update).
 *
 * The quads' vertices are the line's points themselves (each corner carries its own end and the
 * other one), so what reads a mesh's vertices, as the camera's fit does (framePoints.ts), reads the
 * line's points. The width's screen size is one uniform shared by every line of a view, set before
 * each frame ({@link setLineScreen}).
 */
import {
  BufferAttribute,
  BufferGeometry,
  Color,
  Mesh,
  type Object3D,
  ShaderMaterial,
  type Uniform,
  Vector3,
} from 'three';
import { drawHeightsInPlace, type HeightMap } from './heightExaggeration';

/** The drawing buffer's width and height (device px) and the device pixel ratio: shared by every line. */
const SCREEN: Uniform<Vector3> = { value: new Vector3(1, 1, 1) } as Uniform<Vector3>;
/** The colour of the lines' halos: the view's background (shared by every line). */
const HALO_COLOUR: Uniform<Color> = { value: new Color(1, 1, 1) } as Uniform<Color>;

/**
 * Sets the screen every line is drawn for (before each frame: the drawing buffer's size in device
 * px) and the background their halos take (`background` is copied).
 */
export function setLineScreen(
  bufferWidthPx: number,
  bufferHeightPx: number,
  pixelRatio: number,
  background: Color,
): void {
  SCREEN.value.set(Math.max(1, bufferWidthPx), Math.max(1, bufferHeightPx), pixelRatio);
  HALO_COLOUR.value.copy(background);
}

/** The halo each side of a line drawn over everything (CSS px). */
export const HALO_PX = 1.5;

const VERTEX = `
attribute vec3 other;
attribute float side;
uniform vec3 screen;
uniform float widthPx;
void main() {
  vec4 a = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
  vec4 b = projectionMatrix * modelViewMatrix * vec4(other, 1.0);
  vec2 d = (b.xy / b.w - a.xy / a.w) * screen.xy;
  float len = length(d);
  vec2 n = len > 1e-6 ? vec2(-d.y, d.x) / len : vec2(0.0);
  a.xy += n * side * widthPx * screen.z / screen.xy * a.w;
  gl_Position = a;
}`;

const FRAGMENT = `
uniform vec3 color;
uniform float alpha;
void main() {
  gl_FragColor = vec4(color, alpha);
  #include <colorspace_fragment>
}`;

/**
 * A line's material: its `color` (themed as any material's, view3d.ts) and width in CSS px, or
 * (`'halo'`) the background's colour, {@link HALO_PX} wider each side: drawn under a line that is
 * drawn over everything, so that it reads over anything.
 */
export class FatLineMaterial extends ShaderMaterial {
  /** The colour drawn (the shader's uniform itself: the theme recolours it in place). */
  readonly color: Color;

  constructor(color: number | 'halo', widthPx: number, options: { overlay?: boolean; opacity?: number } = {}) {
    const opacity = options.opacity ?? 1;
    const colour = color === 'halo' ? HALO_COLOUR : { value: new Color(color) };
    super({
      uniforms: {
        color: colour,
        alpha: { value: opacity },
        widthPx: { value: color === 'halo' ? widthPx + 2 * HALO_PX : widthPx },
        screen: SCREEN,
      },
      vertexShader: VERTEX,
      fragmentShader: FRAGMENT,
      // Over everything: drawn with the translucent surfaces' pass, after them (its render order), not under them.
      transparent: opacity < 1 || options.overlay === true,
      depthTest: !options.overlay,
      depthWrite: false,
    });
    this.color = colour.value;
  }

  /** The line's width (CSS px; a halo's includes its halo). */
  get widthPx(): number {
    return (this.uniforms.widthPx as Uniform<number>).value;
  }
}

/** Corners per segment (two triangles, not indexed: the draw range counts the segments' vertices). */
const CORNERS = 6;
/** Each corner: which end it sits at (0 the segment's start, 1 its end) and its side of the line. */
const CORNER_END = [0, 0, 1, 0, 1, 1] as const;
const CORNER_SIDE = [1, -1, -1, 1, -1, 1] as const;

/** How a {@link FatLine}'s points join: a polyline, a closed loop, or separate pairs. */
export type FatLineKind = 'strip' | 'loop' | 'pairs';

/** A line of up to `capacity` points, drawn `widthPx` wide; empty until its points are written and finished. */
export class FatLine extends Mesh<BufferGeometry, FatLineMaterial> {
  /** Its points (flat xyz), written in place by its owner, then {@link finish}ed. */
  readonly points: Float32Array;
  /** How many of its points are drawn (the last {@link finish}). */
  drawnPoints = 0;
  private readonly kind: FatLineKind;

  constructor(capacity: number, material: FatLineMaterial, kind: FatLineKind = 'strip') {
    const segments = kind === 'pairs' ? Math.floor(capacity / 2) : capacity;
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new BufferAttribute(new Float32Array(segments * CORNERS * 3), 3));
    geometry.setAttribute('other', new BufferAttribute(new Float32Array(segments * CORNERS * 3), 3));
    const side = new Float32Array(segments * CORNERS);
    for (let i = 0; i < side.length; i++) {
      const k = i % CORNERS;
      // A corner at the segment's end sees the direction reversed: its side is flipped to stay on the same side.
      const own = CORNER_SIDE[k] as number;
      side[i] = CORNER_END[k] === 0 ? own : -own;
    }
    geometry.setAttribute('side', new BufferAttribute(side, 1));
    geometry.setDrawRange(0, 0);
    super(geometry, material);
    this.points = new Float32Array(capacity * 3);
    this.kind = kind;
    this.frustumCulled = false;
  }

  /**
   * Draws the first `count` points written (as many as it holds), heights first drawn through
   * `map` (in place). Pairs: every two points one segment.
   */
  finish(count: number, map?: HeightMap): void {
    const n = Math.min(count, this.points.length / 3);
    this.drawnPoints = n;
    if (map !== undefined) drawHeightsInPlace(map, this.points, n);
    const position = this.geometry.getAttribute('position') as BufferAttribute;
    const other = this.geometry.getAttribute('other') as BufferAttribute;
    const pos = position.array as Float32Array;
    const oth = other.array as Float32Array;
    const p = this.points;
    const pairs = this.kind === 'pairs';
    const segments = pairs ? Math.floor(n / 2) : this.kind === 'loop' ? (n > 2 ? n : Math.max(0, n - 1)) : n - 1;
    const total = Math.max(0, Math.min(segments, pos.length / (3 * CORNERS)));
    for (let s = 0; s < total; s++) {
      const a = pairs ? 2 * s : s;
      const b = pairs ? 2 * s + 1 : (s + 1) % n;
      for (let k = 0; k < CORNERS; k++) {
        const here = CORNER_END[k] === 0 ? a : b;
        const there = CORNER_END[k] === 0 ? b : a;
        const o = 3 * (s * CORNERS + k);
        for (let c = 0; c < 3; c++) {
          pos[o + c] = p[3 * here + c] as number;
          oth[o + c] = p[3 * there + c] as number;
        }
      }
    }
    position.needsUpdate = true;
    other.needsUpdate = true;
    this.geometry.setDrawRange(0, total * CORNERS);
  }

  /** Draws segments between the points of `source` (flat xyz) named by the index pairs `pairs` (for outlines over a mesh). */
  finishPairs(source: ArrayLike<number>, pairs: ArrayLike<number>): void {
    const p = this.points;
    const n = Math.min(pairs.length, p.length / 3);
    for (let i = 0; i < n; i++) {
      const v = pairs[i] as number;
      p[3 * i] = source[3 * v] as number;
      p[3 * i + 1] = source[3 * v + 1] as number;
      p[3 * i + 2] = source[3 * v + 2] as number;
    }
    this.finish(n);
  }
}

/** Whether an object is a {@link FatLine}. */
export function isFatLine(o: Object3D): o is FatLine {
  return o instanceof FatLine;
}
