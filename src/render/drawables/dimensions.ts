/**
 * The dimensions: the step-over L from this pass's path to the next at the start of the drawn
 * passes, L/2 at their end (each along the surface, with extension lines and arrowheads, its label
 * above its middle), and the contact offset y0 from the foot of the tool centre's drop to the
 * contact, across the feed. For three-axis machining, the step as programmed (the machine view's
 * `Lxy` horizontal or `dz` vertical dimension, core machineGeometry.ts).
 */
import type { Object3D } from 'three';
import { dimensionPointCount, surfaceDimensionInto } from '../../core/output/sceneMarks';
import { surfacePoint } from '../../core/output/surfaceGeometry';
import { nearerEndFirst } from '../cameraFit';
import type { FatLine } from '../fatLines';
import { drawnHeightMm } from '../heightExaggeration';
import { LabelAnchor, legend } from '../labelLayer';
import { SCENE_WORDS } from '../sceneWords';
import { COLOURS, Disposer, type Drawable, type DrawState, finishLine, lineOf, positionsOf, writeLine } from './parts';
import { PATH_SEGMENTS } from './paths';

export class DimensionsDrawable extends Disposer implements Drawable {
  private readonly interval = legend(lineOf(dimensionPointCount(PATH_SEGMENTS), COLOURS.dimension), 'dimension');
  private readonly half = legend(lineOf(dimensionPointCount(PATH_SEGMENTS), COLOURS.dimension), 'dimension');
  private readonly offset = legend(lineOf(4, COLOURS.dimension), 'offset');
  /** On its dimension line, as a drawing's dimension reads (the answer: placed before the other labels but the step-through's). */
  private readonly intervalLabel = new LabelAnchor('L', 'label-dim', [0, 0], 9.5);
  private readonly halfLabel = new LabelAnchor('L/2', 'label-dim label-half', [0, -1], 6);
  private readonly offsetLabel = new LabelAnchor('y0', 'label-offset', [0, 1], 5);
  /** Three-axis: the programmed step (up to 16 points: two extension lines, a line, two arrowheads). */
  private readonly step = legend(lineOf(16, COLOURS.dimension), 'dimension');
  private readonly stepLabel = new LabelAnchor('', 'label-dim label-step', [1, 0], 6);
  readonly objects: readonly Object3D[] = [this.interval, this.half, this.offset, this.step];

  constructor() {
    super();
    this.step.add(this.stepLabel);
    this.interval.add(this.intervalLabel);
    this.half.add(this.halfLabel);
    this.offset.add(this.offsetLabel);
  }

  update(s: DrawState): void {
    const g = s.geometry;
    const surface = g.surface;
    const R = s.toolRadiusMm;
    const L = s.intervalMm;
    const tick = 0.08 * R;
    const arrowMm = Math.min(0.07 * R, 0.25 * L);
    const dimension = (line: FatLine, xMm: number, lengthMm: number) =>
      finishLine(
        line,
        surfaceDimensionInto(positionsOf(line), 0, surface, xMm, lengthMm, tick, arrowMm, PATH_SEGMENTS),
      );
    // L between this pass's path and the next at the end of the passes nearer the isometric
    // camera (in front of the tool, clear of it); L/2 at the other end.
    const [nearMm, farMm] = nearerEndFirst(s.fromMm, s.toMm, g.machine?.frameMatrix);
    dimension(this.interval, nearMm, L);
    dimension(this.half, farMm, L / 2);
    this.intervalLabel.position.fromArray(surfacePoint(surface, nearMm, L / 2, 0));
    this.halfLabel.position.fromArray(surfacePoint(surface, farMm, L / 4, tick));
    // Measured along an arc (around a circle across the feed): said after both.
    const arc = s.labels.arc === true ? (s.labels.words ?? SCENE_WORDS).arc : '';
    this.intervalLabel.setText(s.labels.interval + arc);
    this.halfLabel.setText(s.labels.halfInterval + arc);
    // y0: from the foot of O's drop to the contact, across the feed.
    const [ox, oy, oz] = g.toolCentre;
    this.offset.visible = s.labels.contactOffset !== null;
    const p = positionsOf(this.offset);
    p.set([ox, oy, drawnHeightMm(s.map, oz), ox, oy, 0, ox, oy, 0, ox, 0, 0]);
    finishLine(this.offset, 4);
    this.offsetLabel.position.set(ox, oy / 2, -tick);
    this.offsetLabel.setText(s.labels.contactOffset ?? '');
    const machine = g.machine;
    this.step.visible = machine !== null;
    if (machine !== null) {
      writeLine(this.step, machine.step.points, machine.step.points.length / 3);
      this.stepLabel.position.fromArray(machine.step.labelAt);
      this.stepLabel.setText(s.labels.programmedStep ?? '');
    }
  }
}
