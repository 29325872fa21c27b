/**
 * The step-through of the paper's procedure (its Figure 1), one frame at a time: the section
 * circle the frame is at, the candidate points on it, and the point found (with what it is), or
 * nothing while no frame is shown.
 */
import { BufferAttribute, BufferGeometry, type Object3D, Points, PointsMaterial, SphereGeometry } from 'three';
import { circleInto } from '../../core/output/sceneMarks';
import type { TraceFrame } from '../../worker/protocol';
import { framed } from '../framePoints';
import { drawnHeightMm, type HeightMap } from '../heightExaggeration';
import { LabelAnchor, legend } from '../labelLayer';
import type { SceneWordTexts } from '../sceneWords';
import { COLOURS, Disposer, finishLine, lineOf, markerOf, positionsOf, SECTION_POINTS } from './parts';

/** The most candidate points a frame shows. */
const CANDIDATE_CAPACITY = 64;

/** How a frame is drawn: the state's height map, the corner radius (the section's) and the tool radius (mm). */
export interface TraceSizes {
  readonly map: HeightMap;
  readonly cornerRadiusMm: number;
  readonly toolRadiusMm: number;
  /** The scene's words (the point's label). */
  readonly words: SceneWordTexts;
}

export class TraceDrawable extends Disposer {
  private readonly section = framed(legend(lineOf(SECTION_POINTS, COLOURS.trace, true), 'trace'), 'points', true);
  private readonly dot = new SphereGeometry(1, 16, 12);
  private readonly marker = framed(markerOf(this.dot, COLOURS.trace, 'trace'), 'origin', true);
  private readonly label = new LabelAnchor('', 'label-trace', [-1, -1], 10);
  private readonly candidates: Points;
  readonly objects: readonly Object3D[];

  constructor() {
    super();
    this.marker.renderOrder = 12;
    this.marker.add(this.label);
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new BufferAttribute(new Float32Array(CANDIDATE_CAPACITY * 3), 3));
    geometry.setDrawRange(0, 0);
    this.candidates = framed(
      legend(
        new Points(
          geometry,
          new PointsMaterial({
            color: COLOURS.trace,
            size: 6,
            sizeAttenuation: false,
            depthTest: false,
            transparent: true,
          }),
        ),
        'trace',
      ),
      'points',
      true,
    );
    this.candidates.frustumCulled = false;
    this.candidates.renderOrder = 12;
    this.objects = [this.section, this.candidates, this.marker];
    this.section.visible = this.candidates.visible = this.marker.visible = false;
  }

  /**
   * Shows one frame, or hides the replay (null).
   * @returns whether anything changed (hiding what is hidden changes nothing)
   */
  show(frame: TraceFrame | null, sizes: TraceSizes): boolean {
    const on = frame !== null;
    if (!on && !this.section.visible) return false;
    this.section.visible = on;
    this.candidates.visible = on;
    this.marker.visible = on && frame.point !== null;
    if (frame === null) return true;
    const map = sizes.map;
    circleInto(
      positionsOf(this.section),
      0,
      frame.sectionCentre,
      frame.sectionNormal,
      sizes.cornerRadiusMm,
      SECTION_POINTS,
    );
    finishLine(this.section, SECTION_POINTS, map);
    const candidates = positionsOf(this.candidates);
    const n = Math.min(frame.candidates.length / 3, CANDIDATE_CAPACITY);
    for (let i = 0; i < 3 * n; i++) candidates[i] = frame.candidates[i] as number;
    finishLine(this.candidates, n, map);
    if (frame.point) {
      const [px, py, pz] = frame.point;
      this.marker.position.set(px, py, drawnHeightMm(map, pz));
      this.marker.scale.setScalar(0.03 * sizes.toolRadiusMm);
      this.label.setText(
        frame.phase === 'converged'
          ? sizes.words.converged
          : frame.phase === 'search'
            ? sizes.words.best
            : sizes.words.single,
      );
    }
    return true;
  }
}
