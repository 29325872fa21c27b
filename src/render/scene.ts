/**
 * three.js scene of the tool in its posture, its neighbouring passes, the cusp sections and the
 * h pseudo plane; on a cylinder, the cylinder's patch, the h pseudo surface (the cylinder offset by h,
 * radially), the neighbouring passes turned about its axis (axis along the feed) or stepped along
 * it (across), and the cusps. Frame: the contact of this pass at the origin, X feed, Y cross-feed,
 * Z up (mm). The surface's geometry comes from the core (surfaceGeometry.ts), as plain arrays.
 *
 * Its contract:
 *  - objects are built once and updated in place; nothing is rebuilt per update, so nothing
 *    leaks (the axes are scaled, HTML labels are created once and only shown or hidden);
 *  - a frame is rendered only when something changed (camera move, new geometry, resize,
 *    a restored WebGL context), never in a busy loop;
 *  - the camera is fitted on the first geometry and refitted, keeping the viewing direction,
 *    whenever the tool radius changes;
 *  - the camera's near and far planes enclose what is drawn, from the camera's place, before each
 *    frame (clipPlanes.ts): the tool is seen at every radius from 0.001 to 1000 mm and however the
 *    user turns or zooms;
 *  - after `webglcontextlost` it waits; on `webglcontextrestored` (three.js rebuilds its GL
 *    state, its clear colour reset to black) it sets the theme's colours again and draws the
 *    last state without any input;
 *  - `dispose()` disconnects the resize observer and the canvas listeners and frees every
 *    GPU resource and DOM node it made.
 */
import {
  AmbientLight,
  BufferAttribute,
  BufferGeometry,
  Color,
  DirectionalLight,
  DoubleSide,
  Group,
  Line,
  LineBasicMaterial,
  LineLoop,
  type Material,
  Mesh,
  MeshBasicMaterial,
  MeshStandardMaterial,
  Object3D,
  PerspectiveCamera,
  PlaneGeometry,
  Points,
  PointsMaterial,
  Scene,
  Sphere,
  SphereGeometry,
  Vector3,
  WebGLRenderer,
} from 'three';
import type { Surface } from '../core/cylinder';
import {
  axisFoot,
  passMatrix,
  patchIndices,
  surfacePatch,
  surfacePoint,
  surfacePolyline,
} from '../core/surfaceGeometry';
import { toolMeshIndices } from '../core/toolMesh';
import type { Vec3 } from '../core/vec';
import {
  type CuspGeometry,
  LOOP_MAX_POINTS,
  type SceneGeometry,
  TOOL_RADIAL_SEGMENTS,
  type TraceFrame,
} from '../worker/protocol';
import { drawnBoundingSphere, fitClipPlanes } from './clipPlanes';
import {
  drawnHeightMm,
  drawnPoints,
  type HeightMap,
  heightMapFor,
  sceneHeightExaggeration,
} from './heightExaggeration';
import { type LabelRequest, type PixelRect, placeLabels } from './labelLayout';
import { OrbitController } from './orbit';

export type CameraPreset = 'iso' | 'feed' | 'top';

/** Texts of the scene's labels, in the user's unit (the scene knows no units). */
export interface SceneLabels {
  /** The step-over dimension, e.g. `L = 2.8872 mm`. */
  readonly interval: string;
  /** Its half, e.g. `L/2 = 1.4436 mm`. */
  readonly halfInterval: string;
  /** The contact offset dimension, e.g. `y0 = 0.1234 mm`, or null to hide it (no offset). */
  readonly contactOffset: string | null;
}

const SECTION_POINTS = 96;
/** The cylinder patches' grid: segments along the feed and across it. */
const PATCH_FEED = 48;
const PATCH_CROSS = 64;
/** Segments of the CC paths and of the step-over's dimension (arcs on a cylinder). */
const PATH_SEGMENTS = 48;
const CANDIDATE_CAPACITY = 64;
const BACKGROUND = 0xf7f8fa;
const COLOURS = {
  section: 0xff7a00,
  loop: 0xd6336c,
  axis: 0x444444,
  dimension: 0x111111,
  contact: 0x1b7f3b,
  centre: 0x374151,
  pHp: 0xd6336c,
  trace: 0x7c3aed,
  path: 0x1b7f3b,
  tool: 0xb8c7d9,
  ghost: 0x6c7a89,
  plane: 0xc9ced6,
  hPlane: 0x2f80ed,
  ridge: 0xb4235a,
} as const;

/**
 * The stylesheet's custom property for each colour of the scene (theme.ts switches them with the
 * page's light or dark theme); the constants above are the light values and the fallback.
 */
const THEMED_COLOURS: ReadonlyMap<number, string> = new Map([
  [COLOURS.section, '--scene-section'],
  [COLOURS.loop, '--scene-loop'],
  [COLOURS.axis, '--scene-axis'],
  [COLOURS.dimension, '--scene-dimension'],
  [COLOURS.contact, '--scene-contact'],
  [COLOURS.centre, '--scene-centre'],
  [COLOURS.trace, '--scene-trace'],
  [COLOURS.tool, '--scene-tool'],
  [COLOURS.ghost, '--scene-ghost'],
  [COLOURS.plane, '--scene-plane'],
  [COLOURS.hPlane, '--scene-hplane'],
  [COLOURS.ridge, '--scene-ridge'],
  [0xd62828, '--scene-x'],
  [0x2a9d8f, '--scene-y'],
  [0x1d4ed8, '--scene-z'],
]);

