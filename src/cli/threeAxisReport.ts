/**
 * A three-axis answer (issue 20: the tool upright, the surface sloped) as a table for the terminal
 * or as a JSON object. The step as the CAM system programs it comes first (Lxy for raster passes,
 * dz for waterline), then L along the surface and the equivalent lead and tilt at the CC point.
 * Pure; lengths mm, angles degrees.
 */
import type { ThreeAxisAnswer, ThreeAxisProblem, ThreeAxisQuantity } from '../core/threeAxis/validate';
import type { JsonValue } from './report';
import { type Column, echo, length, renderTable } from './table';

type JsonObject = { [key: string]: JsonValue };

const KEY_VALUE: readonly Column[] = [
  { header: '', align: 'left' },
  { header: '', align: 'right' },
  { header: '', align: 'left' },
  { header: '', align: 'left' },
];

/** An angle (degrees) for the table: 7 significant digits, never -0. */
function angle(deg: number): string {
  return length(deg === 0 ? 0 : deg);
}

function toolKind(p: ThreeAxisProblem): string {
  const { toolRadiusMm: R, cornerRadiusMm: Rcr } = p.case;
  return Rcr === R ? 'Ball end mill' : Rcr === 0 ? 'Flat end mill' : 'Filleted end mill';
}

/** The case in words: the tool, upright; the surface and the passes. */
function caseLine(p: ThreeAxisProblem): string {
  const c = p.case;
  const tool = `${toolKind(p)} R = ${echo(c.toolRadiusMm)} mm, Rcr = ${echo(c.cornerRadiusMm)} mm, upright (three-axis)`;
  if (p.surface === 'plane') {
    const passes =
      p.case.passes === 'raster'
        ? `raster passes at psi = ${echo(p.case.rasterAngleDeg)} deg to the fall line`
        : 'waterline passes (along the contour)';
    return `${tool}; plane of slope alpha = ${echo(c.slopeDeg)} deg; ${passes}`;
  }
  const radius = (r: number | null) => (r === null ? 'straight' : `${echo(r)} mm`);
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
export function threeAxisTable(p: ThreeAxisProblem, a: ThreeAxisAnswer): string {
  const facts: string[][] = [];
  const lxy = [
    'Lxy',
    length(a.horizontalStepMm),
    'mm',
    p.surface === 'plane'
      ? 'horizontal step: between the vertical planes of adjacent passes'
      : 'horizontal step: between the tool axes of adjacent levels',
  ];
  if (a.passes === 'raster') facts.push([...lxy.slice(0, 3), `${lxy[3]} (as programmed)`]);
  else
    facts.push([
      'dz',
      length(a.stepDownMm ?? 0),
      'mm',
      'step-down between levels, tool tip to tool tip (as programmed)',
    ]);
  facts.push(['L', length(a.intervalMm), 'mm', 'step-over along the surface: between adjacent cutter-contact paths']);
  if (a.passes === 'waterline') facts.push(lxy);
  facts.push(
    ['lead', angle(a.leadDeg), 'deg', 'equivalent lead rho at the CC point'],
    ['tilt', angle(a.tiltDeg), 'deg', 'equivalent tilt beta at the CC point (+: the shank leans uphill)'],
    ['h', length(a.cuspHeightMm), 'mm', 'cusp height, along the surface normal'],
  );
  const out = [
    caseLine(p),
    `${GIVEN[p.quantity]} = ${echo(p.mm)} mm`,
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
