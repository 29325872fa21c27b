/**
 * three.js scene of the tool in its posture, its neighbouring passes, the cusp sections and the
 * h pseudo plane; on a cylinder, the cylinder's patch, the h pseudo surface (the cylinder offset by h,
 * radially), the neighbouring passes turned about its axis (axis along the feed) or stepped along
 * it (across), and the cusps. Frame: the contact of this pass at the origin, X feed, Y cross-feed,
 * Z up (mm). The surface's geometry comes from the core (surfaceGeometry.ts), as plain arrays.
 *
 * The scene composes its parts: the shared WebGL view (view3d.ts: renderer, camera and its clipping
 * planes, resize, theme, context loss, frames on demand), the label layer (labelLayer.ts) and the
 * drawables (drawables/: each built once and updated in place from one state).
 *
 * Its contract:
 *  - objects are built once and updated in place; nothing is rebuilt per update, so nothing
 *    leaks (the axes are scaled, HTML labels are created once and only shown or hidden);
 *  - a frame is rendered only when something changed (view3d.ts);
 *  - the camera is fitted (cameraFit.ts) to the tool with its shank, its sections, the passes'
 *    paths and the labels' points, so that all are inside the view and fill it: on the first
 *    geometry from the isometric preset, on each preset, and on each new state or size keeping the
 *    viewing direction, until the user zooms or pans (then only scaled with the tool radius);
 *    while the step-through shows a step, on what that step shows (its section, candidates and
 *    point), moved at once (no animation, so nothing moves for a reader who asked for reduced
 *    motion, and a step costs one frame);
 *  - the camera's near and far planes enclose what is drawn (clipPlanes.ts): the tool is seen at
 *    every radius from 0.001 to 1000 mm and however the user turns or zooms;
 *  - after a lost WebGL context is restored it draws the last state on the theme's colours
 *    without any input (view3d.ts);
 *  - `dispose()` disconnects the observers and the canvas listeners and frees every GPU resource
 *    and DOM node it made.
 */
import { Color, Group, type Object3D, Vector3 } from 'three';
import type { SceneGeometry, TraceFrame } from '../worker/protocol';
import { type CameraPreset, fitCamera, presetDirection, type Vec3 } from './cameraFit';
import { drawnBoundingSphere } from './clipPlanes';
import { AxesDrawable } from './drawables/axes';
import { CuspsDrawable } from './drawables/cusps';
import { DesignSurfacesDrawable } from './drawables/designSurfaces';
import { DimensionsDrawable } from './drawables/dimensions';
import { type Drawable, type DrawState, THEMED_COLOURS } from './drawables/parts';
import { PathsDrawable } from './drawables/paths';
import { ToolDrawable } from './drawables/tool';
import { ToolMarksDrawable } from './drawables/toolMarks';
import { TraceDrawable, type TraceSizes } from './drawables/trace';
import { FatLine, setLineScreen } from './fatLines';
import { gatherFramePoints } from './framePoints';
import { drawnHeightMm, heightMapFor, sceneHeightExaggeration } from './heightExaggeration';
import { LabelAnchor, LabelLayer } from './labelLayer';
import type { SceneLabels } from './sceneLabels';
import { SCENE_WORDS } from './sceneWords';
import { ViewedScene } from './view3d';

export type { CameraPreset } from './cameraFit';
export type { SceneLabels } from './sceneLabels';

const BACKGROUND = 0xf7f8fa;

/** The view's accessible name (English; the page gives another language's with the labels). */
const SCENE_NAME = '3D view of the tool in its posture, its neighbouring passes and the cusp sections';

/** The share of the view's half-size kept free around the whole scene (its labels' points at the edge). */
const OVERVIEW_MARGIN = 0.14;
/** Around a step's section and points: the close-up keeps some of the tool around them in view. */
const FOCUS_MARGIN = 0.45;

