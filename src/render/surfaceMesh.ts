/**
 * The simulated machined surface in 3D: a three.js mesh from the simulation's height field
 * (surfaceGrid.ts: coloured by height, heights exaggerated by a stated factor), in one small
 * WebGL view that renders only when something changed. Its camera's near and far planes enclose
 * the surface from wherever the camera is (clipPlanes.ts); after a lost WebGL context is restored
 * it takes the theme's background again and draws its last surface without any input.
 */
import {
  AmbientLight,
  BufferAttribute,
  BufferGeometry,
  Color,
  DirectionalLight,
  DoubleSide,
  Mesh,
  MeshLambertMaterial,
  PerspectiveCamera,
  Scene,
  Sphere,
  WebGLRenderer,
} from 'three';
import { fitClipPlanes } from './clipPlanes';
import { OrbitController } from './orbit';
import { type HeightField, type SurfaceGrid, surfaceGrid } from './surfaceGrid';

const SURFACE_BACKGROUND = 0xf4f6f9;

/** One small WebGL view of the simulated surface. */
export class SurfaceScene {
  private readonly renderer: WebGLRenderer;
  private readonly scene = new Scene();
  /** Its near and far planes are set before each frame from the surface's size (clipPlanes.ts). */
  private readonly camera = new PerspectiveCamera(35, 1, 0.01, 1e6);
  private readonly controls: OrbitController;
  private readonly geometry = new BufferGeometry();
  private readonly resizeObserver: ResizeObserver;
  private frameRequested = false;
  private contextLost = false;
  /** A sphere around the drawn surface (mm; empty before the first). */
  private readonly drawnSphere = new Sphere().makeEmpty();
  /** Frames drawn (tests read it through the view). */
  frames = 0;

  constructor(private readonly container: HTMLElement) {
    this.renderer = new WebGLRenderer({ antialias: false });
    this.renderer.setPixelRatio(1);
    this.renderer.setClearColor(new Color(SURFACE_BACKGROUND));
    const canvas = this.renderer.domElement;
    canvas.setAttribute('data-testid', 'surface-canvas');
    canvas.setAttribute('role', 'img');
    canvas.setAttribute('aria-label', '3D view of the simulated machined surface, coloured by height');
    container.append(canvas);
    canvas.addEventListener('webglcontextlost', () => {
      this.contextLost = true;
    });
    // three.js's own listener (added with the renderer, so it runs first) rebuilds its GL state,
    // the clear colour with it (black): the theme's background again, and a frame of the surface.
    canvas.addEventListener('webglcontextrestored', () => {
      this.contextLost = false;
      this.applyTheme();
    });
    this.camera.up.set(0, 0, 1);
    this.controls = new OrbitController(this.camera, canvas);
    // As the 3D scene: a vertical swipe scrolls the page, a horizontal drag turns the view.
    canvas.style.touchAction = 'pan-y';
    this.controls.onChange = () => this.requestRender();
    this.scene.add(new AmbientLight(0xffffff, 1.4));
    const sun = new DirectionalLight(0xffffff, 1.5);
    sun.position.set(2, -3, 5);
    this.scene.add(sun);
    this.scene.add(new Mesh(this.geometry, new MeshLambertMaterial({ vertexColors: true, side: DoubleSide })));
    this.resizeObserver = new ResizeObserver(() => this.resize());
    this.resizeObserver.observe(container);
  }

  /** Shows a height field, heights times `exaggeration`. */
  update(field: HeightField, exaggeration: number): SurfaceGrid {
    const g = surfaceGrid(field, exaggeration);
    this.geometry.setAttribute('position', new BufferAttribute(g.positions, 3));
    this.geometry.setAttribute('color', new BufferAttribute(g.colours, 3));
    this.geometry.setIndex(new BufferAttribute(g.indices, 1));
    this.geometry.computeVertexNormals();
    this.geometry.computeBoundingSphere();
    if (this.geometry.boundingSphere) this.drawnSphere.copy(this.geometry.boundingSphere);
    const cx = field.alongLengthMm / 2;
    const cy = (field.acrossFromMm + field.acrossToMm) / 2;
    const size = Math.max(field.alongLengthMm, field.acrossToMm - field.acrossFromMm);
    this.controls.target.set(cx, cy, 0);
    this.camera.position.set(cx - 0.55 * size, cy - 0.75 * size, 0.6 * size);
    this.controls.update();
    this.requestRender();
    return g;
  }

  /** Takes the background from the stylesheet's current theme (`--surface-bg`) and redraws. */
  applyTheme(): void {
    this.renderer.setClearColor(
      new Color(getComputedStyle(this.container).getPropertyValue('--surface-bg').trim() || SURFACE_BACKGROUND),
    );
    this.requestRender();
  }

  requestRender(): void {
    if (this.frameRequested) return;
    this.frameRequested = true;
    requestAnimationFrame(() => {
      this.frameRequested = false;
      if (this.contextLost) return; // drawn again on webglcontextrestored
      fitClipPlanes(this.camera, this.drawnSphere);
      this.renderer.render(this.scene, this.camera);
      this.frames++;
    });
  }

  private resize(): void {
    const w = Math.max(1, this.container.clientWidth);
    const h = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.requestRender();
  }
}
