/**
 * One case's answer as a table for the terminal or as a JSON object. Pure: comparison in, text
 * or plain data out. Names come from the core's procedure registry; lengths mm, angles degrees.
 * The parts: the roughness and simulation blocks (reportExtras.ts) and the JSON (reportJson.ts),
 * re-exported here.
 */
import {
  APPROXIMATION_KEYS,
  type ApproximationKey,
  CORRECTED_KEYS,
  type CorrectedKey,
  CURVATURE_ROWS,
  type ForwardComparison,
  type ForwardEstimate,
  type InverseComparison,
  type InverseEstimate,
  type PassInput,
  PROCEDURES,
  type Surface,
} from '../core/index';
import type { LengthUnit } from '../core/input/units';
import { finishLines } from './finish';
import {
  type Extras,
  exactBlock,
  flankFacts,
  givenHeight,
  roughnessLines,
  simulationLines,
  toolKind,
} from './reportExtras';
import { type Column, echo, type Lengths, lengthsIn, NONE, percent, renderTable } from './table';

/** The table's lengths in mm. */
const MM = lengthsIn('mm');

/** The extras (reportExtras.ts) and the JSON (reportJson.ts), re-exported for the callers. */
export { type Extras, roughnessLines, ruleOfThumb, type SimulationRun } from './reportExtras';
export { extrasJson, forwardJson, inverseJson, type JsonObject, type JsonValue } from './reportJson';

/** The paper's procedures: their inverse is named by its equation. */
const PAPER_KEYS: readonly ApproximationKey[] = ['sekine', 'redonnet', 'bedi'];

/** Label of an approximation in the forward table; lead-only models say so under tilt. */
export function forwardLabel(key: ApproximationKey, tiltDeg: number): string {
  const p = PROCEDURES[key];
  return p.leadOnly && tiltDeg !== 0 ? `${p.label}, lead only` : p.label;
}

/** Label of an approximation in the inverse table (the paper's by their inverse equations). */
export function inverseLabel(key: ApproximationKey, tiltDeg: number): string {
  const p = PROCEDURES[key];
  const base = PAPER_KEYS.includes(key) ? `${p.shortLabel} (${p.inverseEquations})` : p.label;
  return p.leadOnly && tiltDeg !== 0 ? `${base}, lead only` : base;
}

/** The design surface in words: `plane`, or the cylinder with its signed radius and axis. */
export function surfaceText(surface: Surface, L: Lengths = MM): string {
  if (surface.kind === 'plane') return 'on a plane';
  const kind = surface.radiusMm > 0 ? 'convex' : 'concave';
  const axis =
    surface.axis === 'feed'
      ? 'axis along the feed (passes run along it)'
      : 'axis across the feed (passes go around it)';
  return `on a ${kind} cylinder Rs = ${L.echo(surface.radiusMm)} ${L.u}, ${axis}`;
}

function caseLine(input: PassInput, L: Lengths): string {
  return (
    `${toolKind(input.toolRadiusMm, input.cornerRadiusMm)} R = ${L.echo(input.toolRadiusMm)} ${L.u}, Rcr = ${L.echo(input.cornerRadiusMm)} ${L.u}; ` +
    `lead rho = ${echo(input.leadAngleDeg)} deg, tilt beta = ${echo(input.tiltAngleDeg)} deg; ${input.pattern} passes ` +
    surfaceText(input.surface, L)
  );
}

/** Label of a curvature row: the plane's answer, or a procedure's circle corrected for the curvature. */
export function curvatureLabel(key: CorrectedKey | 'plane'): string {
  return CURVATURE_ROWS[key === 'plane' ? 'plane' : (`${key}Corrected` as const)].label;
}

/** Notes under a table, numbered; returns the marker of the note just added. */
class Notes {
  readonly lines: string[] = [];
  add(text: string): string {
    this.lines.push(`[${this.lines.length + 1}] ${text}`);
    return `[${this.lines.length}]`;
  }
}

