/**
 * The tool in its posture, opaque and shaded, its shank drawn up to the holder (a wider collar
 * across the axis, edged by the holder line), and the neighbouring passes' tools at -L and +L
 * (mirrored for zigzag) drawn lighter, as outlines (the flat end's edge, the top of the corner, the
 * shank's top and four lines along the shank) over a faint body, so that they do not crowd the
 * section circles between them, carried along the surface by the core's rigid motion; for
 * three-axis machining the passes its machine view gives (one: the next pass).
 */
import {
  BufferAttribute,
  BufferGeometry,
  DoubleSide,
  Mesh,
  MeshBasicMaterial,
  MeshStandardMaterial,
  type Object3D,
} from 'three';
import { passMatrix } from '../../core/output/surfaceGeometry';
import { TOOL_PROFILE_POINTS, toolMeshIndices } from '../../core/tool/toolMesh';
import { TOOL_RADIAL_SEGMENTS } from '../../worker/protocol';
import { FatLine, FatLineMaterial } from '../fatLines';
import { framed } from '../framePoints';
import { drawHeightsInPlace } from '../heightExaggeration';
import { legend } from '../labelLayer';
import { toolOutlineIndices } from '../outlineIndices';
import { COLOURS, Disposer, type Drawable, type DrawState, MARK_LINE_PX, THIN_LINE_PX } from './parts';

/** The shank's top (where the holder starts) and the holder's top, above the tool centre O (x R). */
export const SHANK_TOP_R = 1.5;
const HOLDER_TOP_R = 1.75;
/** The holder's radius (x R). */
const HOLDER_RADIUS_R = 1.2;
/** The share of its own colour the tool gives off: its side away from the light still stands out of a dark background. */
const SELF_LIGHT = 0.35;
/** Segments around the holder. */
const HOLDER_SEGMENTS = 48;

/** Triangles of a closed band: rows 0 (bottom centre), 1 (bottom ring), 2 (top ring), 3 (top centre). */
function holderIndices(): Uint32Array {
  const out: number[] = [];
  const at = (r: number, j: number) => r * (HOLDER_SEGMENTS + 1) + j;
  for (let r = 0; r < 3; r++)
    for (let j = 0; j < HOLDER_SEGMENTS; j++)
      out.push(at(r, j), at(r, j + 1), at(r + 1, j), at(r, j + 1), at(r + 1, j + 1), at(r + 1, j));
  return Uint32Array.from(out);
}

export class ToolDrawable extends Disposer implements Drawable {
  readonly objects: readonly Object3D[];
  /** One body, shared by the tool and its ghosts. */
  private readonly geometry = new BufferGeometry();
  /** The neighbouring passes, at -L and +L. */
  private readonly neighbours: readonly [Mesh, Mesh];
  /** Their outline (segments over the body's vertices), one line shared by both. */
  private readonly outline: FatLine;
  private readonly outlinePairs = toolOutlineIndices(TOOL_RADIAL_SEGMENTS);
  /** The holder: a collar above the shank, and its edges (the holder line at its foot). */
  private readonly holder = new BufferGeometry();
  private readonly holderEdges = new FatLine(
    4 * HOLDER_SEGMENTS,
    new FatLineMaterial(COLOURS.holder, MARK_LINE_PX),
    'pairs',
  );

  /** The tool and the holder: the camera is fitted to their boxes about the tool axis (framePoints.ts). */
  private readonly framedBodies: readonly Object3D[];

  /** The tool's and the holder's materials (lit, and a share of their own colour given off). */
  private readonly bodies: readonly MeshStandardMaterial[];

  constructor() {
    super();
    this.geometry.setAttribute('position', new BufferAttribute(new Float32Array(0), 3));
    this.geometry.setIndex(new BufferAttribute(toolMeshIndices(TOOL_RADIAL_SEGMENTS), 1));
    const tool = new Mesh(
      this.geometry,
      new MeshStandardMaterial({ color: COLOURS.tool, metalness: 0.1, roughness: 0.7, side: DoubleSide }),
    );
    this.holder.setAttribute('position', new BufferAttribute(new Float32Array(4 * (HOLDER_SEGMENTS + 1) * 3), 3));
    this.holder.setIndex(new BufferAttribute(holderIndices(), 1));
    const holder = framed(
      legend(
        new Mesh(
          this.holder,
          new MeshStandardMaterial({ color: COLOURS.holder, metalness: 0.1, roughness: 0.7, side: DoubleSide }),
        ),
        'tool',
      ),
      'box',
    );
    holder.add(legend(this.holderEdges, 'tool'));
    tool.add(holder);
    this.bodies = [tool.material, holder.material as MeshStandardMaterial];
    this.framedBodies = [tool, holder];
    this.matchTheme();
    const ghost = new MeshBasicMaterial({
      color: COLOURS.ghost,
      transparent: true,
      opacity: 0.08,
      side: DoubleSide,
      depthWrite: false,
    });
    this.outline = new FatLine(this.outlinePairs.length, new FatLineMaterial(COLOURS.ghost, THIN_LINE_PX), 'pairs');
    this.neighbours = [new Mesh(this.geometry, ghost), new Mesh(this.geometry, ghost)];
    // The outline's mesh is shared by both neighbours: each draws it in its own placement.
    const outlineCopy = new Mesh(this.outline.geometry, this.outline.material);
    outlineCopy.frustumCulled = false;
    this.neighbours[0].add(legend(this.outline, 'tool'));
    this.neighbours[1].add(legend(outlineCopy, 'tool'));
    // Their placement is a rigid motion from the core (passMatrix), set as the matrix itself.
    for (const m of this.neighbours) m.matrixAutoUpdate = false;
    this.objects = [framed(legend(tool, 'tool'), 'box'), ...this.neighbours.map((m) => legend(m, 'tool'))];
  }