/**
 * Recolours a three.js scene from the stylesheet: the background from `--scene-bg` and each
 * material whose light colour is in `themed` from its custom property (read on `element`).
 * The light colour is kept in the material's userData, so it can be applied again and again.
 */
export function applySceneTheme(
  scene: Scene,
  renderer: WebGLRenderer,
  element: Element,
  background: number,
  themed: ReadonlyMap<number, string> = THEMED_COLOURS,
): void {
  const css = getComputedStyle(element);
  const read = (name: string, fallback: number): Color => {
    const text = css.getPropertyValue(name).trim();
    return new Color(text === '' ? fallback : text);
  };
  renderer.setClearColor(read('--scene-bg', background));
  scene.traverse((object) => {
    const own = (object as Partial<Mesh>).material;
    for (const material of own === undefined ? [] : Array.isArray(own) ? own : [own]) {
      const coloured = material as Material & { color?: Color };
      if (!coloured.color) continue;
      if (typeof coloured.userData.lightColour !== 'number') coloured.userData.lightColour = coloured.color.getHex();
      const light = coloured.userData.lightColour as number;
      const name = themed.get(light);
      if (name) coloured.color.copy(read(name, light));
    }
  });
}

/** The WebGL renderer's name says it rasterises in software (checked on a throwaway context). */
function isSoftwareWebGL(): boolean {
  const gl = document.createElement('canvas').getContext('webgl2');
  if (!gl) return false;
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  const name = String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
  gl.getExtension('WEBGL_lose_context')?.loseContext();
  return /swiftshader|llvmpipe|softpipe|software|basic render/i.test(name);
}

/** Two unit vectors perpendicular to the unit vector `d` and to each other. */
function perpendiculars(d: Vector3): [Vector3, Vector3] {
  const u = new Vector3(Math.abs(d.x) < 0.9 ? 1 : 0, Math.abs(d.x) < 0.9 ? 0 : 1, 0).cross(d).normalize();
  return [u, d.clone().cross(u).normalize()];
}

function lineOf(capacity: number, color: number, loop = false): Line {
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(new Float32Array(capacity * 3), 3));
  geometry.setDrawRange(0, 0);
  const material = new LineBasicMaterial({ color, depthTest: false });
  const line = loop ? new LineLoop(geometry, material) : new Line(geometry, material);
  line.renderOrder = 10;
  line.frustumCulled = false;
  return line;
}

/** Sets a cylinder patch's points (the grid and its indices stay). */
function setPatch(mesh: Mesh, points: Float64Array): void {
  const attr = mesh.geometry.getAttribute('position') as BufferAttribute;
  (attr.array as Float32Array).set(points);
  attr.needsUpdate = true;
}

function setLine(line: Line, points: ArrayLike<number>, count: number): void {
  const attr = line.geometry.getAttribute('position') as BufferAttribute;
  const arr = attr.array as Float32Array;
  const n = Math.min(count, arr.length / 3);
  for (let i = 0; i < n * 3; i++) arr[i] = points[i] as number;
  attr.needsUpdate = true;
  line.geometry.setDrawRange(0, n);
}

/** Points of a circle (flat xyz) around `centre` in the plane with unit normal `normal`. */
function circlePoints(centre: Vec3, normal: Vec3, radius: number): Float32Array {
  const n = new Vector3(normal[0], normal[1], normal[2]);
  const u = new Vector3(0, 0, 1).cross(n);
  if (u.lengthSq() < 1e-12) u.set(1, 0, 0);
  u.normalize();
  const v = new Vector3().crossVectors(n, u).normalize();
  const pts = new Float32Array(SECTION_POINTS * 3);
  for (let i = 0; i < SECTION_POINTS; i++) {
    const a = (2 * Math.PI * i) / SECTION_POINTS;
    const c = Math.cos(a) * radius;
    const s = Math.sin(a) * radius;
    pts[3 * i] = centre[0] + c * u.x + s * v.x;
    pts[3 * i + 1] = centre[1] + c * u.y + s * v.y;
    pts[3 * i + 2] = centre[2] + c * u.z + s * v.z;
  }
  return pts;
}

/**
 * A label anchored at a 3D point: an object of the scene that carries an HTML element. After each
 * frame the scene centres the outer element on the point's projection (its inline transform is set
 * through the CSSOM) and labelLayout.ts offsets the inner one, which carries the class. (What
 * three.js's CSS2DRenderer did, in the lines this scene needs: 1.2 kB gzip less.)
 */
class LabelAnchor extends Object3D {
  constructor(readonly element: HTMLElement) {
    super();
  }
}

function label(text: string, className: string, side: readonly [number, number], priority: number): LabelAnchor {
  const anchor = document.createElement('div');
  anchor.className = 'scene-label-anchor';
  const inner = document.createElement('span');
  inner.className = `scene-label ${className}`;
  inner.textContent = text;
  anchor.append(inner);
  const object = new LabelAnchor(anchor);
  const spec: LabelSpec = { side, priority };
  object.userData.label = spec;
  return object;
}

/** How a label would like to be placed (see labelLayout.ts). */
interface LabelSpec {
  readonly side: readonly [number, number];
  readonly priority: number;
}

/** Whether an object and all its ancestors are visible. */
function shown(object: Object3D): boolean {
  for (let o: Object3D | null = object; o !== null; o = o.parent) if (!o.visible) return false;
  return true;
}