/** A row of the forward table: a step-over beside the exact one (or n/a with its reason as a note). */
function forwardRow(label: string, r: ForwardEstimate<unknown>, warningBy: string, notes: Notes, L: Lengths): string[] {
  if (!r.ok) return [label, 'n/a', 'n/a', NONE, NONE, NONE, notes.add(r.notApplicable)];
  const marker = r.warning === null ? '' : notes.add(`${warningBy}: ${r.warning}`);
  return [
    label,
    L.length(r.intervalMm),
    L.length(r.halfIntervalMm),
    L.deviation(r.deviationMm),
    percent(r.deviationPercent),
    r.realScallopMm === null ? 'wall' : L.length(r.realScallopMm),
    marker,
  ];
}

/** A row of the inverse table: a scallop height beside the exact one (or n/a with its reason as a note). */
function inverseRow(label: string, r: InverseEstimate, notes: Notes, L: Lengths): string[] {
  if (!r.ok) return [label, 'n/a', NONE, NONE, notes.add(r.notApplicable)];
  return [label, L.length(r.scallopHeightMm), L.deviation(r.deviationMm), percent(r.deviationPercent)];
}

/** The forward answer (scallop height to step-over) as a table, with the extras that were computed. */
export function forwardTable(c: ForwardComparison, extras: Extras = {}, unit: LengthUnit = 'mm'): string {
  const L = lengthsIn(unit);
  const { input, exact } = c;
  const zigzag = input.pattern === 'zigzag';
  const out = [caseLine(input, L), givenHeight(input.scallopHeightMm, extras, L), ''];
  const facts: string[][] = [
    ['L', L.length(exact.intervalMm), L.u, 'step-over: between adjacent cutter-contact (CC) paths'],
    ['L/2', L.length(exact.halfIntervalMm), L.u, 'half step-over'],
    ...flankFacts(exact, L, 'the cusp'),
    ['h', L.length(exact.cuspHeightMm), L.u, zigzag ? 'highest cusp (between the narrower flanks)' : 'cusp height'],
  ];
  if (exact.otherCuspHeightMm !== null) {
    facts.push(['h2', L.length(exact.otherCuspHeightMm), L.u, 'other cusp (between the wider flanks), zigzag']);
  }
  out.push(...exactBlock(facts));
  if (exact.noScallop) {
    out.push(
      `  A flat end without lead or tilt leaves no scallop at any step-over up to its diameter: L = 2R for any h.`,
    );
  }
  out.push('');

  const notes = new Notes();
  const columns: Column[] = [
    { header: 'procedure', align: 'left' },
    { header: `L [${L.u}]`, align: 'right' },
    { header: `L/2 [${L.u}]`, align: 'right' },
    { header: `dev L [${L.u}]`, align: 'right' },
    { header: 'dev [%]', align: 'right' },
    { header: `real h [${L.u}]`, align: 'right' },
    { header: 'note', align: 'left' },
  ];
  const rows: string[][] = [
    [
      PROCEDURES.exact.label,
      L.length(exact.intervalMm),
      L.length(exact.halfIntervalMm),
      NONE,
      NONE,
      L.length(exact.cuspHeightMm),
    ],
  ];
  for (const key of APPROXIMATION_KEYS) {
    const label = forwardLabel(key, input.tiltAngleDeg);
    rows.push(forwardRow(label, c.approximations[key], PROCEDURES[key].shortLabel, notes, L));
  }
  const k = c.curvature;
  const curved =
    k === null
      ? null
      : [
          forwardRow(curvatureLabel('plane'), k.plane, 'Plane', notes, L),
          ...CORRECTED_KEYS.map((key) =>
            forwardRow(curvatureLabel(key), k.corrected[key], PROCEDURES[key].shortLabel, notes, L),
          ),
        ];
  const devLine = 'dev L: step-over minus the exact one; real h: the scallop that step-over really leaves (exact).';
  return tablesAndExtras(out, columns, rows, curved, devLine, extras, exact.cuspHeightMm, notes, L);
}

