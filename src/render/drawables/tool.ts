/**
 * The tool in its posture (a translucent body) and the neighbouring passes' tools at -L and +L
 * (wireframe ghosts, mirrored for zigzag), carried along the surface by the core's rigid motion;
 * for three-axis machining the passes its machine view gives (one: the next pass).
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
import { toolMeshIndices } from '../../core/tool/toolMesh';
import { TOOL_RADIAL_SEGMENTS } from '../../worker/protocol';
import { drawHeightsInPlace } from '../heightExaggeration';
import { legend } from '../labelLayer';
import { COLOURS, type Drawable, type DrawState, disposeObjects } from './parts';

export class ToolDrawable implements Drawable {
  readonly objects: readonly Object3D[];
  /** One body, shared by the tool and its ghosts. */
  private readonly geometry = new BufferGeometry();
  /** The neighbouring passes, at -L and +L. */
  private readonly neighbours: readonly [Mesh, Mesh];

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
    const ghost = new MeshBasicMaterial({ color: COLOURS.ghost, wireframe: true, transparent: true, opacity: 0.12 });
    this.neighbours = [new Mesh(this.geometry, ghost), new Mesh(this.geometry, ghost)];
    // Their placement is a rigid motion from the core (passMatrix), set as the matrix itself.
    for (const m of this.neighbours) m.matrixAutoUpdate = false;
    this.objects = [legend(tool, 'tool'), ...this.neighbours.map((m) => legend(m, 'tool'))];
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
    drawHeightsInPlace(s.map, positions, source.length / 3);
    attr.needsUpdate = true;
    this.geometry.computeVertexNormals();
    this.geometry.computeBoundingSphere();
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