/** Where the camera is and what it was fitted to (world mm), for the tests' probe. */
export interface SceneFraming {
  readonly position: Vec3;
  readonly target: Vec3;
  readonly up: Vec3;
  readonly fovDeg: number;
  readonly aspect: number;
  /**
   * The corners of the tool's and its holder's boxes (the tool in its posture, shank included; flat
   * xyz), about the tool axis and facing the camera: a box along the surface's axes stands far out of a tool turned into
   * the machine frame (three-axis), and the view framed to it was left empty above and below.
   */
  readonly toolBox: readonly number[];
  /** Every point the camera was fitted to (flat xyz). */
  readonly framed: readonly number[];
  /** The step-through's close-up: the points of the step shown (flat xyz), or null when none is. */
  readonly focus: readonly number[] | null;
  /** Whether the camera still follows what is drawn (false once the user zoomed or panned). */
  readonly autoFit: boolean;
  /** The tool: its centre O, its axis up the shank (world) and its radius (mm); null before a state. */
  readonly tool: { readonly centre: Vec3; readonly axis: Vec3; readonly radiusMm: number } | null;
  /** The lines drawn over everything, shown now: their legend key, width (CSS px) and points (world, flat xyz). */
  readonly lines: ReadonlyArray<{ readonly key: string; readonly widthPx: number; readonly points: readonly number[] }>;
}

export class ToolScene extends ViewedScene {
  private readonly labels: LabelLayer;
  /**
   * The parts, built in this order: the lines and dots drawn over everything are drawn in the
   * order their materials were made (three.js sorts them by material), so the marks of the
   * posture come first and the cusps' over them, as the reader expects.
   */
  private readonly toolMarks = new ToolMarksDrawable();
  private readonly paths = new PathsDrawable();
  private readonly dimensions = new DimensionsDrawable();
  private readonly trace = new TraceDrawable();
  private readonly tool = new ToolDrawable();
  private readonly surfaces = new DesignSurfacesDrawable();
  private readonly cusps = new CuspsDrawable();
  private readonly axes = new AxesDrawable();
  private readonly drawables: readonly Drawable[] = [
    this.surfaces,
    this.cusps,
    this.tool,
    this.paths,
    this.toolMarks,
    this.dimensions,
    this.axes,
  ];
  /**
   * What the drawables draw, in the CC point's local frame: turned into the machine frame (z up, the
   * tool axis) for three-axis machining, as it is at other times (the local frame is the world).
   */
  private readonly world = new Group();
  /** The height exaggeration, said on the scene (a badge in its bottom left corner). */
  private readonly scaleBadge = document.createElement('div');
  /** What the step-through draws with: the last state's sizes (a unit tool before any). */
  private traceSizes: TraceSizes = {
    map: heightMapFor(1, 0),
    cornerRadiusMm: 1,
    toolRadiusMm: 1,
    words: SCENE_WORDS,
  };
  /** The last state drawn (null before any): the tests' probe reads its tool. */
  private lastGeometry: SceneGeometry | null = null;
  /** Tool radius the camera was fitted to (0: not yet). */
  private fittedRadiusMm = 0;
  /** The preset last asked (the first fit looks from it, should it be asked before any state). */
  private preset: CameraPreset = 'iso';
  /** The camera follows what is drawn until the user zooms or pans (a preset takes it back). */
  private autoFit = true;
  /** Whether a step of the step-through is shown (the camera then frames it). */
  private traceShown = false;
  /** The background's colour, read before each frame for the lines' halos (reused). */
  private readonly background = new Color();
  /** The points of the last fit (reused). */
  private readonly points: number[] = [];

  constructor(private readonly container: HTMLElement) {
    super(container, {
      testId: 'scene-canvas',
      ariaLabel: SCENE_NAME,
      fovDeg: 40,
      initialFarMm: 1000,
      background: BACKGROUND,
      backgroundProperty: '--scene-bg',
      themed: THEMED_COLOURS,
      quality: 'adaptive',
      lights: { ambient: 0.8, sun: 1.2, sunFrom: [3, -4, 6] },
    });
    this.labels = new LabelLayer(container, () => this.requestRender());
    const { scene, camera, controls } = this.view;
    controls.onZoomOrPan = () => {
      this.autoFit = false;
    };
    this.view.afterResize = () => {
      if (this.fittedRadiusMm > 0 && this.autoFit) this.fitView();
    };
    // The lines' widths are in CSS px: each frame is drawn for the drawing buffer's size.
    this.view.beforeRender = () => {
      const { renderer } = this.view;
      const ratio = renderer.getPixelRatio();
      renderer.getClearColor(this.background);
      setLineScreen(
        Math.floor(this.view.widthPx * ratio),
        Math.floor(this.view.heightPx * ratio),
        ratio,
        this.background,
      );
    };
    this.view.afterRender = () => this.labels.layout(scene, camera, this.view.widthPx, this.view.heightPx);
    for (const d of this.drawables) this.world.add(...d.objects);
    this.world.matrixAutoUpdate = false;
    scene.add(this.world);
    scene.add(...this.trace.objects);
    this.scaleBadge.className = 'scene-scale';
    this.scaleBadge.setAttribute('data-testid', 'scene-exaggeration');
    this.scaleBadge.hidden = true;
    container.append(this.scaleBadge);
    for (const badge of container.querySelectorAll<HTMLElement>('.stale-badge, .scene-scale'))
      this.labels.watchBadge(badge);
    this.view.resize();
  }

