/**
 * One WebGL view of a three.js scene, shared by the page's two 3D views (the tool's scene, scene.ts,
 * and the Machined surface, surfaceMesh.ts): the renderer and its canvas, a perspective camera
 * turned with the pointer (orbit.ts), the size followed, the theme's colours, the WebGL context's
 * loss and restoration, and frames drawn on demand.
 *
 * Its contract:
 *  - a frame is rendered only when something changed (camera move, resize, the owner's request, a
 *    restored WebGL context), never in a busy loop; several requests in one animation frame
 *    render once;
 *  - before each frame the camera's near and far planes enclose `drawnSphere`, from the camera's
 *    place (clipPlanes.ts), so what the owner draws is seen at any size and however the user turns
 *    or zooms;
 *  - after `webglcontextlost` it waits; on `webglcontextrestored` (three.js has rebuilt its GL state,
 *    its clear colour reset to black) it takes the theme's colours again and draws the last state
 *    without any input;
 *  - `dispose()` disconnects the resize observer and the canvas listeners, frees the renderer and
 *    removes the canvas (the owner frees what it drew).
 */
import {
  AmbientLight,
  Color,
  DirectionalLight,
  type Material,
  type Mesh,
  PerspectiveCamera,
  Scene,
  Sphere,
  WebGLRenderer,
} from 'three';
import { fitClipPlanes } from './clipPlanes';
import { OrbitController } from './orbit';

/** How a view is made. */
export interface View3DOptions {
  /** The canvas's `data-testid` and its accessible description. */
  readonly testId: string;
  readonly ariaLabel: string;
  /** The camera's vertical field of view (degrees) and its far plane before anything is drawn (mm). */
  readonly fovDeg: number;
  readonly initialFarMm: number;
  /** The background's light colour (the fallback) and the stylesheet's custom property for it. */
  readonly background: number;
  readonly backgroundProperty: string;
  /** Material colours switched with the theme: light colour -> custom property (none by default). */
  readonly themed?: ReadonlyMap<number, string>;
  /**
   * `adaptive`: multisampling and the device's pixel ratio (up to 2), except on a software
   * rasteriser; `cheap`: neither, on any device.
   */
  readonly quality: 'adaptive' | 'cheap';
  /** The white lights, added first: an ambient one and a sun shining from `sunFrom` (intensities). */
  readonly lights: {
    readonly ambient: number;
    readonly sun: number;
    readonly sunFrom: readonly [number, number, number];
  };
}

/**
 * Recolours a three.js scene from the stylesheet: the background from `backgroundProperty` and each
 * material whose light colour is in `themed` from its custom property (read on `element`). The
 * light colour is kept in the material's userData, so it can be applied again and again.
 */
