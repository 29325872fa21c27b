/**
 * The simulated machined surface in 3D: a three.js mesh from the simulation's height field
 * (surfaceGrid.ts: coloured by height, heights exaggerated by a stated factor), in one small WebGL
 * view (view3d.ts, shared with the tool's scene) that renders only when something changed. Its
 * camera's near and far planes enclose the surface from wherever the camera is; after a lost
 * WebGL context is restored it takes the theme's background again and draws its last surface
 * without any input.
 */
import { BufferAttribute, BufferGeometry, DoubleSide, Mesh, MeshLambertMaterial } from 'three';
import { type HeightField, type SurfaceGrid, type SurfaceGridOptions, surfaceGrid } from './surfaceGrid';
import { ViewedScene } from './view3d';

const SURFACE_BACKGROUND = 0xf4f6f9;

/** One small WebGL view of the simulated surface. */
export class SurfaceScene extends ViewedScene {
  private readonly geometry = new BufferGeometry();
  private readonly mesh = new Mesh(this.geometry, new MeshLambertMaterial({ vertexColors: true, side: DoubleSide }));

  constructor(container: HTMLElement) {
    super(container, {
      testId: 'surface-canvas',
      ariaLabel: '3D view of the simulated machined surface, coloured by height',
      fovDeg: 35,
      initialFarMm: 1e6,
      background: SURFACE_BACKGROUND,
      backgroundProperty: '--surface-bg',
      quality: 'cheap',
      lights: { ambient: 1.4, sun: 1.5, sunFrom: [2, -3, 5] },
    });
    this.view.scene.add(this.mesh);
  }

  /**
   * Shows a height field, heights times `exaggeration` (`options`: rows kept, the ramp's range);
   * a field of the same size is written into the buffers in place.
   */
  update(field: HeightField, exaggeration: number, options: SurfaceGridOptions = {}): SurfaceGrid {
    const g = surfaceGrid(field, exaggeration, options);
    this.write('position', g.positions);
    this.write('color', g.colours);
    const index = this.geometry.getIndex();
    if (index !== null && index.array.length === g.indices.length) {
      index.array.set(g.indices);
      index.needsUpdate = true;
    } else this.geometry.setIndex(new BufferAttribute(g.indices, 1));
    this.geometry.computeVertexNormals();
    this.geometry.computeBoundingSphere();
    if (this.geometry.boundingSphere) this.view.drawnSphere.copy(this.geometry.boundingSphere);
    const cx = field.alongLengthMm / 2;
    const cy = (field.acrossFromMm + field.acrossToMm) / 2;
    const size = Math.max(field.alongLengthMm, field.acrossToMm - field.acrossFromMm);
    const { camera, controls } = this.view;
    controls.target.set(cx, cy, 0);
    camera.position.set(cx - 0.55 * size, cy - 0.75 * size, 0.6 * size);
    controls.update();
    this.view.requestRender();
    return g;
  }

  /** Writes xyz or rgb triples into the geometry's attribute `name`, in place when it has their size. */
  private write(name: 'position' | 'color', values: Float32Array): void {
    const attribute = this.geometry.getAttribute(name);
    if (attribute instanceof BufferAttribute && attribute.array.length === values.length) {
      attribute.array.set(values);
      attribute.needsUpdate = true;
    } else this.geometry.setAttribute(name, new BufferAttribute(values, 3));
  }

  /** Frees the view and the surface's GPU resources. */
  override dispose(): void {
    super.dispose();
    this.geometry.dispose();
    this.mesh.material.dispose();
  }
}
