/**
 * The tool in its posture (a translucent body) and the neighbouring passes' tools at -L and +L
 * (mirrored for zigzag) drawn lighter, as outlines (the flat end's edge, the top of the corner,
 * the shank's top and four lines along the shank) over a faint body, so that they do not crowd the
 * section circles between them, carried along the surface by the core's rigid motion;
 * for three-axis machining the passes its machine view gives (one: the next pass).
 */
import {
  BufferAttribute,
  BufferGeometry,
  DoubleSide,
  LineBasicMaterial,
  LineSegments,
  Mesh,
  MeshBasicMaterial,
  MeshStandardMaterial,
  type Object3D,
} from 'three';
import { passMatrix } from '../../core/output/surfaceGeometry';
import { toolMeshIndices } from '../../core/tool/toolMesh';
import { TOOL_RADIAL_SEGMENTS } from '../../worker/protocol';
import { framed } from '../framePoints';
import { drawHeightsInPlace } from '../heightExaggeration';
import { legend } from '../labelLayer';
import { toolOutlineIndices } from '../outlineIndices';
import { COLOURS, type Drawable, type DrawState, disposeObjects } from './parts';

export class ToolDrawable implements Drawable {
  readonly objects: readonly Object3D[];
  /** One body, shared by the tool and its ghosts. */
  private readonly geometry = new BufferGeometry();
  /** The neighbouring passes, at -L and +L. */
  private readonly neighbours: readonly [Mesh, Mesh];
  /** Their outline: lines over the same vertices as the body. */
  private readonly outline = new BufferGeometry();

  constructor() {
    this.geometry.setAttribute('position', new BufferAttribute(new Float32Array(0), 3));
    this.geometry.setIndex(new BufferAttribute(toolMeshIndices(TOOL_RADIAL_SEGMENTS), 1));
    const tool = new Mesh(
      this.geometry,
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
    this.outline.setAttribute('position', this.geometry.getAttribute('position'));
    this.outline.setIndex(new BufferAttribute(toolOutlineIndices(TOOL_RADIAL_SEGMENTS), 1));
    const ghost = new MeshBasicMaterial({
      color: COLOURS.ghost,
      transparent: true,
      opacity: 0.06,
      side: DoubleSide,
      depthWrite: false,
    });
    const edge = new LineBasicMaterial({ color: COLOURS.ghost, transparent: true, opacity: 0.55 });
    this.neighbours = [new Mesh(this.geometry, ghost), new Mesh(this.geometry, ghost)];
    for (const m of this.neighbours) m.add(legend(new LineSegments(this.outline, edge), 'tool'));
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
      this.outline.setAttribute('position', attr);
    }
    const positions = attr.array as Float32Array;
    positions.set(source);
    drawHeightsInPlace(s.map, positions, source.length / 3);
    attr.needsUpdate = true;
    this.geometry.computeVertexNormals();
    this.geometry.computeBoundingSphere();
    this.geometry.computeBoundingBox();
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

  dispose(): void {
    disposeObjects(this.objects);
  }
}