  update(s: DrawState): void {
    const g = s.geometry;
    const source = g.toolPositions;
    let attr = this.geometry.getAttribute('position') as BufferAttribute;
    if (attr.array.length !== source.length) {
      // A new size (a new mesh resolution): the one allocation, replacing the buffer.
      attr = new BufferAttribute(new Float32Array(source.length), 3);
      this.geometry.setAttribute('position', attr);
    }
    const positions = attr.array as Float32Array;
    positions.set(source);
    const R = s.toolRadiusMm;
    const [ox, oy, oz] = g.toolCentre;
    const [ax, ay, az] = g.toolAxis;
    // The shank up to the holder: the last ring of the profile moved along the axis.
    const ring = TOOL_RADIAL_SEGMENTS + 1;
    for (let v = (TOOL_PROFILE_POINTS - 1) * ring; v < TOOL_PROFILE_POINTS * ring && 3 * v < positions.length; v++) {
      const k = 3 * v;
      const along =
        SHANK_TOP_R * R -
        ((positions[k] as number) - ox) * ax -
        ((positions[k + 1] as number) - oy) * ay -
        ((positions[k + 2] as number) - oz) * az;
      positions[k] = (positions[k] as number) + along * ax;
      positions[k + 1] = (positions[k + 1] as number) + along * ay;
      positions[k + 2] = (positions[k + 2] as number) + along * az;
    }
    drawHeightsInPlace(s.map, positions, source.length / 3);
    attr.needsUpdate = true;
    this.geometry.computeVertexNormals();
    this.geometry.computeBoundingSphere();
    this.geometry.computeBoundingBox();
    this.outline.finishPairs(positions, this.outlinePairs);
    this.fillHolder(s);
    // Boxes square to the tool axis: tight around the tool in any posture (three-axis: turned upright).
    for (const body of this.framedBodies) body.userData.boxAxis = g.toolAxis;
    // The neighbours: carried along the surface by L (turned about a cylinder's axis along the
    // feed, about m on a doubly curved patch); in the machine frame, the passes it gives.
    const given = g.machine?.passMatrices;
    this.neighbours.forEach((m, i) => {
      const motion =
        given === undefined
          ? passMatrix(g.surface, i === 0 ? -s.intervalMm : s.intervalMm, g.pattern === 'zigzag')
          : given[i];
      m.visible = motion !== undefined;
      if (motion === undefined) return;
      m.matrix.fromArray(motion as number[]);
      m.matrixWorldNeedsUpdate = true;
    });
  }

  /** After the theme's colours are taken: each body gives off a share of its (new) colour. */
  matchTheme(): void {
    for (const m of this.bodies) m.emissive.copy(m.color).multiplyScalar(SELF_LIGHT);
  }

  /** The holder's collar about the tool axis, from the shank's top up, and its edge rings. */
  private fillHolder(s: DrawState): void {
    const g = s.geometry;
    const R = s.toolRadiusMm;
    const [ox, oy, oz] = g.toolCentre;
    const [ax, ay, az] = g.toolAxis;
    // Two unit vectors across the axis.
    const k = Math.abs(ax) < 0.9 ? 0 : 1;
    let ux = k === 0 ? 0 : -az;
    let uy = k === 0 ? az : 0;
    let uz = k === 0 ? -ay : ax;
    const n = Math.hypot(ux, uy, uz) || 1;
    ux /= n;
    uy /= n;
    uz /= n;
    const vx = ay * uz - az * uy;
    const vy = az * ux - ax * uz;
    const vz = ax * uy - ay * ux;
    const attr = this.holder.getAttribute('position') as BufferAttribute;
    const p = attr.array as Float32Array;
    const edges = this.holderEdges.points;
    let w = 0;
    let e = 0;
    for (let r = 0; r < 4; r++) {
      const radius = r === 0 || r === 3 ? 0 : HOLDER_RADIUS_R * R;
      const along = (r < 2 ? SHANK_TOP_R : HOLDER_TOP_R) * R;
      for (let j = 0; j <= HOLDER_SEGMENTS; j++) {
        const t = (2 * Math.PI * j) / HOLDER_SEGMENTS;
        const c = radius * Math.cos(t);
        const sn = radius * Math.sin(t);
        p[w++] = ox + along * ax + c * ux + sn * vx;
        p[w++] = oy + along * ay + c * uy + sn * vy;
        p[w++] = oz + along * az + c * uz + sn * vz;
      }
    }
    drawHeightsInPlace(s.map, p, attr.count);
    // The edges: the holder line (the collar's foot, row 1) and its top (row 2), segment by segment.
    for (let r = 1; r <= 2; r++)
      for (let j = 0; j < HOLDER_SEGMENTS; j++)
        for (let q = j; q <= j + 1; q++) {
          const i = 3 * (r * (HOLDER_SEGMENTS + 1) + q);
          edges[e++] = p[i] as number;
          edges[e++] = p[i + 1] as number;
          edges[e++] = p[i + 2] as number;
        }
    this.holderEdges.finish(e / 3);
    attr.needsUpdate = true;
    this.holder.computeVertexNormals();
    // The camera is fitted to its box about the tool axis (framePoints.ts), from these points.
    this.holder.computeBoundingSphere();
    this.holder.computeBoundingBox();
  }
}