/** Marks an object with the key of its legend entry (index.html, `data-legend`). */
function legend<T extends Object3D>(object: T, key: string): T {
  object.userData.legend = key;
  return object;
}

/** Sets a label's text (the inner element's). */
function setLabel(object: LabelAnchor, text: string): void {
  const inner = object.element.firstElementChild;
  if (inner && inner.textContent !== text) inner.textContent = text;
}

/** One cusp's drawing: its section circle, its P_hp and the torus / plane curves at its height. */
class CuspMarks {
  readonly section = lineOf(SECTION_POINTS, COLOURS.section, true);
  readonly loops = [lineOf(LOOP_MAX_POINTS, COLOURS.loop, true), lineOf(LOOP_MAX_POINTS, COLOURS.loop, true)];
  readonly point: Mesh;

  /** The cusp along the feed (the scallop's ridge), at its height. */
  readonly ridge = legend(lineOf(2, COLOURS.ridge), 'ridge');

  constructor(dot: SphereGeometry, text: string, className: string, side: readonly [number, number]) {
    this.point = legend(new Mesh(dot, new MeshBasicMaterial({ color: COLOURS.pHp, depthTest: false })), 'php');
    this.point.renderOrder = 11;
    this.point.userData.marker = true;
    this.point.add(label(text, className, side, 8));
    legend(this.section, 'section');
    for (const l of this.loops) legend(l, 'loop');
  }

  objects(): Object3D[] {
    return [this.section, ...this.loops, this.point, this.ridge];
  }

  /** Shows a cusp (or hides it: null), heights drawn through `map`; the ridge runs from x = xFrom to xTo. */
  show(c: CuspGeometry | null, dotRadius: number, map: HeightMap, xFrom: number, xTo: number): void {
    this.section.visible = this.point.visible = this.ridge.visible = c !== null;
    this.loops.forEach((line, i) => {
      const loop = c?.loops[i];
      line.visible = loop !== undefined && loop.length > 0;
      setLine(line, loop ? drawnPoints(map, loop) : [], loop ? loop.length / 3 : 0);
    });
    if (c === null) return;
    setLine(
      this.section,
      drawnPoints(map, circlePoints(c.sectionCentre, c.sectionNormal, c.sectionRadiusMm)),
      SECTION_POINTS,
    );
    this.point.scale.setScalar(dotRadius);
    const z = drawnHeightMm(map, c.pHp[2]);
    this.point.position.set(c.pHp[0], c.pHp[1], z);
    setLine(this.ridge, [xFrom, c.pHp[1], z, xTo, c.pHp[1], z], 2);
  }
}

export class ToolScene {
  private readonly renderer: WebGLRenderer;
  /** The layer of the labels' elements, over the canvas. */
  private readonly labels = document.createElement('div');
  private readonly scene = new Scene();
  /** Its near and far planes are set before each frame from the drawing's size (clipPlanes.ts). */
  private readonly camera = new PerspectiveCamera(40, 1, 0.01, 1000);
  private readonly controls: OrbitController;
  private readonly toolGeometry = new BufferGeometry();
  private readonly tool: Mesh;
  /** The neighbouring passes, at -L and +L (mirrored for zigzag). */
  private readonly neighbours: Mesh[];
  private readonly designedPlane: Mesh;
  private readonly hPlane: Mesh;
  /** On a cylinder: its patch and the h pseudo surface (updated in place; hidden on a plane). */
  private readonly designedCylinder: Mesh;
  private readonly hCylinder: Mesh;
  /** On a cylinder: the cusp points on the h pseudo surface. */
  private readonly cuspPoints: Mesh[];
  private readonly right: CuspMarks;
  private readonly left: CuspMarks;
  private readonly toolAxis = lineOf(2, COLOURS.axis);
  /** Cutter-contact paths of the three passes (lines along the feed on the surface; arcs around a cylinder across the feed). */
  private readonly paths = [
    lineOf(PATH_SEGMENTS + 1, COLOURS.path),
    lineOf(PATH_SEGMENTS + 1, COLOURS.path),
    lineOf(PATH_SEGMENTS + 1, COLOURS.path),
  ];
  /** The step-over L between two CC paths, and L/2 from this pass's path, with arrowheads. */
  private readonly dimension = legend(lineOf(PATH_SEGMENTS + 12, COLOURS.dimension), 'dimension');
  private readonly halfDimension = legend(lineOf(PATH_SEGMENTS + 12, COLOURS.dimension), 'dimension');
  private readonly offsetDimension = legend(lineOf(4, COLOURS.dimension), 'offset');
  private readonly contact: Mesh;
  private readonly centre: Mesh;
  private readonly axisFoot: Mesh;
  private readonly dimLabel = label('L', 'label-dim', [0, -1], 6);
  private readonly halfDimLabel = label('L/2', 'label-dim label-half', [0, -1], 6);
  private readonly offsetLabel = label('y0', 'label-offset', [0, 1], 5);
  /** The height exaggeration, said on the scene (a badge in its bottom left corner). */
  private readonly scaleBadge: HTMLElement;
  private heightMap: HeightMap = { factor: 1, bandMm: 0 };
  private readonly axes = new Group();
  private readonly traceSection = lineOf(SECTION_POINTS, COLOURS.trace, true);
  private readonly candidates: Points;
  private readonly traceMarker: Mesh;
  private readonly traceLabel = label('', 'label-trace', [-1, -1], 10);
  private readonly resizeObserver: ResizeObserver;
  /**
   * Sizes of the labels and badges, as the browser last laid them out: read when it reports a
   * change (after its layout, where reading costs nothing), never forced in the middle of a frame.
   * A change redraws, so a label whose text grew is placed again in the next frame.
   */
  private readonly sizeObserver = new ResizeObserver((entries) => this.sizesChanged(entries));
  private readonly sizes = new WeakMap<Element, { readonly widthPx: number; readonly heightPx: number }>();
  /** The badges' boxes in the scene (px), while shown. */
  private readonly badgeRects = new Map<Element, PixelRect>();
  /** The scene's size (px), as last laid out. */
  private widthPx = 1;
  private heightPx = 1;
  private readonly onContextLost = () => {
    this.contextLost = true;
  };
  private readonly onContextRestored = () => {
    this.contextLost = false;
    // three.js's own listener (added with the renderer, so it ran before this one) has rebuilt its
    // GL state, the clear colour with it (black): the theme's again, and a frame of the last state.
    this.applyTheme();
  };
  private contextLost = false;
  private frameRequested = false;
  private cornerRadiusMm = 1;
  /** A sphere around what the last state draws (world, mm): the camera's near and far planes enclose it. */
  private drawnSphere = new Sphere().makeEmpty();
  /** Tool radius the camera was fitted to (0: not yet). */
  private fittedRadiusMm = 0;
  /** Frames rendered so far. */
  frames = 0;
  /** Called after each rendered frame. */
  onFrame: (() => void) | null = null;

