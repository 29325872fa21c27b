/**
 * A three-axis answer (issue 20: the tool upright, the surface sloped) as a table for the terminal
 * or as a JSON object. The step as the CAM system programs it comes first (Lxy for raster passes,
 * dz for waterline), then L along the surface and the equivalent lead and tilt at the CC point.
 * Pure; lengths mm, angles degrees.
 */

import type { LengthUnit } from '../core/input/units';
import type { SlopeSweep, SlopeSweepInput } from '../core/threeAxis/slopeSweep';
import type { ThreeAxisAnswer, ThreeAxisProblem, ThreeAxisQuantity } from '../core/threeAxis/validate';
import type { JsonObject, JsonValue } from './report';
import { KEY_VALUE, toolKind } from './reportExtras';
import { type Column, echo, type Lengths, length, lengthsIn, renderTable } from './table';

/** An angle (degrees) for the table: 7 significant digits, never -0. */
function angle(deg: number): string {
  return length(deg === 0 ? 0 : deg);
}

/** The case in words: the tool, upright; the surface and the passes. */
function caseLine(p: ThreeAxisProblem, L: Lengths): string {
  const c = p.case;
  const tool = `${toolKind(c.toolRadiusMm, c.cornerRadiusMm)} R = ${L.echo(c.toolRadiusMm)} ${L.u}, Rcr = ${L.echo(c.cornerRadiusMm)} ${L.u}, upright (three-axis)`;
  if (p.surface === 'plane') {
    const passes =
      p.case.passes === 'raster'
        ? `raster passes at psi = ${echo(p.case.rasterAngleDeg)} deg to the fall line`
        : 'waterline passes (along the contour)';
    return `${tool}; plane of slope alpha = ${echo(c.slopeDeg)} deg; ${passes}`;
  }
  const radius = (r: number | null) => (r === null ? 'straight' : `${L.echo(r)} ${L.u}`);
  return (
    `${tool}; surface of revolution about a vertical axis at slope alpha = ${echo(c.slopeDeg)} deg, ` +
    `feed radius Rf ${radius(p.case.feedRadiusMm)}, cross radius Rc ${radius(p.case.crossRadiusMm)}; waterline passes`
  );
}

/** The quantity given, as the table's second line. */
const GIVEN: Readonly<Record<ThreeAxisQuantity, string>> = {
  h: 'Scallop height h',
  interval: 'Step-over along the surface L',
  horizontalStep: 'Horizontal step Lxy',
  stepDown: 'Step-down dz',
};

/** The three-axis answer as a table: the programmed step first, then L, lead and tilt, and h. */
export function threeAxisTable(p: ThreeAxisProblem, a: ThreeAxisAnswer, unit: LengthUnit = 'mm'): string {
  const L = lengthsIn(unit);
  const facts: string[][] = [];
  const lxy = [
    'Lxy',
    L.length(a.horizontalStepMm),
    L.u,
    p.surface === 'plane'
      ? 'horizontal step: between the vertical planes of adjacent passes'
      : 'horizontal step: between the tool axes of adjacent levels',
  ];
  if (a.passes === 'raster') facts.push([...lxy.slice(0, 3), `${lxy[3]} (as programmed)`]);
  else
    facts.push([
      'dz',
      L.length(a.stepDownMm ?? 0),
      L.u,
      'step-down between levels, tool tip to tool tip (as programmed)',
    ]);
  facts.push(['L', L.length(a.intervalMm), L.u, 'step-over along the surface: between adjacent cutter-contact paths']);
  if (a.passes === 'waterline') facts.push(lxy);
  facts.push(
    ['lead', angle(a.leadDeg), 'deg', 'equivalent lead rho at the CC point'],
    ['tilt', angle(a.tiltDeg), 'deg', 'equivalent tilt beta at the CC point (+: the shank leans uphill)'],
    ['h', L.length(a.cuspHeightMm), L.u, 'cusp height, along the surface normal'],
  );
  const out = [
    caseLine(p, L),
    `${GIVEN[p.quantity]} = ${L.echo(p.mm)} ${L.u}`,
    '',
    'Three-axis, exact:',
    ...renderTable(KEY_VALUE, facts, false).map((l) => `  ${l}`),
  ];
  if (a.noScallop) {
    out.push('  A flat end on a flat floor leaves no scallop at any step-over up to its diameter: L = 2R for any h.');
  }
  return out.join('\n');
}

/** The three-axis answer as JSON: the input, `exact` (L, Lxy or dz, the cusp) and the posture at the CC point. */
export function threeAxisJson(p: ThreeAxisProblem, a: ThreeAxisAnswer): JsonObject {
  const c = p.case;
  const input: JsonObject = { R: c.toolRadiusMm, Rcr: c.cornerRadiusMm, slope: c.slopeDeg, passes: a.passes };
  if (p.surface === 'plane' && p.case.passes === 'raster') input.rasterAngle = p.case.rasterAngleDeg;
  if (p.surface === 'revolution') {
    if (p.case.feedRadiusMm !== null) input.feedRadius = p.case.feedRadiusMm;
    if (p.case.crossRadiusMm !== null) input.crossRadius = p.case.crossRadiusMm;
  }
  input[p.quantity] = p.mm;
  const exact: JsonObject = { interval: a.intervalMm };
  if (a.passes === 'raster') exact.horizontalStep = a.horizontalStepMm;
  else exact.stepDown = a.stepDownMm ?? 0;
  exact.scallopHeight = a.cuspHeightMm;
  exact.noScallop = a.noScallop;
  return {
    unit: 'mm',
    machine: '3axis',
    surface: p.surface,
    input,
    exact,
    posture: { lead: a.leadDeg, tilt: a.tiltDeg === 0 ? 0 : a.tiltDeg },
  };
}

