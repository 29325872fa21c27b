/**
 * The design surface and the h pseudo surface (the surface offset by the scallop height h): two
 * translucent patches around the contact, 2.8 R along the feed and 2 L + 2.4 R across it, whatever
 * the surface (surfaceGeometry.ts gives their points; a plane is one more surface there). Heights
 * are drawn through the state's height map. A curved patch (a cylinder, a doubly curved point) is
 * coloured by its height above the tangent plane (curvatureShading.ts: dome, bowl, saddle and the
 * cylinder's fall read at a glance, shaded by its normal so that it reads curved); a plane keeps
 * the material's colour. The two surfaces differ by more than colour (issue 21): the design
 * surface is the more opaque, edged with a solid line; the h pseudo surface is faint, ruled with
 * a grid of its own colour; each is named by a label on it.
 */
import { BufferAttribute, BufferGeometry, DoubleSide, Mesh, MeshBasicMaterial, type Object3D } from 'three';
import { patchIndices, surfacePatch, surfacePoint } from '../../core/output/surfaceGeometry';
import { BandMaterial } from '../bandMaterial';
import { curvatureBandsInto } from '../curvatureShading';
import { FatLine, FatLineMaterial } from '../fatLines';
import { drawHeightsInPlace, drawnHeightMm } from '../heightExaggeration';
import { LabelAnchor, legend } from '../labelLayer';
import { PATCH_CROSS, PATCH_FEED, patchLineIndices } from '../outlineIndices';
import { SCENE_WORDS } from '../sceneWords';
import { COLOURS, Disposer, type Drawable, type DrawState, THIN_LINE_PX } from './parts';

function patchMesh(color: number, opacity: number, shaded: boolean): Mesh {
  const g = new BufferGeometry();
  const vertices = (PATCH_FEED + 1) * (PATCH_CROSS + 1) * 3;
  g.setAttribute('position', new BufferAttribute(new Float32Array(vertices), 3));
  if (shaded) {
    // The band material's: each vertex's shade and its coordinate along the band strip (bandMaterial.ts).
    g.setAttribute('shade', new BufferAttribute(new Float32Array(vertices).fill(1), 3));
    g.setAttribute('band', new BufferAttribute(new Float32Array((vertices / 3) * 2).fill(0.5), 2));
  }
  g.setIndex(new BufferAttribute(patchIndices(PATCH_FEED, PATCH_CROSS), 1));
  const m = new Mesh(
    g,
    shaded
      ? new BandMaterial(opacity)
      : new MeshBasicMaterial({ color, side: DoubleSide, transparent: true, opacity, depthWrite: false }),
  );
  m.frustumCulled = false;
  return m;
}

/** Lines over a patch's own vertices (its edge, and a grid with `every` > 0), written with the patch. */
function patchLines(patch: Mesh, color: number, opacity: number, every: number): FatLine {
  const pairs = patchLineIndices(every);
  const lines = new FatLine(pairs.length, new FatLineMaterial(color, THIN_LINE_PX, { opacity }), 'pairs');
  lines.userData.pairs = pairs;
  patch.add(lines);
  return lines;
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
  const colours = mesh.geometry.getAttribute('shade') as BufferAttribute | undefined;
  const uv = mesh.geometry.getAttribute('band') as BufferAttribute | undefined;
  if (colours !== undefined && uv !== undefined) {
    curvatureBandsInto(uv.array, colours.array, points, PATCH_FEED + 1, PATCH_CROSS + 1, 0);
    colours.needsUpdate = true;
    uv.needsUpdate = true;
  }
  for (const child of mesh.children)
    if (child instanceof FatLine) child.finishPairs(points, child.userData.pairs as Uint32Array);
  // Kept for three.js's back-to-front sorting of the translucent objects.
  mesh.geometry.computeBoundingSphere();
}

/** The h pseudo surface's grid: a line every this many rows and columns of its patch. */
const H_GRID_EVERY = 8;

export class DesignSurfacesDrawable extends Disposer implements Drawable {
  private readonly design = legend(patchMesh(COLOURS.plane, 0.6, false), 'design');
  /** A curved patch: coloured by its shape, more opaque so that the colours read. */
  private readonly curved = legend(patchMesh(0xffffff, 0.85, true), 'design');
  private readonly hSurface = legend(patchMesh(COLOURS.hPlane, 0.14, false), 'hplane');
  private readonly designName = new LabelAnchor(SCENE_WORDS.designPlane, 'label-surface', [1, 1], 3);
  private readonly hName = new LabelAnchor(SCENE_WORDS.hPlane, 'label-hsurface', [1, -1], 3);
  readonly objects: readonly Object3D[] = [this.design, this.curved, this.hSurface];

  constructor() {
    super();
    for (const patch of [this.design, this.curved]) legend(patchLines(patch, COLOURS.centre, 0.7, 0), 'design');
    legend(patchLines(this.hSurface, COLOURS.hPlane, 0.35, H_GRID_EVERY), 'hplane');
    this.design.add(this.designName);
    this.hSurface.add(this.hName);
  }

  update(s: DrawState): void {
    const surface = s.geometry.surface;
    const curved = surface.kind !== 'plane';
    this.design.visible = !curved;
    this.curved.visible = curved;
    fillPatch(curved ? this.curved : this.design, s, 0);
    fillPatch(this.hSurface, s, s.geometry.scallopHeightMm);
    // The names, on each surface beside the passes: the design's before this pass, the h one's after it.
    const R = s.toolRadiusMm;
    const L = s.intervalMm;
    const at = (label: LabelAnchor, crossMm: number, heightMm: number) => {
      const p = surfacePoint(surface, 0.95 * R, crossMm, heightMm);
      label.position.set(p[0], p[1], drawnHeightMm(s.map, p[2]));
    };
    at(this.designName, -0.6 * L, 0);
    at(this.hName, 0.6 * L, s.geometry.scallopHeightMm);
    const words = s.labels.words ?? SCENE_WORDS;
    this.designName.setText(curved ? words.designSurface : words.designPlane);
    this.hName.setText(curved ? words.hSurface : words.hPlane);
    // The curved patch carries the design surface's name while it is shown.
    const parent = curved ? this.curved : this.design;
    if (this.designName.parent !== parent) parent.add(this.designName);
  }
}