/** The inverse answer (step-over to scallop height) as a table, with the extras that were computed. */
export function inverseTable(c: InverseComparison, extras: Extras = {}, unit: LengthUnit = 'mm'): string {
  const L = lengthsIn(unit);
  const { input, exact } = c;
  const zigzag = input.pattern === 'zigzag';
  const out = [
    caseLine(input, L),
    `Step-over L = ${L.echo(input.intervalMm)} ${L.u} (L/2 = ${L.echo(input.intervalMm / 2)} ${L.u}) between cutter-contact paths`,
    '',
  ];
  const facts: string[][] = [['h', L.length(exact.cuspHeightMm), L.u, 'scallop height (the highest cusp)']];
  if (zigzag) {
    facts.push(
      ['hR', L.length(exact.rightCuspHeightMm), L.u, 'cusp between right flanks (wR = L/2)'],
      ['hL', L.length(exact.leftCuspHeightMm), L.u, 'cusp between left flanks (wL = L/2)'],
    );
  }
  facts.push(...flankFacts(exact, L, 'its cusp'));
  out.push(...exactBlock(facts));
  if (exact.cuspHeightMm === 0) {
    out.push('  No scallop: the flat bottom lying on the plane covers this step-over.');
  }
  out.push('');

  const notes = new Notes();
  const columns: Column[] = [
    { header: 'procedure', align: 'left' },
    { header: `h [${L.u}]`, align: 'right' },
    { header: `dev [${L.u}]`, align: 'right' },
    { header: 'dev [%]', align: 'right' },
    { header: 'note', align: 'left' },
  ];
  const rows: string[][] = [[PROCEDURES.exact.label, L.length(exact.cuspHeightMm), NONE, NONE]];
  for (const key of APPROXIMATION_KEYS) {
    rows.push(inverseRow(inverseLabel(key, input.tiltAngleDeg), c.approximations[key], notes, L));
  }
  const k = c.curvature;
  const curved =
    k === null
      ? null
      : [
          inverseRow(curvatureLabel('plane'), k.plane, notes, L),
          ...CORRECTED_KEYS.map((key) => inverseRow(curvatureLabel(key), k.corrected[key], notes, L)),
        ];
  return tablesAndExtras(
    out,
    columns,
    rows,
    curved,
    'dev: scallop height minus the exact one.',
    extras,
    exact.cuspHeightMm,
    notes,
    L,
  );
}

/**
 * The end of both directions' reports: the table of the procedures, the cylinder's rows beneath it
 * (when there are any), the line saying what dev means, the extras and the notes; all joined.
 */
function tablesAndExtras(
  out: string[],
  columns: Column[],
  rows: string[][],
  curved: string[][] | null,
  devLine: string,
  extras: Extras,
  exactCuspHeightMm: number,
  notes: Notes,
  L: Lengths,
): string {
  out.push(...renderTable(columns, rows));
  if (curved !== null) {
    out.push('', 'On the cylinder: the plane answer and the usual curvature corrections, beside the exact one:');
    out.push(...renderTable(columns, curved));
  }
  out.push('', devLine);
  if (curved !== null) {
    out.push('Above the cylinder rows: the approximations as on a plane (they ignore the curvature).');
  }
  if (extras.roughness !== undefined) out.push('', ...roughnessLines(extras.roughness, exactCuspHeightMm, L));
  if (extras.simulation !== undefined) {
    out.push('', ...simulationLines(extras.simulation, exactCuspHeightMm, extras.roughness, L));
  }
  if (extras.finish !== undefined) out.push('', ...finishLines(extras.finish, exactCuspHeightMm, L));
  if (notes.lines.length > 0) out.push('', ...notes.lines);
  return out.join('\n');
}