  /** Called after each rendered frame. */
  get onFrame(): (() => void) | null {
    return this.view.onFrame;
  }

  set onFrame(listener: (() => void) | null) {
    this.view.onFrame = listener;
  }

  /** Whether WebGL runs on a software rasteriser (SwiftShader, llvmpipe): then no MSAA, pixel ratio 1. */
  get softwareRendering(): boolean {
    return this.view.softwareRendering;
  }

  /** Shows a solved state. Everything is updated in place. */
  update(g: SceneGeometry, labels: SceneLabels): void {
    const canvas = this.view.renderer.domElement;
    const name = labels.name ?? SCENE_NAME;
    if (canvas.getAttribute('aria-label') !== name) canvas.setAttribute('aria-label', name);
    const R = g.toolRadiusMm;
    // Heights exaggerated near a plane when the scallop would be too low to see (the drawing only);
    // not in the machine frame, where the programmed step's dimension is drawn at true scale.
    const map = heightMapFor(
      g.surface.kind === 'plane' && g.machine === null ? sceneHeightExaggeration(R, g.scallopHeightMm) : 1,
      g.scallopHeightMm,
    );
    if (g.machine === null) this.world.matrix.identity();
    else this.world.matrix.fromArray(g.machine.frameMatrix as number[]);
    this.world.matrixWorldNeedsUpdate = true;
    const state: DrawState = {
      geometry: g,
      labels,
      map,
      toolRadiusMm: R,
      intervalMm: g.intervalMm,
      dotRadiusMm: 0.035 * R,
      fromMm: -1.3 * R,
      toMm: 1.3 * R,
    };
    for (const d of this.drawables) d.update(state);
    this.lastGeometry = g;
    this.traceSizes = { map, cornerRadiusMm: g.cornerRadiusMm, toolRadiusMm: R, words: labels.words ?? SCENE_WORDS };
    const badge = this.scaleBadge;
    badge.hidden = false;
    // In the reader's language (the page's words, sceneWords.ts in English).
    const words = labels.words ?? SCENE_WORDS;
    const k = map.factor === 1 ? null : map.factor;
    badge.textContent = words.scale(k);
    badge.title = words.scaleTitle(k);
    drawnBoundingSphere(this.view.scene, (o) => o instanceof LabelAnchor, this.view.drawnSphere);
    this.fit(R);
    // New results are drawn at once rather than on the next animation frame: the browser
    // presents the frame at its next vsync either way, and this saves up to one frame of latency.
    this.view.renderNow();
  }

  /**
   * After a new state: the first time from the isometric preset; then, while the camera follows
   * what is drawn, fitted again from where it looks; once the user zoomed or panned, scaled about
   * the contact with the tool radius only (the same view of a tool that many times larger).
   */
  private fit(R: number): void {
    const before = this.fittedRadiusMm;
    this.fittedRadiusMm = R;
    if (before === 0) this.setCamera(this.preset);
    else if (this.autoFit) this.fitView();
    else if (Math.abs(R - before) > 1e-12 * R) {
      const { camera, controls } = this.view;
      const offset = camera.position
        .clone()
        .sub(controls.target)
        .multiplyScalar(R / before);
      controls.target.multiplyScalar(R / before);
      camera.position.copy(controls.target).add(offset);
      controls.update();
    }
  }