/** Whether the sweep's constant step was typed or is the flat floor's. */
export interface SweepStep {
  readonly typed: boolean;
}

function sweepCaseLine(i: SlopeSweepInput, L: Lengths): string {
  const kind = toolKind(i.toolRadiusMm, i.cornerRadiusMm);
  const tool = `${kind} R = ${L.echo(i.toolRadiusMm)} ${L.u}, Rcr = ${L.echo(i.cornerRadiusMm)} ${L.u}, upright (three-axis)`;
  if (i.passes === 'raster') return `${tool}; raster passes at psi = ${echo(i.rasterAngleDeg)} deg to the fall line`;
  const radius = (r: number | null | undefined) => (r === null || r === undefined ? 'straight' : `${L.echo(r)} ${L.u}`);
  const surface =
    (i.feedRadiusMm ?? null) === null && (i.crossRadiusMm ?? null) === null
      ? 'a plane'
      : `a surface of revolution, Rf ${radius(i.feedRadiusMm)}, Rc ${radius(i.crossRadiusMm)} held at every slope`;
  return `${tool}; waterline passes on ${surface}`;
}

/** The slope sweep as a table: for each slope the step for h, L, the posture, the limit and the constant step's cusp. */
export function slopeSweepTable(i: SlopeSweepInput, s: SlopeSweep, step: SweepStep, unit: LengthUnit = 'mm'): string {
  const L = lengthsIn(unit);
  const raster = i.passes === 'raster';
  const name = raster ? 'Lxy' : 'dz';
  const constant = step.typed
    ? `the typed ${raster ? 'horizontal step' : 'step-down'} ${name} = ${L.echo(s.programmedStepMm)} ${L.u}`
    : `the flat floor's step-over for h, ${name} = ${L.length(s.programmedStepMm)} ${L.u}`;
  const columns: Column[] = [
    { header: 'slope [deg]', align: 'right' },
    { header: `${name} for h [${L.u}]`, align: 'right' },
    { header: `L [${L.u}]`, align: 'right' },
    { header: 'lead [deg]', align: 'right' },
    { header: 'tilt [deg]', align: 'right' },
    { header: `h limit [${L.u}]`, align: 'right' },
    { header: `h at ${name} = const [${L.u}]`, align: 'right' },
  ];
  const rows = s.points.map((p) => [
    angle(p.slopeDeg),
    p.stepMm === null ? '-' : L.length(p.stepMm),
    p.intervalMm === null ? '-' : L.length(p.intervalMm),
    angle(p.leadDeg),
    angle(p.tiltDeg),
    Number.isFinite(p.heightLimitMm) ? L.length(p.heightLimitMm) : 'none',
    p.cuspAtProgrammedStepMm !== null ? L.length(p.cuspAtProgrammedStepMm) : (p.programmedStepRefusal ?? '-'),
  ]);
  const largest =
    s.largestSlopeDeg === 90
      ? 'h is valid up to 90 deg (the concave meridian leaves a scallop on the vertical too)'
      : s.largestSlopeDeg >= 90 - 1e-6
        ? 'h is valid up to a vertical wall (90 deg, where the side cuts it flat)'
        : `the largest slope where h is valid: ${angle(s.largestSlopeDeg)} deg`;
  return [
    sweepCaseLine(i, L),
    `Scallop height h = ${L.echo(i.hMm)} ${L.u}; ${largest}`,
    `Constant programmed step: ${constant}`,
    '',
    ...renderTable(columns, rows),
    '',
    `${name} for h: the step that leaves h at that slope (exact); h at ${name} = const: the cusp the constant step really leaves there`,
    '(a code where that step leaves no scallop: a wall, the shank, beyond the surface...); heights along the surface normal.',
  ].join('\n');
}

/** The slope sweep as JSON: the input, the largest valid slope, the constant step and the points (absent values left out). */
export function slopeSweepJson(i: SlopeSweepInput, s: SlopeSweep, step: SweepStep): JsonObject {
  const input: JsonObject = { R: i.toolRadiusMm, Rcr: i.cornerRadiusMm, h: i.hMm, passes: i.passes };
  if (i.passes === 'raster') input.rasterAngle = i.rasterAngleDeg;
  if (i.feedRadiusMm !== undefined && i.feedRadiusMm !== null) input.feedRadius = i.feedRadiusMm;
  if (i.crossRadiusMm !== undefined && i.crossRadiusMm !== null) input.crossRadius = i.crossRadiusMm;
  if (step.typed) input[i.passes === 'raster' ? 'horizontalStep' : 'stepDown'] = s.programmedStepMm;
  const points: JsonValue[] = s.points.map((p) => {
    const o: JsonObject = { slope: p.slopeDeg, lead: p.leadDeg, tilt: p.tiltDeg === 0 ? 0 : p.tiltDeg };
    if (p.stepMm !== null) o[i.passes === 'raster' ? 'horizontalStep' : 'stepDown'] = p.stepMm;
    if (p.intervalMm !== null) o.interval = p.intervalMm;
    if (Number.isFinite(p.heightLimitMm)) o.heightLimit = p.heightLimitMm;
    if (p.cuspAtProgrammedStepMm !== null) o.cuspAtProgrammedStep = p.cuspAtProgrammedStepMm;
    if (p.programmedStepRefusal !== null) o.programmedStepRefusal = p.programmedStepRefusal;
    return o;
  });
  return {
    unit: 'mm',
    machine: '3axis',
    sweep: 'slope',
    input,
    largestSlope: s.largestSlopeDeg,
    flatFloorStep: s.flatFloorStepMm,
    programmedStep: s.programmedStepMm,
    programmedStepTyped: step.typed,
    points,
  };
}
