/**
 * The design surface and the h pseudo surface (the surface offset by the scallop height h): two
 * translucent patches around the contact, 2.8 R along the feed and 2 L + 2.4 R across it, whatever
 * the surface (surfaceGeometry.ts gives their points; a plane is one more surface there). Heights
 * are drawn through the state's height map. A doubly curved patch is coloured by its height above
 * the tangent plane (curvatureShading.ts: dome, bowl and saddle read at a glance); a plane and a
 * cylinder keep the material's colour.
 */
import { BufferAttribute, BufferGeometry, DoubleSide, Mesh, MeshBasicMaterial, type Object3D } from 'three';
import { patchIndices, surfacePatch } from '../../core/output/surfaceGeometry';
import { curvatureColoursInto } from '../curvatureShading';
import { drawHeightsInPlace } from '../heightExaggeration';
import { legend } from '../labelLayer';
import { COLOURS, type Drawable, type DrawState, disposeObjects } from './parts';

/** The patches' grid: segments along the feed and across it. */
const PATCH_FEED = 48;
const PATCH_CROSS = 64;

/** A curved patch's material colour: white (not themed), so that its vertex colours show as they are. */
const CURVED_BASE = 0xffffff;

function patchMesh(color: number, opacity: number, shaded: boolean): Mesh {
  const g = new BufferGeometry();
  const vertices = (PATCH_FEED + 1) * (PATCH_CROSS + 1) * 3;
  g.setAttribute('position', new BufferAttribute(new Float32Array(vertices), 3));
  if (shaded) g.setAttribute('color', new BufferAttribute(new Float32Array(vertices).fill(1), 3));
  g.setIndex(new BufferAttribute(patchIndices(PATCH_FEED, PATCH_CROSS), 1));
  const m = new Mesh(
    g,
    new MeshBasicMaterial({
      color,
      side: DoubleSide,
      transparent: true,
      opacity,
      depthWrite: false,
      vertexColors: shaded,
    }),
  );
  m.frustumCulled = false;
  return m;
}

/** Writes a patch of the surface offset by `heightMm` into `mesh`'s buffer, heights drawn through the map. */
function fillPatch(mesh: Mesh, s: DrawState, heightMm: number): void {
  const attr = mesh.geometry.getAttribute('position') as BufferAttribute;
  const points = attr.array as Float32Array;
  const feedHalfMm = (2.8 * s.toolRadiusMm) / 2;
  const crossHalfMm = (2 * s.intervalMm + 2.4 * s.toolRadiusMm) / 2;
  surfacePatch(s.geometry.surface, heightMm, feedHalfMm, crossHalfMm, PATCH_FEED, PATCH_CROSS, points);
  drawHeightsInPlace(s.map, points, attr.count);
  attr.needsUpdate = true;
  const colours = mesh.geometry.getAttribute('color') as BufferAttribute | undefined;
  if (colours !== undefined) {
    curvatureColoursInto(colours.array, points, PATCH_FEED + 1, PATCH_CROSS + 1, 0);
    colours.needsUpdate = true;
  }
  // Kept for three.js's back-to-front sorting of the translucent objects.
  mesh.geometry.computeBoundingSphere();
}

export class DesignSurfacesDrawable implements Drawable {
  private readonly design = legend(patchMesh(COLOURS.plane, 0.55, false), 'design');
  /** A doubly curved patch: coloured by its shape, more opaque so that the colours read. */
  private readonly curved = legend(patchMesh(CURVED_BASE, 0.85, true), 'design');
  private readonly hSurface = legend(patchMesh(COLOURS.hPlane, 0.18, false), 'hplane');
  readonly objects: readonly Object3D[] = [this.design, this.curved, this.hSurface];

  update(s: DrawState): void {
    const kind = s.geometry.surface.kind;
    const curved = kind === 'torus' || kind === 'revolution';
    this.design.visible = !curved;
    this.curved.visible = curved;
    fillPatch(curved ? this.curved : this.design, s, 0);
    fillPatch(this.hSurface, s, s.geometry.scallopHeightMm);
  }

  dispose(): void {
    disposeObjects(this.objects);
  }
}