  /**
   * Fits the camera, looking from where it looks now, to everything drawn (or, while a step of the
   * step-through is shown, to that step's section and points).
   */
  private fitView(): void {
    const { camera, controls, scene } = this.view;
    scene.updateMatrixWorld();
    const towards = camera.position.clone().sub(controls.target);
    if (towards.lengthSq() === 0) towards.set(0, 0, 1);
    const facing = towards.toArray();
    const focus = this.traceShown && gatherFramePoints(scene, this.points, true, facing) > 0;
    const count = focus ? this.points.length / 3 : gatherFramePoints(scene, this.points, false, facing);
    const fitted = fitCamera(this.points, count, towards.toArray(), camera.up.toArray(), {
      fovDeg: camera.fov,
      aspect: camera.aspect,
      margin: focus ? FOCUS_MARGIN : OVERVIEW_MARGIN,
    });
    if (fitted === null) return;
    camera.position.set(...fitted.position);
    controls.target.set(...fitted.target);
    controls.update();
    this.requestRender();
  }

  /** Where the camera is and what it frames (the tests' probe). */
  framing(): SceneFraming {
    const { camera, controls, scene } = this.view;
    scene.updateMatrixWorld();
    const facing = camera.position.clone().sub(controls.target).toArray();
    const toolBox: number[] = [];
    gatherFramePoints(this.tool.objects[0] as Object3D, toolBox, false, facing);
    const all: number[] = [];
    gatherFramePoints(scene, all, false, facing);
    const focus: number[] = [];
    const focused = this.traceShown && gatherFramePoints(scene, focus, true, facing) > 0;
    const lines: Array<{ key: string; widthPx: number; points: number[] }> = [];
    const at = new Vector3();
    scene.traverseVisible((o) => {
      if (!(o instanceof FatLine) || o.material.depthTest || typeof o.userData.legend !== 'string') return;
      const points: number[] = [];
      for (let i = 0; i < o.drawnPoints; i++)
        points.push(
          ...at
            .fromArray(o.points, 3 * i)
            .applyMatrix4(o.matrixWorld)
            .toArray(),
        );
      lines.push({ key: o.userData.legend, widthPx: o.material.widthPx, points });
    });
    const g = this.lastGeometry;
    const tool =
      g === null
        ? null
        : {
            centre: at
              .set(g.toolCentre[0], g.toolCentre[1], drawnHeightMm(this.traceSizes.map, g.toolCentre[2]))
              .applyMatrix4(this.world.matrix)
              .toArray(),
            axis: at
              .set(...g.toolAxis)
              .transformDirection(this.world.matrix)
              .toArray(),
            radiusMm: g.toolRadiusMm,
          };
    return {
      tool,
      lines,
      position: camera.position.toArray(),
      target: controls.target.toArray(),
      up: camera.up.toArray(),
      fovDeg: camera.fov,
      aspect: camera.aspect,
      toolBox,
      framed: all,
      focus: focused ? focus : null,
      autoFit: this.autoFit,
    };
  }

  /** Shows one frame of the paper's procedure (section, candidates, point), or hides the replay. */
  showTraceFrame(frame: TraceFrame | null): void {
    if (!this.trace.show(frame, this.traceSizes)) return;
    this.traceShown = frame !== null;
    // The camera moves to what the step shows (or back to the whole scene when the replay ends).
    if (this.autoFit && this.fittedRadiusMm > 0) this.fitView();
    this.requestRender();
  }

  /** Takes the colours from the stylesheet's current theme (on start and each change) and redraws. */
  override applyTheme(): void {
    super.applyTheme();
    this.tool.matchTheme();
  }

  /** Marks the view as not answering the inputs on screen (or answering them again). */
  setStale(stale: boolean): void {
    this.container.classList.toggle('stale', stale);
  }

  /** Looks from a preset direction (cameraFit.ts), fitted to what is drawn; the camera follows it again. */
  setCamera(preset: CameraPreset): void {
    const { camera, controls } = this.view;
    const { towardsCamera, up } = presetDirection(preset);
    this.preset = preset;
    camera.up.set(...up);
    camera.position.copy(controls.target).add(camera.position.clone().set(...towardsCamera));
    controls.update();
    this.autoFit = true;
    this.fitView();
    this.requestRender();
  }

  /** Frees everything the scene made: observers, listeners, GPU resources and DOM nodes. */
  override dispose(): void {
    super.dispose();
    this.labels.dispose();
    for (const d of this.drawables) d.dispose();
    this.trace.dispose();
    this.scaleBadge.remove();
  }
}
