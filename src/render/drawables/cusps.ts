/**
 * The cusps. On a plane, each cusp's section circle, the torus / plane curves at its height (the
 * paper's loops), its point P_hp and the scallop's ridge along the feed through it; on a cylinder,
 * the cusp points on the h pseudo surface (where the neighbouring passes' profiles meet).
 */
import { type Mesh, type Object3D, SphereGeometry } from 'three';
import { circleInto } from '../../core/output/sceneMarks';
import { type CuspGeometry, LOOP_MAX_POINTS } from '../../worker/protocol';
import { framed } from '../framePoints';
import { drawnHeightMm } from '../heightExaggeration';
import { LabelAnchor, legend } from '../labelLayer';
import { SCENE_WORDS } from '../sceneWords';
import {
  COLOURS,
  Disposer,
  type Drawable,
  type DrawState,
  finishLine,
  lineOf,
  markerOf,
  positionsOf,
  SECTION_POINTS,
  writeLine,
} from './parts';

/** One cusp's drawing: its section circle, its P_hp and the torus / plane curves at its height. */
class CuspMarks {
  readonly section = framed(legend(lineOf(SECTION_POINTS, COLOURS.section, true), 'section'), 'points');
  readonly loops = [lineOf(LOOP_MAX_POINTS, COLOURS.loop, true), lineOf(LOOP_MAX_POINTS, COLOURS.loop, true)];
  /** The cusp along the feed (the scallop's ridge), at its height. */
  readonly ridge = legend(lineOf(2, COLOURS.ridge), 'ridge');
  readonly point: Mesh;

  constructor(dot: SphereGeometry, text: string, className: string, side: readonly [number, number]) {
    this.point = framed(markerOf(dot, COLOURS.pHp, 'php'), 'origin');
    this.point.add(new LabelAnchor(text, className, side, 8));
    for (const l of this.loops) legend(l, 'loop');
  }

  objects(): Object3D[] {
    return [this.section, ...this.loops, this.point, this.ridge];
  }

  /** Shows a cusp (or hides it: null), heights drawn through the state's map; the ridge along the drawn passes. */
  show(c: CuspGeometry | null, s: DrawState): void {
    const map = s.map;
    this.section.visible = this.point.visible = this.ridge.visible = c !== null;
    this.loops.forEach((line, i) => {
      const loop = c?.loops[i];
      line.visible = loop !== undefined && loop.length > 0;
      if (loop === undefined) finishLine(line, 0);
      else writeLine(line, loop, loop.length / 3, map);
    });
    if (c === null) return;
    circleInto(positionsOf(this.section), 0, c.sectionCentre, c.sectionNormal, c.sectionRadiusMm, SECTION_POINTS);
    finishLine(this.section, SECTION_POINTS, map);
    this.point.scale.setScalar(s.dotRadiusMm);
    const z = drawnHeightMm(map, c.pHp[2]);
    this.point.position.set(c.pHp[0], c.pHp[1], z);
    const ridge = positionsOf(this.ridge);
    ridge[0] = s.fromMm;
    ridge[1] = c.pHp[1];
    ridge[2] = z;
    ridge[3] = s.toMm;
    ridge[4] = c.pHp[1];
    ridge[5] = z;
    finishLine(this.ridge, 2);
  }
}

export class CuspsDrawable extends Disposer implements Drawable {
  readonly objects: readonly Object3D[];
  private readonly dot = new SphereGeometry(1, 16, 12);
  private readonly right = new CuspMarks(this.dot, 'P_hp R', 'label-php', [1, -0.8]);
  private readonly left = new CuspMarks(this.dot, 'P_hp L', 'label-php label-php-left', [-1, -0.8]);
  /** On a cylinder: the cusp points on the h pseudo surface, right and left. */
  private readonly points: readonly [Mesh, Mesh];
  /** Their labels (the word "cusp" in the reader's language). */
  private readonly pointLabels: LabelAnchor[] = [];

  constructor() {
    super();
    const point = (text: string, className: string, side: readonly [number, number]) => {
      const m = framed(markerOf(this.dot, COLOURS.pHp, 'cusp'), 'origin');
      const label = new LabelAnchor(text, className, side, 8);
      this.pointLabels.push(label);
      m.add(label);
      m.visible = false;
      return m;
    };
    this.points = [
      point(`${SCENE_WORDS.cusp} R`, 'label-php', [1, -0.8]),
      point(`${SCENE_WORDS.cusp} L`, 'label-php label-php-left', [-1, -0.8]),
    ];
    this.objects = [...this.points, ...this.right.objects(), ...this.left.objects()];
  }

  update(s: DrawState): void {
    const g = s.geometry;
    const cusp = (s.labels.words ?? SCENE_WORDS).cusp;
    this.pointLabels.forEach((label, i) => {
      label.setText(`${cusp} ${i === 0 ? 'R' : 'L'}`);
    });
    this.right.show(g.right, s);
    this.left.show(g.left, s);
    this.points.forEach((m, i) => {
      const p = g.cuspPoints === null ? null : i === 0 ? g.cuspPoints.right : g.cuspPoints.left;
      m.visible = p !== null;
      if (p === null) return;
      m.position.set(p[0], p[1], p[2]);
      m.scale.setScalar(s.dotRadiusMm);
    });
  }
}
