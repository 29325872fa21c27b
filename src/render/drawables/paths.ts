/**
 * The cutter-contact paths of the three passes, L apart: lines along the feed on the surface (an
 * arc around a cylinder whose axis runs across the feed, the feed circle turned about m on a doubly
 * curved patch, a level circle on a surface of revolution); for three-axis machining the passes its
 * machine view draws.
 */
import type { Object3D } from 'three';
import { surfacePolylineInto } from '../../core/output/surfaceGeometry';
import type { FatLine } from '../fatLines';
import { framed } from '../framePoints';
import { legend } from '../labelLayer';
import { COLOURS, Disposer, type Drawable, type DrawState, finishLine, lineOf, positionsOf } from './parts';

/** Segments of a path along the feed. */
export const PATH_SEGMENTS = 48;

export class PathsDrawable extends Disposer implements Drawable {
  private readonly paths: readonly FatLine[] = [0, 1, 2].map(() =>
    framed(legend(lineOf(PATH_SEGMENTS + 1, COLOURS.path), 'path'), 'points'),
  );
  readonly objects: readonly Object3D[] = this.paths;

  update(s: DrawState): void {
    const surface = s.geometry.surface;
    const offsets = s.geometry.machine?.pathOffsetsMm;
    this.paths.forEach((line, i) => {
      const y = offsets === undefined ? (i - 1) * s.intervalMm : offsets[i];
      line.visible = y !== undefined;
      if (y === undefined) return;
      surfacePolylineInto(positionsOf(line), 0, surface, 0, s.fromMm, y, s.toMm, y, PATH_SEGMENTS);
      finishLine(line, PATH_SEGMENTS + 1);
    });
  }
}
