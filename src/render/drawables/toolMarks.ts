/**
 * The marked points of the tool's posture: the contact CC (P_base) at the origin, the tool centre
 * O, and the tool axis from where it meets the surface (its foot, marked) up the shank.
 */
import { type Object3D, SphereGeometry } from 'three';
import { axisFoot } from '../../core/output/surfaceGeometry';
import { framed } from '../framePoints';
import { drawnHeightMm } from '../heightExaggeration';
import { LabelAnchor, legend } from '../labelLayer';
import { COLOURS, Disposer, type Drawable, type DrawState, finishLine, lineOf, markerOf, positionsOf } from './parts';

export class ToolMarksDrawable extends Disposer implements Drawable {
  readonly objects: readonly Object3D[];
  /** Framed with the tool: its top, above the holder, stays in the view. */
  private readonly axis = framed(legend(lineOf(2, COLOURS.axis), 'axis'), 'points');
  private readonly dot = new SphereGeometry(1, 16, 12);
  private readonly contact = markerOf(this.dot, COLOURS.contact, 'contact');
  private readonly centre = markerOf(this.dot, COLOURS.centre, 'centre');
  private readonly foot = markerOf(this.dot, COLOURS.axis, 'axis');

  constructor() {
    super();
    this.contact.add(new LabelAnchor('CC (P_base)', 'label-pbase', [0, 1], 9));
    this.centre.add(new LabelAnchor('O', 'label-centre', [1, -0.6], 7));
    this.objects = [this.axis, this.contact, this.centre, this.foot];
  }

  /** The axis line, then the dots; each the state's dot size (the foot smaller, O a little). */
  update(s: DrawState): void {
    const g = s.geometry;
    const map = s.map;
    const [ox, oy, oz] = g.toolCentre;
    const [ax, ay, az] = g.toolAxis;
    const foot = axisFoot(g.surface, g.toolCentre, g.toolAxis);
    const up = 2.2 * s.toolRadiusMm;
    const line = positionsOf(this.axis);
    line[0] = foot[0];
    line[1] = foot[1];
    line[2] = foot[2];
    line[3] = ox + up * ax;
    line[4] = oy + up * ay;
    line[5] = oz + up * az;
    finishLine(this.axis, 2, map);
    this.foot.scale.setScalar(0.6 * s.dotRadiusMm);
    this.foot.position.set(foot[0], foot[1], drawnHeightMm(map, foot[2]));
    this.centre.scale.setScalar(0.8 * s.dotRadiusMm);
    this.centre.position.set(ox, oy, drawnHeightMm(map, oz));
    this.contact.scale.setScalar(s.dotRadiusMm);
    this.contact.position.set(0, 0, 0);
  }
}
