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
 *  - the camera is fitted on the first geometry and refitted, keeping the viewing direction,
 *    whenever the tool radius changes;
 *  - the camera's near and far planes enclose what is drawn (clipPlanes.ts): the tool is seen at
 *    every radius from 0.001 to 1000 mm and however the user turns or zooms;
 *  - after a lost WebGL context is restored it draws the last state on the theme's colours
 *    without any input (view3d.ts);
 *  - `dispose()` disconnects the observers and the canvas listeners and frees every GPU resource
 *    and DOM node it made.
 */
import { AmbientLight, DirectionalLight, Group } from 'three';
import type { SceneGeometry, TraceFrame } from '../worker/protocol';
import { type CameraPreset, presetCamera, rescaleCamera } from './cameraFit';
import { drawnBoundingSphere } from './clipPlanes';
import { AxesDrawable } from './drawables/axes';
import { CuspsDrawable } from './drawables/cusps';
import { DesignSurfacesDrawable } from './drawables/designSurfaces';
import { DimensionsDrawable } from './drawables/dimensions';
import { type Drawable, type DrawState, type SceneLabels, THEMED_COLOURS } from './drawables/parts';
import { PathsDrawable } from './drawables/paths';
import { ToolDrawable } from './drawables/tool';
import { ToolMarksDrawable } from './drawables/toolMarks';
import { TraceDrawable, type TraceSizes } from './drawables/trace';
import { heightMapFor, sceneHeightExaggeration } from './heightExaggeration';
import { LabelAnchor, LabelLayer } from './labelLayer';
import { View3D } from './view3d';

export type { CameraPreset } from './cameraFit';
export type { SceneLabels } from './drawables/parts';

const BACKGROUND = 0xf7f8fa;

export class ToolScene {
  private readonly view: View3D;
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
  private traceSizes: TraceSizes = { map: heightMapFor(1, 0), cornerRadiusMm: 1, toolRadiusMm: 1 };
  /** Tool radius the camera was fitted to (0: not yet). */
  private fittedRadiusMm = 0;

  constructor(private readonly container: HTMLElement) {
    this.view = new View3D(container, {
      testId: 'scene-canvas',
      ariaLabel: '3D view of the tool in its posture, its neighbouring passes and the cusp sections',
      fovDeg: 40,
      initialFarMm: 1000,
      background: BACKGROUND,
      backgroundProperty: '--scene-bg',
      themed: THEMED_COLOURS,
      quality: 'adaptive',
    });
    this.labels = new LabelLayer(container, () => this.requestRender());
    const { scene, camera } = this.view;
    this.view.afterRender = () => this.labels.layout(scene, camera, this.view.widthPx, this.view.heightPx);
    scene.add(new AmbientLight(0xffffff, 1.2));
    const sun = new DirectionalLight(0xffffff, 1.6);
    sun.position.set(3, -4, 6);
    scene.add(sun);
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

  /** Frames rendered so far. */
  get frames(): number {
    return this.view.frames;
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
    this.traceSizes = { map, cornerRadiusMm: g.cornerRadiusMm, toolRadiusMm: R };
    const badge = this.scaleBadge;
    badge.hidden = false;
    badge.textContent =
      map.factor === 1 ? 'heights at true scale' : `heights drawn x${map.factor} (up to 2h above the plane)`;
    badge.title =
      map.factor === 1
        ? 'Every length and height is drawn at true scale.'
        : `So that the scallop can be seen, heights from the plane up to twice the scallop height are drawn ${map.factor} times taller, the tool above them at true scale. Only the drawing: every number is the solver's.`;
    drawnBoundingSphere(this.view.scene, (o) => o instanceof LabelAnchor, this.view.drawnSphere);
    if (Math.abs(R - this.fittedRadiusMm) > 1e-12 * R) this.fit(R);
    // New results are drawn at once rather than on the next animation frame: the browser
    // presents the frame at its next vsync either way, and this saves up to one frame of latency.
    this.view.renderNow();
  }

  /**
   * Fits the camera to a tool of radius R: the first time from the isometric preset, afterwards
   * scaling target and distance with R so the viewing direction stays as the user left it.
   */
  private fit(R: number): void {
    const before = this.fittedRadiusMm;
    this.fittedRadiusMm = R;
    if (before === 0) this.setCamera('iso');
    else rescaleCamera(this.view.camera, this.view.controls, R / before);
  }

  /** Shows one frame of the paper's procedure (section, candidates, point), or hides the replay. */
  showTraceFrame(frame: TraceFrame | null): void {
    if (this.trace.show(frame, this.traceSizes)) this.requestRender();
  }

  /** Marks the view as not answering the inputs on screen (or answering them again). */
  setStale(stale: boolean): void {
    this.container.classList.toggle('stale', stale);
  }

  setCamera(preset: CameraPreset): void {
    presetCamera(this.view.camera, this.view.controls, preset, this.fittedRadiusMm || 3);
    this.requestRender();
  }

  /** Takes the scene's colours from the stylesheet's current theme (on start and each change) and redraws. */
  applyTheme(): void {
    this.view.applyTheme();
  }

  /** Renders on the next animation frame (several requests in one frame render once). */
  requestRender(): void {
    this.view.requestRender();
  }

  /** Frees everything the scene made: observers, listeners, GPU resources and DOM nodes. */
  dispose(): void {
    this.view.dispose();
    this.labels.dispose();
    for (const d of this.drawables) d.dispose();
    this.trace.dispose();
    this.scaleBadge.remove();
  }
}