  /** Whether WebGL runs on a software rasteriser (SwiftShader, llvmpipe): then no MSAA, pixel ratio 1. */
  readonly softwareRendering: boolean;

  constructor(private readonly container: HTMLElement) {
    // Multisampling and a high pixel ratio cost little on a GPU, but on a software rasteriser
    // they tripled the input-to-frame time (measured: about 50 ms against 6 ms on SwiftShader).
    this.softwareRendering = isSoftwareWebGL();
    this.renderer = new WebGLRenderer({ antialias: !this.softwareRendering });
    this.renderer.setPixelRatio(this.softwareRendering ? 1 : Math.min(2, window.devicePixelRatio || 1));
    this.renderer.setClearColor(new Color(BACKGROUND));
    const canvas = this.renderer.domElement;
    canvas.setAttribute('data-testid', 'scene-canvas');
    canvas.setAttribute(
      'aria-label',
      '3D view of the tool in its posture, its neighbouring passes and the cusp sections',
    );
    canvas.setAttribute('role', 'img');
    canvas.addEventListener('webglcontextlost', this.onContextLost);
    canvas.addEventListener('webglcontextrestored', this.onContextRestored);
    container.appendChild(canvas);
    this.labels.className = 'scene-labels';
    container.appendChild(this.labels);

    this.camera.up.set(0, 0, 1);
    this.controls = new OrbitController(this.camera, canvas);
    // A vertical swipe over the scene scrolls the page; a horizontal
    // drag turns the view and two fingers zoom: the deliberate gestures.
    canvas.style.touchAction = 'pan-y';
    this.controls.onChange = () => this.requestRender();

    this.scene.add(new AmbientLight(0xffffff, 1.2));
    const sun = new DirectionalLight(0xffffff, 1.6);
    sun.position.set(3, -4, 6);
    this.scene.add(sun);

    this.toolGeometry.setAttribute('position', new BufferAttribute(new Float32Array(0), 3));
    this.toolGeometry.setIndex(new BufferAttribute(toolMeshIndices(TOOL_RADIAL_SEGMENTS), 1));
    this.tool = new Mesh(
      this.toolGeometry,
      new MeshStandardMaterial({
        color: COLOURS.tool,
        metalness: 0.3,
        roughness: 0.45,
        transparent: true,
        opacity: 0.22,
        side: DoubleSide,
        depthWrite: false,
      }),
    );
    const ghost = new MeshBasicMaterial({ color: COLOURS.ghost, wireframe: true, transparent: true, opacity: 0.12 });
    this.neighbours = [new Mesh(this.toolGeometry, ghost), new Mesh(this.toolGeometry, ghost)];
    // Their placement is a rigid motion from the core (passMatrix), set as the matrix itself.
    for (const m of this.neighbours) m.matrixAutoUpdate = false;
    const planeGeometry = new PlaneGeometry(1, 1);
    this.designedPlane = new Mesh(
      planeGeometry,
      new MeshBasicMaterial({
        color: COLOURS.plane,
        side: DoubleSide,
        transparent: true,
        opacity: 0.55,
        depthWrite: false,
      }),
    );
    this.hPlane = new Mesh(
      planeGeometry,
      new MeshBasicMaterial({
        color: COLOURS.hPlane,
        side: DoubleSide,
        transparent: true,
        opacity: 0.18,
        depthWrite: false,
      }),
    );
    const patch = () => {
      const g = new BufferGeometry();
      g.setAttribute('position', new BufferAttribute(new Float32Array((PATCH_FEED + 1) * (PATCH_CROSS + 1) * 3), 3));
      g.setIndex(new BufferAttribute(patchIndices(PATCH_FEED, PATCH_CROSS), 1));
      return g;
    };
    this.designedCylinder = new Mesh(patch(), this.designedPlane.material);
    this.hCylinder = new Mesh(patch(), this.hPlane.material);
    for (const m of [this.designedCylinder, this.hCylinder]) {
      m.frustumCulled = false;
      m.visible = false;
    }
    const dot = new SphereGeometry(1, 16, 12);
    const marker = (
      color: number,
      key: string,
      text: string | null,
      className: string,
      side: readonly [number, number],
      priority: number,
    ) => {
      const m = legend(new Mesh(dot, new MeshBasicMaterial({ color, depthTest: false })), key);
      m.renderOrder = 11;
      m.userData.marker = true;
      if (text !== null) m.add(label(text, className, side, priority));
      return m;
    };
    this.contact = marker(COLOURS.contact, 'contact', 'CC (P_base)', 'label-pbase', [0, 1], 9);
    this.centre = marker(COLOURS.centre, 'centre', 'O', 'label-centre', [1, -0.6], 7);
    this.axisFoot = marker(COLOURS.axis, 'axis', null, '', [0, 0], 0);
    this.right = new CuspMarks(dot, 'P_hp R', 'label-php', [1, -0.8]);
    this.left = new CuspMarks(dot, 'P_hp L', 'label-php label-php-left', [-1, -0.8]);
    this.cuspPoints = [
      marker(COLOURS.pHp, 'cusp', 'cusp R', 'label-php', [1, -0.8], 8),
      marker(COLOURS.pHp, 'cusp', 'cusp L', 'label-php label-php-left', [-1, -0.8], 8),
    ];
    for (const m of this.cuspPoints) m.visible = false;
    this.dimension.add(this.dimLabel);
    this.halfDimension.add(this.halfDimLabel);
    this.offsetDimension.add(this.offsetLabel);
    legend(this.tool, 'tool');
    for (const m of this.neighbours) legend(m, 'tool');
    for (const l of this.paths) legend(l, 'path');
    legend(this.toolAxis, 'axis');
    legend(this.designedPlane, 'design');
    legend(this.designedCylinder, 'design');
    legend(this.hPlane, 'hplane');
    legend(this.hCylinder, 'hplane');
    legend(this.axes, 'axes');
    legend(this.traceSection, 'trace');
    this.scaleBadge = document.createElement('div');
    this.scaleBadge.className = 'scene-scale';
    this.scaleBadge.setAttribute('data-testid', 'scene-exaggeration');
    this.scaleBadge.hidden = true;
    container.appendChild(this.scaleBadge);
    this.buildAxes();
    this.scene.add(
      this.designedPlane,
      this.hPlane,
      this.designedCylinder,
      this.hCylinder,
      ...this.cuspPoints,
      this.tool,
      ...this.neighbours,
      ...this.right.objects(),
      ...this.left.objects(),
      ...this.paths,
      this.toolAxis,
      this.dimension,
      this.halfDimension,
      this.offsetDimension,
      this.contact,
      this.centre,
      this.axisFoot,
      this.axes,
    );
    this.traceMarker = marker(COLOURS.trace, 'trace', null, '', [0, 0], 0);
    this.traceMarker.renderOrder = 12;
    this.traceMarker.add(this.traceLabel);
    const candidateGeometry = new BufferGeometry();
    candidateGeometry.setAttribute('position', new BufferAttribute(new Float32Array(CANDIDATE_CAPACITY * 3), 3));
    candidateGeometry.setDrawRange(0, 0);
    this.candidates = new Points(
      candidateGeometry,
      new PointsMaterial({ color: COLOURS.trace, size: 6, sizeAttenuation: false, depthTest: false }),
    );
    this.candidates.frustumCulled = false;
    legend(this.candidates, 'trace');
    this.candidates.renderOrder = 12;
    this.scene.add(this.traceSection, this.candidates, this.traceMarker);
    this.traceSection.visible = this.candidates.visible = this.traceMarker.visible = false;

    this.resizeObserver = new ResizeObserver(() => this.resize());
    this.resizeObserver.observe(container);
    for (const badge of container.querySelectorAll<HTMLElement>('.stale-badge, .scene-scale'))
      this.sizeObserver.observe(badge);
    this.resize();
  }