export function applySceneTheme(
  scene: Scene,
  renderer: WebGLRenderer,
  element: Element,
  background: number,
  themed: ReadonlyMap<number, string>,
  backgroundProperty = '--scene-bg',
): void {
  const css = getComputedStyle(element);
  const read = (name: string, fallback: number): Color => {
    const text = css.getPropertyValue(name).trim();
    return new Color(text === '' ? fallback : text);
  };
  renderer.setClearColor(read(backgroundProperty, background));
  if (themed.size === 0) return;
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

const NO_THEMED: ReadonlyMap<number, string> = new Map();

/** One WebGL view: its owner adds what it draws to `scene`, keeps `drawnSphere` and asks for frames. */
export class View3D {
  readonly scene = new Scene();
  /** Its near and far planes are set before each frame from `drawnSphere` (clipPlanes.ts). */
  readonly camera: PerspectiveCamera;
  readonly controls: OrbitController;
  readonly renderer: WebGLRenderer;
  /** Whether WebGL runs on a software rasteriser (SwiftShader, llvmpipe): then no MSAA, pixel ratio 1. */
  readonly softwareRendering: boolean;
  /** A sphere around what is drawn (world, mm; empty before anything is): the owner keeps it up to date. */
  readonly drawnSphere = new Sphere().makeEmpty();
  /** The view's size (px), as last laid out. */
  widthPx = 1;
  heightPx = 1;
  /** Frames rendered so far. */
  frames = 0;
  /** Called after each rendered frame (the page's and the tests' frame listener). */
  onFrame: (() => void) | null = null;
  /** Called after the view takes a new size, before its frame is drawn (the owner may refit its camera). */
  afterResize: (() => void) | null = null;
  /** Called before each render (the owner sets what its materials read of the screen). */
  beforeRender: (() => void) | null = null;
  /** Called after each render, before `onFrame`, with the frame on the canvas (the label layer). */
  afterRender: (() => void) | null = null;
  private readonly resizeObserver = new ResizeObserver(() => this.resize());
  private contextLost = false;
  private frameRequested = false;
  private readonly onContextLost = () => {
    this.contextLost = true;
  };
  private readonly onContextRestored = () => {
    this.contextLost = false;
    // three.js's own listener (added with the renderer, so it ran before this one) has rebuilt its
    // GL state, the clear colour with it (black): the theme's again, and a frame of the last state.
    this.applyTheme();
  };

  constructor(
    private readonly container: HTMLElement,
    private readonly options: View3DOptions,
  ) {
    // Multisampling and a high pixel ratio cost little on a GPU, but on a software rasteriser
    // they tripled the input-to-frame time (measured: about 50 ms against 6 ms on SwiftShader).
    const adaptive = options.quality === 'adaptive';
    this.softwareRendering = adaptive && isSoftwareWebGL();
    const cheap = !adaptive || this.softwareRendering;
    this.renderer = new WebGLRenderer({ antialias: !cheap });
    this.renderer.setPixelRatio(cheap ? 1 : Math.min(2, window.devicePixelRatio || 1));
    this.renderer.setClearColor(new Color(options.background));
    const canvas = this.renderer.domElement;
    canvas.setAttribute('data-testid', options.testId);
    canvas.setAttribute('aria-label', options.ariaLabel);
    canvas.setAttribute('role', 'img');
    canvas.addEventListener('webglcontextlost', this.onContextLost);
    canvas.addEventListener('webglcontextrestored', this.onContextRestored);
    container.append(canvas);
    this.camera = new PerspectiveCamera(options.fovDeg, 1, 0.01, options.initialFarMm);
    this.camera.up.set(0, 0, 1);
    this.controls = new OrbitController(this.camera, canvas);
    // A vertical swipe over the view scrolls the page; a horizontal
    // drag turns the view and two fingers zoom: the deliberate gestures.
    canvas.style.touchAction = 'pan-y';
    this.controls.onChange = () => this.requestRender();
    this.resizeObserver.observe(container);
    const { ambient, sun, sunFrom } = options.lights;
    this.scene.add(new AmbientLight(0xffffff, ambient));
    const sunLight = new DirectionalLight(0xffffff, sun);
    sunLight.position.set(...sunFrom);
    this.scene.add(sunLight);
  }

  /** Takes the colours from the stylesheet's current theme (on start and each change) and redraws. */
  applyTheme(): void {
    const { background, themed, backgroundProperty } = this.options;
    applySceneTheme(this.scene, this.renderer, this.container, background, themed ?? NO_THEMED, backgroundProperty);
    this.requestRender();
  }

  /** Renders on the next animation frame (several requests in one frame render once). */
  requestRender(): void {
    if (this.frameRequested) return;
    this.frameRequested = true;
    requestAnimationFrame(() => {
      if (this.frameRequested) this.renderNow();
    });
  }

  /** Renders at once (a request pending is then fulfilled); nothing while the context is lost. */
  renderNow(): void {
    this.frameRequested = false;
    if (this.contextLost) return; // drawn again on webglcontextrestored
    // The near and far planes from the drawing's size and the camera's place (after any refit or move).
    fitClipPlanes(this.camera, this.drawnSphere);
    this.beforeRender?.();
    this.renderer.render(this.scene, this.camera);
    this.afterRender?.();
    this.frames++;
    this.onFrame?.();
  }

  /** Takes the container's laid-out size (called by the resize observer; the owner may call it at once). */
  resize(): void {
    const w = Math.max(1, this.container.clientWidth);
    const h = Math.max(1, this.container.clientHeight);
    this.widthPx = w;
    this.heightPx = h;
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.afterResize?.();
    this.requestRender();
  }

  /** Stops drawing and frees the renderer and the canvas; what the owner drew, it frees itself. */
  dispose(): void {
    this.resizeObserver.disconnect();
    this.frameRequested = false;
    const canvas = this.renderer.domElement;
    canvas.removeEventListener('webglcontextlost', this.onContextLost);
    canvas.removeEventListener('webglcontextrestored', this.onContextRestored);
    this.controls.dispose();
    this.renderer.dispose();
    canvas.remove();
    this.afterRender = null;
    this.beforeRender = null;
    this.afterResize = null;
    this.onFrame = null;
  }
}

/** What owns one {@link View3D} (the page's two 3D views): frames, theme, render requests and disposal go to the view. */
export class ViewedScene {
  protected readonly view: View3D;

  constructor(container: HTMLElement, options: View3DOptions) {
    this.view = new View3D(container, options);
  }

  /** Frames rendered so far (tests read it). */
  get frames(): number {
    return this.view.frames;
  }

  /** Takes the colours from the stylesheet's current theme (on start and each change) and redraws. */
  applyTheme(): void {
    this.view.applyTheme();
  }

  /** Renders on the next animation frame (several requests in one frame render once). */
  requestRender(): void {
    this.view.requestRender();
  }

  /** Frees the view; an owner frees what it drew, then calls this. */
  dispose(): void {
    this.view.dispose();
  }
}
