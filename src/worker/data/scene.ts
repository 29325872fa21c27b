/**
 * The 3D scene's data: the tool in its posture (its mesh), the step-over, and the cusps: on a plane
 * the section through each cusp point and the curves where the torus meets the cusp's height; on a
 * cylinder the cusp points on the offset surface. Mm.
 */

import { MIN_LENGTH_MM, type ToolInput } from '../../core/input/validate';
import { cuspSection, intersectionLoops } from '../../core/output/geometry';
import { surfacePoint } from '../../core/output/surfaceGeometry';
import type { Surface } from '../../core/surfaces/cylinder';
import { placeTool } from '../../core/tool/placement';
import { flankAtHeight } from '../../core/tool/posture';
import { toolMesh } from '../../core/tool/toolMesh';
import {
  type Cusp,
  type CuspGeometry,
  type ExactSummary,
  LOOP_SAMPLES,
  type Loops,
  type SceneGeometry,
  TOOL_RADIAL_SEGMENTS,
} from '../protocol';

/** At most the two closed curves a torus leaves on a plane. */
function asLoops(curves: Float64Array[]): Loops {
  const [a, b] = curves;
  return a === undefined ? [] : b === undefined ? [a] : [a, b];
}

/** The scene's geometry: the tool in its posture, the cusp sections and curves (mm). */
export function sceneGeometry(
  input: ToolInput,
  exact: ExactSummary,
  surface: Surface = { kind: 'plane' },
): SceneGeometry {
  const p = placeTool(input);
  const mesh = toolMesh(input, 0.6 * input.toolRadiusMm, TOOL_RADIAL_SEGMENTS);
  // What the scene draws on any surface: the tool in its posture and the step-over it leaves.
  const common = {
    toolRadiusMm: input.toolRadiusMm,
    cornerRadiusMm: input.cornerRadiusMm,
    pattern: exact.pattern,
    intervalMm: exact.intervalMm,
    scallopHeightMm: exact.cuspHeightMm,
    toolCentre: p.centre,
    toolAxis: p.axis,
    toolPositions: mesh.positions,
    surface,
    machine: null,
  };
  if (surface.kind === 'cylinder') {
    // The torus against the h pseudo plane is the plane's construction: on a cylinder the scene
    // marks the cusps themselves, on the offset cylinder, in the section through the contact.
    const cusp = (c: Cusp) => (c.heightMm < MIN_LENGTH_MM ? null : surfacePoint(surface, 0, c.yMm, c.heightMm));
    return { ...common, right: null, left: null, cuspPoints: { right: cusp(exact.right), left: cusp(exact.left) } };
  }
  const same = exact.right.heightMm === exact.left.heightMm;
  const sections = (['right', 'left'] as const).map((flank) => {
    const h = exact[flank].heightMm;
    return h < MIN_LENGTH_MM ? null : { flank, h, s: cuspSection(p, flank, flankAtHeight(p.shape, flank, h)) };
  });
  const [rs, ls] = sections;
  const cusp = (x: typeof rs, ringAngles: number[]): CuspGeometry | null =>
    x
      ? {
          flank: x.flank,
          heightMm: x.h,
          pHp: x.s.pHp,
          sectionCentre: x.s.sectionCentre,
          sectionNormal: x.s.sectionNormal,
          sectionRadiusMm: x.s.sectionRadiusMm,
          loops: ringAngles.length === 0 ? [] : asLoops(intersectionLoops(p, x.h, ringAngles, LOOP_SAMPLES)),
        }
      : null;
  // Equal heights: one set of curves through both cusps, carried by the right cusp.
  const both = [rs?.s.ringAngleRad, ls?.s.ringAngleRad].filter((t): t is number => t !== undefined);
  const right = cusp(rs ?? null, same ? both : rs ? [rs.s.ringAngleRad] : []);
  const left = cusp(ls ?? null, same && rs ? [] : ls ? [ls.s.ringAngleRad] : []);
  return { ...common, right, left, cuspPoints: null };
}