  /** Unit arrows, built once; the group is scaled with the tool. */
  private buildAxes(): void {
    const specs: Array<[Vector3, number, string]> = [
      [new Vector3(1, 0, 0), 0xd62828, 'X (feed)'],
      [new Vector3(0, 1, 0), 0x2a9d8f, 'Y'],
      [new Vector3(0, 0, 1), 0x1d4ed8, 'Z'],
    ];
    for (const [dir, color, text] of specs) {
      // A shaft and a head of two crossed strokes, 0.12 long (drawn lines: no cone geometry).
      const [u, v] = perpendiculars(dir);
      const arrow = new Group();
      const at = (k: number, w: Vector3 | null, s: number) => {
        const p = dir.clone().multiplyScalar(k);
        return w === null ? p : p.addScaledVector(w, s);
      };
      const strokes = [
        [at(0, null, 0), at(1, null, 0)],
        [at(0.88, u, 0.045), at(1, null, 0), at(0.88, u, -0.045)],
        [at(0.88, v, 0.045), at(1, null, 0), at(0.88, v, -0.045)],
      ];
      const material = new LineBasicMaterial({ color });
      for (const points of strokes) arrow.add(new Line(new BufferGeometry().setFromPoints(points), material));
      const tag = label(text, 'label-axis', [0, 0], 2);
      tag.position.copy(dir).multiplyScalar(1.08);
      arrow.add(tag);
      this.axes.add(arrow);
    }
  }

