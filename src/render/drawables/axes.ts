/** The axes X (feed), Y and Z: unit arrows built once, scaled with the tool (1.6 R). */
import { Group, type Object3D, Vector3 } from 'three';
import { FatLine, FatLineMaterial } from '../fatLines';
import { LabelAnchor, legend } from '../labelLayer';
import { SCENE_WORDS } from '../sceneWords';
import { COLOURS, Disposer, type Drawable, type DrawState, MARK_LINE_PX } from './parts';

/** Two unit vectors perpendicular to the unit vector `d` and to each other. */
function perpendiculars(d: Vector3): [Vector3, Vector3] {
  const u = new Vector3(Math.abs(d.x) < 0.9 ? 1 : 0, Math.abs(d.x) < 0.9 ? 0 : 1, 0).cross(d).normalize();
  return [u, d.clone().cross(u).normalize()];
}

export class AxesDrawable extends Disposer implements Drawable {
  private readonly axes = legend(new Group(), 'axes');
  readonly objects: readonly Object3D[] = [this.axes];
  /** The axes' labels, X first (its word for the feed in the reader's language). */
  private readonly tags: LabelAnchor[] = [];

  constructor() {
    super();
    const specs: Array<[Vector3, number, string]> = [
      [new Vector3(1, 0, 0), COLOURS.x, SCENE_WORDS.xAxis],
      [new Vector3(0, 1, 0), COLOURS.y, 'Y'],
      [new Vector3(0, 0, 1), COLOURS.z, 'Z'],
    ];
    for (const [dir, color, text] of specs) {
      // A shaft and a head of two crossed strokes, 0.12 long (drawn lines: no cone geometry).
      const [u, v] = perpendiculars(dir);
      const at = (k: number, w: Vector3 | null, s: number) => {
        const p = dir.clone().multiplyScalar(k);
        return w === null ? p : p.addScaledVector(w, s);
      };
      const tip = at(1, null, 0);
      const strokes = [at(0, null, 0), tip, at(0.88, u, 0.045), tip, at(0.88, u, -0.045), tip];
      strokes.push(at(0.88, v, 0.045), tip, at(0.88, v, -0.045), tip);
      const arrow = new FatLine(strokes.length, new FatLineMaterial(color, MARK_LINE_PX), 'pairs');
      for (const [i, p] of strokes.entries()) p.toArray(arrow.points, 3 * i);
      arrow.finish(strokes.length);
      const tag = new LabelAnchor(text, 'label-axis', [0, 0], 2);
      tag.position.copy(dir).multiplyScalar(1.08);
      arrow.add(tag);
      this.axes.add(arrow);
      this.tags.push(tag);
    }
  }

  update(s: DrawState): void {
    this.axes.scale.setScalar(1.6 * s.toolRadiusMm);
    this.tags[0]?.setText((s.labels.words ?? SCENE_WORDS).xAxis);
  }
}