  /** Shows a solved state. Everything is updated in place. */
  update(g: SceneGeometry, labels: SceneLabels): void {
    // Heights exaggerated near a plane when the scallop would be too low to see (the drawing only).
    const map = heightMapFor(
      g.surface.kind === 'plane' ? sceneHeightExaggeration(g.toolRadiusMm, g.scallopHeightMm) : 1,
      g.scallopHeightMm,
    );
    this.heightMap = map;
    const dz = (z: number) => drawnHeightMm(map, z);
    const toolPositions = drawnPoints(map, g.toolPositions);
    const attr = this.toolGeometry.getAttribute('position') as BufferAttribute;
    if (attr.array.length !== toolPositions.length) {
      this.toolGeometry.setAttribute('position', new BufferAttribute(toolPositions, 3));
    } else {
      (attr.array as Float32Array).set(toolPositions);
      attr.needsUpdate = true;
    }
    this.toolGeometry.computeVertexNormals();
    this.toolGeometry.computeBoundingSphere();
    const L = g.intervalMm;
    const surface: Surface = g.surface;
    const cylinder = surface.kind === 'cylinder';
    // The neighbours: carried along the surface by L (turned about a cylinder's axis along the feed).
    this.neighbours.forEach((m, i) => {
      m.matrix.fromArray(passMatrix(surface, i === 0 ? -L : L, g.pattern === 'zigzag'));
      m.matrixWorldNeedsUpdate = true;
    });

    const R = g.toolRadiusMm;
    this.cornerRadiusMm = g.cornerRadiusMm;
    const sizeX = 2.8 * R;
    const sizeY = 2 * L + 2.4 * R;
    this.designedPlane.visible = this.hPlane.visible = !cylinder;
    this.designedCylinder.visible = this.hCylinder.visible = cylinder;
    if (cylinder) {
      setPatch(this.designedCylinder, surfacePatch(surface, 0, sizeX / 2, sizeY / 2, PATCH_FEED, PATCH_CROSS));
      setPatch(this.hCylinder, surfacePatch(surface, g.scallopHeightMm, sizeX / 2, sizeY / 2, PATCH_FEED, PATCH_CROSS));
    } else {
      this.designedPlane.scale.set(sizeX, sizeY, 1);
      this.designedPlane.position.set(0, 0, 0);
      this.hPlane.scale.set(sizeX, sizeY, 1);
      this.hPlane.position.set(0, 0, dz(g.scallopHeightMm));
    }
    this.scaleBadge.hidden = false;
    this.scaleBadge.textContent =
      map.factor === 1 ? 'heights at true scale' : `heights drawn x${map.factor} (up to 2h above the plane)`;
    this.scaleBadge.title =
      map.factor === 1
        ? 'Every length and height is drawn at true scale.'
        : `So that the scallop can be seen, heights from the plane up to twice the scallop height are drawn ${map.factor} times taller, the tool above them at true scale. Only the drawing: every number is the solver's.`;

    const dotR = 0.035 * R;
    const xFrom = -1.3 * R;
    const xTo = 1.3 * R;
    this.right.show(g.right, dotR, map, xFrom, xTo);
    this.left.show(g.left, dotR, map, xFrom, xTo);
    this.cuspPoints.forEach((m, i) => {
      const p = g.cuspPoints === null ? null : i === 0 ? g.cuspPoints.right : g.cuspPoints.left;
      m.visible = p !== null;
      if (p === null) return;
      m.position.set(...p);
      m.scale.setScalar(dotR);
    });

    // Tool axis from where it meets the surface (its foot) up the shank; the contact lies off it.
    const [ox, oy, oz] = g.toolCentre;
    const [ax, ay, az] = g.toolAxis;
    const foot = axisFoot(surface, g.toolCentre, g.toolAxis);
    const up = 2.2 * R;
    setLine(this.toolAxis, drawnPoints(map, [...foot, ox + up * ax, oy + up * ay, oz + up * az]), 2);
    this.axisFoot.scale.setScalar(0.6 * dotR);
    this.axisFoot.position.set(foot[0], foot[1], dz(foot[2]));
    this.centre.scale.setScalar(0.8 * dotR);
    this.centre.position.set(ox, oy, dz(oz));
    this.contact.scale.setScalar(dotR);
    this.contact.position.set(0, 0, 0);

    // The cutter-contact paths of the three passes, and the step-over L between two of them (along
    // the surface: an arc around a cylinder with the axis along the feed).
    this.paths.forEach((line, i) => {
      const y = (i - 1) * L;
      setLine(line, surfacePolyline(surface, 0, [xFrom, y], [xTo, y], PATH_SEGMENTS), PATH_SEGMENTS + 1);
    });
    // L from this pass's path to the next at the start of the drawn passes, L/2 at their end: each
    // along the surface with extension lines and arrowheads, its label above its middle.
    const tick = 0.08 * R;
    const arrowMm = Math.min(0.07 * R, 0.25 * L);
    const dimensionAt = (line: Line, x: number, length: number) => {
      const arc = surfacePolyline(surface, 0, [x, 0], [x, length], PATH_SEGMENTS);
      const head = (y: number, dir: 1 | -1) => [
        ...surfacePoint(surface, x - 0.5 * arrowMm, y + dir * arrowMm, 0),
        ...surfacePoint(surface, x, y, 0),
        ...surfacePoint(surface, x + 0.5 * arrowMm, y + dir * arrowMm, 0),
        ...surfacePoint(surface, x, y, 0),
      ];
      const points = [
        ...surfacePoint(surface, x, 0, tick),
        ...surfacePoint(surface, x, 0, 0),
        ...head(0, 1),
        ...arc,
        ...head(length, -1),
        ...surfacePoint(surface, x, length, tick),
      ];
      setLine(line, points, points.length / 3);
    };
    dimensionAt(this.dimension, xFrom, L);
    dimensionAt(this.halfDimension, xTo, L / 2);
    this.dimLabel.position.set(...surfacePoint(surface, xFrom, L / 2, tick));
    this.halfDimLabel.position.set(...surfacePoint(surface, xTo, L / 4, tick));
    setLabel(this.dimLabel, labels.interval);
    setLabel(this.halfDimLabel, labels.halfInterval);
    // y0: from the foot of O's drop to the contact, across the feed.
    this.offsetDimension.visible = labels.contactOffset !== null;
    setLine(this.offsetDimension, [ox, oy, dz(oz), ox, oy, 0, ox, oy, 0, ox, 0, 0], 4);
    this.offsetLabel.position.set(ox, oy / 2, -tick);
    setLabel(this.offsetLabel, labels.contactOffset ?? '');

    this.axes.scale.setScalar(1.6 * R);
    this.drawnSphere = drawnBoundingSphere(this.scene, (o) => o instanceof LabelAnchor);
    if (Math.abs(R - this.fittedRadiusMm) > 1e-12 * R) this.fit(R);
    // New results are drawn at once rather than on the next animation frame: the browser
    // presents the frame at its next vsync either way, and this saves up to one frame of latency.
    this.renderNow();
  }

  /**
   * Fits the camera to a tool of radius R: the first time from the isometric preset, afterwards
   * scaling target and distance with R so the viewing direction stays as the user left it.
   */
  private fit(R: number): void {
    const before = this.fittedRadiusMm;
    this.fittedRadiusMm = R;
    if (before === 0) {
      this.setCamera('iso');
      return;
    }
    const k = R / before;
    const offset = this.camera.position.clone().sub(this.controls.target).multiplyScalar(k);
    this.controls.target.multiplyScalar(k);
    this.camera.position.copy(this.controls.target).add(offset);
    this.controls.update();
  }

  /** Shows one frame of the paper's procedure (section, candidates, point), or hides the replay. */
  showTraceFrame(frame: TraceFrame | null): void {
    const on = frame !== null;
    if (!on && !this.traceSection.visible) return; // already hidden: nothing changed, no frame
    this.traceSection.visible = on;
    this.candidates.visible = on;
    this.traceMarker.visible = on && frame.point !== null;
    if (frame) {
      const map = this.heightMap;
      setLine(
        this.traceSection,
        drawnPoints(map, circlePoints(frame.sectionCentre, frame.sectionNormal, this.cornerRadiusMm)),
        SECTION_POINTS,
      );
      const attr = this.candidates.geometry.getAttribute('position') as BufferAttribute;
      const n = Math.min(frame.candidates.length / 3, attr.count);
      (attr.array as Float32Array).set(drawnPoints(map, frame.candidates.slice(0, 3 * n)));
      attr.needsUpdate = true;
      this.candidates.geometry.setDrawRange(0, n);
      if (frame.point) {
        const [px, py, pz] = frame.point;
        this.traceMarker.position.set(px, py, drawnHeightMm(map, pz));
        this.traceMarker.scale.setScalar(0.03 * (this.fittedRadiusMm || 1));
        setLabel(
          this.traceLabel,
          frame.phase === 'converged'
            ? 'P_hp (converged)'
            : frame.phase === 'search'
              ? 'best P_hp[i]'
              : 'single contact',
        );
      }
    }
    this.requestRender();
  }

  /** Marks the view as not answering the inputs on screen (or answering them again). */
  setStale(stale: boolean): void {
    this.container.classList.toggle('stale', stale);
  }

  setCamera(preset: CameraPreset): void {
    const R = this.fittedRadiusMm || 3;
    const target = new Vector3(0, 0, 0.3 * R);
    const d = 4.2 * R;
    if (preset === 'iso') this.camera.position.set(target.x + d * 0.75, target.y - d * 0.85, target.z + d * 0.6);
    else if (preset === 'feed') {
      // Looking back against the feed, so that Y runs to the right as in the profile view.
      target.z = 0.45 * R;
      this.camera.position.set(target.x + d * 1.3, target.y, target.z + 1e-3);
    } else this.camera.position.set(target.x, target.y, target.z + d * 1.3);
    this.camera.up.set(preset === 'top' ? 1 : 0, 0, preset === 'top' ? 0 : 1);
    this.controls.target.copy(target);
    this.controls.update();
    this.requestRender();
  }

  /** Renders on the next animation frame (several requests in one frame render once). */
  /** Takes the scene's colours from the stylesheet's current theme (on start and each change) and redraws. */
  applyTheme(): void {
    applySceneTheme(this.scene, this.renderer, this.container, BACKGROUND);
    this.requestRender();
  }

  requestRender(): void {
    if (this.frameRequested) return;
    this.frameRequested = true;
    requestAnimationFrame(() => {
      if (this.frameRequested) this.renderNow();
    });
  }

  private renderNow(): void {
    this.frameRequested = false;
    if (this.contextLost) return; // drawn again on webglcontextrestored
    // The near and far planes from the drawing's size and the camera's place (after any refit or move).
    fitClipPlanes(this.camera, this.drawnSphere);
    this.renderer.render(this.scene, this.camera);
    this.layoutLabels();
    this.frames++;
    this.onFrame?.();
  }

  /**
   * Places the labels three.js has just positioned so that none covers another, a marked point or
   * a badge, or runs out of the scene (labelLayout.ts), and records which legend entries the
   * drawing uses (`data-drawn` on the scene box, read by the legend and the tests).
   */
  private layoutLabels(): void {
    const w = this.widthPx;
    const h = this.heightPx;
    /** A point's place on screen (px) and its depth (-1 near plane, 1 far plane). */
    const toScreen = (o: Object3D): [number, number, number] => {
      const v = new Vector3().setFromMatrixPosition(o.matrixWorld).project(this.camera);
      return [(v.x * 0.5 + 0.5) * w, (-v.y * 0.5 + 0.5) * h, v.z];
    };
    const obstacles: PixelRect[] = [...this.badgeRects.values()];
    const objects: LabelAnchor[] = [];
    const requests: LabelRequest[] = [];
    const drawn = new Set<string>();
    this.scene.traverse((o) => {
      if (!shown(o)) {
        if (o instanceof LabelAnchor) o.element.style.display = 'none';
        return;
      }
      if (typeof o.userData.legend === 'string') drawn.add(o.userData.legend);
      if (o.userData.marker === true) {
        const [x, y] = toScreen(o);
        obstacles.push({ left: x - 4, top: y - 4, right: x + 4, bottom: y + 4 });
      }
      const spec = o.userData.label as LabelSpec | undefined;
      if (!(o instanceof LabelAnchor) || spec === undefined) return;
      // Centred on its point's projection; hidden behind the camera or beyond the far plane.
      const [x, y, depth] = toScreen(o);
      const inView = depth >= -1 && depth <= 1;
      o.element.style.display = inView ? '' : 'none';
      if (!inView) return;
      o.element.style.transform = `translate(-50%, -50%) translate(${x}px, ${y}px)`;
      if (o.element.parentNode !== this.labels) this.labels.append(o.element);
      const inner = o.element.firstElementChild as HTMLElement | null;
      if (!inner || inner.textContent === '') return;
      const size = this.sizes.get(inner);
      if (size === undefined) {
        this.sizeObserver.observe(inner); // placed once its size is known (the next frame)
        inner.style.visibility = 'hidden';
        return;
      }
      objects.push(o);
      requests.push({
        anchorXPx: x,
        anchorYPx: y,
        widthPx: size.widthPx,
        heightPx: size.heightPx,
        side: spec.side,
        priority: spec.priority,
      });
    });
    const placements = placeLabels(requests, w, h, obstacles);
    objects.forEach((o, i) => {
      const p = placements[i];
      const inner = o.element.firstElementChild as HTMLElement;
      if (!p?.visible) {
        inner.style.visibility = 'hidden';
        return;
      }
      inner.style.visibility = '';
      inner.style.transform = `translate(${p.dxPx.toFixed(1)}px, ${p.dyPx.toFixed(1)}px)`;
    });
    const keys = [...drawn].sort().join(' ');
    if (this.container.dataset.drawn !== keys) this.container.dataset.drawn = keys;
  }

  /** Labels and badges laid out anew: their sizes (and the badges' places) for the next layout. */
  private sizesChanged(entries: readonly ResizeObserverEntry[]): void {
    for (const entry of entries) {
      const el = entry.target as HTMLElement;
      const widthPx = el.offsetWidth;
      const heightPx = el.offsetHeight;
      if (el.classList.contains('scene-label')) this.sizes.set(el, { widthPx, heightPx });
      else if (widthPx > 0 && heightPx > 0)
        this.badgeRects.set(el, {
          left: el.offsetLeft,
          top: el.offsetTop,
          right: el.offsetLeft + widthPx,
          bottom: el.offsetTop + heightPx,
        });
      else this.badgeRects.delete(el);
    }
    this.requestRender();
  }

  private resize(): void {
    const w = Math.max(1, this.container.clientWidth);
    const h = Math.max(1, this.container.clientHeight);
    this.widthPx = w;
    this.heightPx = h;
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.requestRender();
  }

  /** Frees everything the scene made: observers, listeners, GPU resources and DOM nodes. */
  dispose(): void {
    this.resizeObserver.disconnect();
    this.sizeObserver.disconnect();
    this.frameRequested = false;
    const canvas = this.renderer.domElement;
    canvas.removeEventListener('webglcontextlost', this.onContextLost);
    canvas.removeEventListener('webglcontextrestored', this.onContextRestored);
    this.controls.dispose();
    const geometries = new Set<BufferGeometry>();
    const materials = new Set<Material>();
    this.scene.traverse((o) => {
      const drawable = o as Partial<Mesh>;
      if (drawable.geometry) geometries.add(drawable.geometry);
      const m = drawable.material;
      if (Array.isArray(m)) for (const x of m) materials.add(x);
      else if (m) materials.add(m);
    });
    for (const g of geometries) g.dispose();
    for (const m of materials) m.dispose();
    this.renderer.dispose();
    canvas.remove();
    this.labels.remove();
    this.onFrame = null;
  }
}
