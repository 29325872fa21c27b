/**
 * One case's answer as a table for the terminal or as a JSON object. Pure: comparison in, text
 * or plain data out. Names come from the core's procedure registry; lengths mm, angles degrees.
 */
import {
  APPROXIMATION_KEYS,
  type ApproximationKey,
  CORRECTED_KEYS,
  type CorrectedKey,
  CURVATURE_ROWS,
  type ExactForward,
  type ForwardComparison,
  type ForwardEstimate,
  type InverseComparison,
  type InverseEstimate,
  type PassInput,
  PROCEDURES,
  type Roughness,
  raRuleOfThumbMm,
  type SimulationResult,
  type Surface,
} from '../core/index';
import { PASS_FIELDS } from '../core/input/fields';
import { rawOf } from '../core/input/raw';
import { type Column, deviation, echo, length, NONE, percent, renderTable } from './table';

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

function toolKind(input: PassInput): string {
  if (input.cornerRadiusMm === input.toolRadiusMm) return 'Ball end mill';
  if (input.cornerRadiusMm === 0) return 'Flat end mill';
  return 'Filleted end mill';
}

/** The design surface in words: `plane`, or the cylinder with its signed radius and axis. */
export function surfaceText(surface: Surface): string {
  if (surface.kind === 'plane') return 'on a plane';
  const kind = surface.radiusMm > 0 ? 'convex' : 'concave';
  const axis =
    surface.axis === 'feed'
      ? 'axis along the feed (passes run along it)'
      : 'axis across the feed (passes go around it)';
  return `on a ${kind} cylinder Rs = ${echo(surface.radiusMm)} mm, ${axis}`;
}

function caseLine(input: PassInput): string {
  return (
    `${toolKind(input)} R = ${echo(input.toolRadiusMm)} mm, Rcr = ${echo(input.cornerRadiusMm)} mm; ` +
    `lead rho = ${echo(input.leadAngleDeg)} deg, tilt beta = ${echo(input.tiltAngleDeg)} deg; ${input.pattern} passes ` +
    surfaceText(input.surface)
  );
}

/** A simulation of the passes and its wall-clock time, or why it was not run. */
export type SimulationRun =
  | { readonly ok: true; readonly result: SimulationResult; readonly ms: number }
  | { readonly ok: false; readonly notApplicable: string };

/** What a case's report adds to the comparison: roughness, the target Ra it was solved for, a simulation. */
export interface Extras {
  /** Exact roughness of the surface the passes leave (at the exact step-over, or the given one). */
  readonly roughness?: Roughness;
  /** The target Ra (mm) the scallop height was solved for (--ra). */
  readonly targetRaMm?: number;
  readonly simulation?: SimulationRun;
}

/** The rule of thumb Ra ~ h/4 beside the exact Ra: its value and its error (null % when Ra = 0). */
export function ruleOfThumb(
  scallopHeightMm: number,
  exactRaMm: number,
): { raMm: number; deviationMm: number; deviationPercent: number | null } {
  const raMm = raRuleOfThumbMm(scallopHeightMm);
  const deviationMm = raMm - exactRaMm;
  return { raMm, deviationMm, deviationPercent: exactRaMm > 0 ? (100 * deviationMm) / exactRaMm : null };
}

/** Lines of the roughness block (exact Rz, Ra, Rq and the rule of thumb). */
export function roughnessLines(r: Roughness, scallopHeightMm: number): string[] {
  const thumb = ruleOfThumb(scallopHeightMm, r.raMm);
  const off =
    thumb.deviationPercent === null
      ? `${deviation(thumb.deviationMm)} mm off`
      : `${deviation(thumb.deviationMm)} mm (${percent(thumb.deviationPercent)} %) off the exact Ra`;
  const facts: string[][] = [
    ['Rz', length(r.rzMm), 'mm', 'highest peak minus deepest valley'],
    ['Ra', length(r.raMm), 'mm', 'mean absolute deviation from the mean line'],
    ['Rq', length(r.rqMm), 'mm', 'root mean square deviation from the mean line'],
    ['h/4', length(thumb.raMm), 'mm', `rule of thumb Ra ~ h/4: ${off}`],
  ];
  return [
    'Roughness across the feed (exact, ISO 4287 over one period of the passes):',
    ...indent(renderTable(KEY_VALUE, facts, false)),
  ];
}

/** Lines of the simulation block: the simulated values beside the exact ones, with the stated bounds. */
function simulationLines(sim: SimulationRun, exactCuspMm: number, exact: Roughness | undefined): string[] {
  if (!sim.ok) return [`Simulation of the passes: ${sim.notApplicable}.`];
  const s = sim.result;
  const vs = (simulated: number, exactMm: number | undefined) =>
    exactMm === undefined ? '' : `; exact minus simulated ${deviation(exactMm - simulated)} mm`;
  const facts: string[][] = [
    [
      'h',
      length(s.cuspHeightMm),
      'mm',
      `highest cusp, within ${length(s.resolutionBoundMm)} mm${vs(s.cuspHeightMm, exactCuspMm)}`,
    ],
    [
      'Rz',
      length(s.roughness.rzMm),
      'mm',
      `within ${length(s.roughnessBoundMm)} mm${vs(s.roughness.rzMm, exact?.rzMm)}`,
    ],
    [
      'Ra',
      length(s.roughness.raMm),
      'mm',
      `within ${length(s.roughnessBoundMm)} mm${vs(s.roughness.raMm, exact?.raMm)}`,
    ],
    [
      'Rq',
      length(s.roughness.rqMm),
      'mm',
      `within ${length(s.roughnessBoundMm)} mm${vs(s.roughness.rqMm, exact?.rqMm)}`,
    ],
  ];
  return [
    `Simulation of the passes (the tool solid on a ${s.cellsAcross} x ${s.cellsAlong} height field, ` +
      `${s.placements} placements, ${Math.round(sim.ms)} ms; independent of the exact solver):`,
    ...indent(renderTable(KEY_VALUE, facts, false)),
  ];
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

const KEY_VALUE: readonly Column[] = [
  { header: '', align: 'left' },
  { header: '', align: 'right' },
  { header: '', align: 'left' },
  { header: '', align: 'left' },
];

function indent(lines: readonly string[]): string[] {
  return lines.map((l) => `  ${l}`);
}

/** A row of the forward table: a step-over beside the exact one (or n/a with its reason as a note). */
function forwardRow(label: string, r: ForwardEstimate<unknown>, warningBy: string, notes: Notes): string[] {
  if (!r.ok) return [label, 'n/a', 'n/a', NONE, NONE, NONE, notes.add(r.notApplicable)];
  const marker = r.warning === null ? '' : notes.add(`${warningBy}: ${r.warning}`);
  return [
    label,
    length(r.intervalMm),
    length(r.halfIntervalMm),
    deviation(r.deviationMm),
    percent(r.deviationPercent),
    r.realScallopMm === null ? 'wall' : length(r.realScallopMm),
    marker,
  ];
}

/** A row of the inverse table: a scallop height beside the exact one (or n/a with its reason as a note). */
function inverseRow(label: string, r: InverseEstimate, notes: Notes): string[] {
  if (!r.ok) return [label, 'n/a', NONE, NONE, notes.add(r.notApplicable)];
  return [label, length(r.scallopHeightMm), deviation(r.deviationMm), percent(r.deviationPercent)];
}

/** The forward answer (scallop height to step-over) as a table, with the extras that were computed. */
export function forwardTable(c: ForwardComparison, extras: Extras = {}): string {
  const { input, exact } = c;
  const zigzag = input.pattern === 'zigzag';
  const target =
    extras.targetRaMm === undefined
      ? `Scallop height h = ${echo(input.scallopHeightMm)} mm`
      : `Target roughness Ra = ${echo(extras.targetRaMm)} mm: scallop height h = ${length(input.scallopHeightMm)} mm`;
  const out = [caseLine(input), target, ''];
  const facts: string[][] = [
    ['L', length(exact.intervalMm), 'mm', 'step-over: between adjacent cutter-contact (CC) paths'],
    ['L/2', length(exact.halfIntervalMm), 'mm', 'half step-over'],
    ['wR', length(exact.halfWidthRightMm), 'mm', 'right flank (+Y) from the contact, at the cusp'],
    ['wL', length(exact.halfWidthLeftMm), 'mm', 'left flank (-Y) from the contact, at the cusp'],
    [
      'y0',
      length(exact.contactOffsetMm),
      'mm',
      'contact offset: the tool centre point runs -y0 (in Y) from its CC path',
    ],
    ['h', length(exact.cuspHeightMm), 'mm', zigzag ? 'highest cusp (between the narrower flanks)' : 'cusp height'],
  ];
  if (exact.otherCuspHeightMm !== null) {
    facts.push(['h2', length(exact.otherCuspHeightMm), 'mm', 'other cusp (between the wider flanks), zigzag']);
  }
  out.push(`${PROCEDURES.exact.label}:`, ...indent(renderTable(KEY_VALUE, facts, false)));
  if (exact.noScallop) {
    out.push(
      `  A flat end without lead or tilt leaves no scallop at any step-over up to its diameter: L = 2R for any h.`,
    );
  }
  out.push('');

  const notes = new Notes();
  const columns: Column[] = [
    { header: 'procedure', align: 'left' },
    { header: 'L [mm]', align: 'right' },
    { header: 'L/2 [mm]', align: 'right' },
    { header: 'dev L [mm]', align: 'right' },
    { header: 'dev [%]', align: 'right' },
    { header: 'real h [mm]', align: 'right' },
    { header: 'note', align: 'left' },
  ];
  const rows: string[][] = [
    [
      PROCEDURES.exact.label,
      length(exact.intervalMm),
      length(exact.halfIntervalMm),
      NONE,
      NONE,
      length(exact.cuspHeightMm),
    ],
  ];
  for (const key of APPROXIMATION_KEYS) {
    const label = forwardLabel(key, input.tiltAngleDeg);
    rows.push(forwardRow(label, c.approximations[key], PROCEDURES[key].shortLabel, notes));
  }
  out.push(...renderTable(columns, rows));
  if (c.curvature !== null) {
    const k = c.curvature;
    const curved: string[][] = [forwardRow(curvatureLabel('plane'), k.plane, 'Plane', notes)];
    for (const key of CORRECTED_KEYS) {
      curved.push(forwardRow(curvatureLabel(key), k.corrected[key], PROCEDURES[key].shortLabel, notes));
    }
    out.push('', 'On the cylinder: the plane answer and the usual curvature corrections, beside the exact one:');
    out.push(...renderTable(columns, curved));
  }
  out.push('', 'dev L: step-over minus the exact one; real h: the scallop that step-over really leaves (exact).');
  if (c.curvature !== null) {
    out.push('Above the cylinder rows: the approximations as on a plane (they ignore the curvature).');
  }
  if (extras.roughness !== undefined) out.push('', ...roughnessLines(extras.roughness, exact.cuspHeightMm));
  if (extras.simulation !== undefined) {
    out.push('', ...simulationLines(extras.simulation, exact.cuspHeightMm, extras.roughness));
  }
  if (notes.lines.length > 0) out.push('', ...notes.lines);
  return out.join('\n');
}

/** The inverse answer (step-over to scallop height) as a table, with the extras that were computed. */
export function inverseTable(c: InverseComparison, extras: Extras = {}): string {
  const { input, exact } = c;
  const zigzag = input.pattern === 'zigzag';
  const out = [
    caseLine(input),
    `Step-over L = ${echo(input.intervalMm)} mm (L/2 = ${echo(input.intervalMm / 2)} mm) between cutter-contact paths`,
    '',
  ];
  const facts: string[][] = [['h', length(exact.cuspHeightMm), 'mm', 'scallop height (the highest cusp)']];
  if (zigzag) {
    facts.push(
      ['hR', length(exact.rightCuspHeightMm), 'mm', 'cusp between right flanks (wR = L/2)'],
      ['hL', length(exact.leftCuspHeightMm), 'mm', 'cusp between left flanks (wL = L/2)'],
    );
  }
  facts.push(
    ['wR', length(exact.halfWidthRightMm), 'mm', 'right flank (+Y) from the contact, at its cusp'],
    ['wL', length(exact.halfWidthLeftMm), 'mm', 'left flank (-Y) from the contact, at its cusp'],
    [
      'y0',
      length(exact.contactOffsetMm),
      'mm',
      'contact offset: the tool centre point runs -y0 (in Y) from its CC path',
    ],
  );
  out.push(`${PROCEDURES.exact.label}:`, ...indent(renderTable(KEY_VALUE, facts, false)));
  if (exact.cuspHeightMm === 0) {
    out.push('  No scallop: the flat bottom lying on the plane covers this step-over.');
  }
  out.push('');

  const notes = new Notes();
  const columns: Column[] = [
    { header: 'procedure', align: 'left' },
    { header: 'h [mm]', align: 'right' },
    { header: 'dev [mm]', align: 'right' },
    { header: 'dev [%]', align: 'right' },
    { header: 'note', align: 'left' },
  ];
  const rows: string[][] = [[PROCEDURES.exact.label, length(exact.cuspHeightMm), NONE, NONE]];
  for (const key of APPROXIMATION_KEYS) {
    rows.push(inverseRow(inverseLabel(key, input.tiltAngleDeg), c.approximations[key], notes));
  }
  out.push(...renderTable(columns, rows));
  if (c.curvature !== null) {
    const k = c.curvature;
    const curved: string[][] = [inverseRow(curvatureLabel('plane'), k.plane, notes)];
    for (const key of CORRECTED_KEYS) curved.push(inverseRow(curvatureLabel(key), k.corrected[key], notes));
    out.push('', 'On the cylinder: the plane answer and the usual curvature corrections, beside the exact one:');
    out.push(...renderTable(columns, curved));
  }
  out.push('', 'dev: scallop height minus the exact one.');
  if (c.curvature !== null) {
    out.push('Above the cylinder rows: the approximations as on a plane (they ignore the curvature).');
  }
  if (extras.roughness !== undefined) out.push('', ...roughnessLines(extras.roughness, exact.cuspHeightMm));
  if (extras.simulation !== undefined) {
    out.push('', ...simulationLines(extras.simulation, exact.cuspHeightMm, extras.roughness));
  }
  if (notes.lines.length > 0) out.push('', ...notes.lines);
  return out.join('\n');
}

/** JSON data: numbers are always finite; a value that does not exist is left out, never null. */
export type JsonValue = number | string | boolean | JsonValue[] | { [key: string]: JsonValue };
type JsonObject = { [key: string]: JsonValue };

/** The tool, posture, pattern and surface as validation reads them (a plane has no surface fields: left out). */
function toolJson(input: PassInput): JsonObject {
  const out = rawOf(input, PASS_FIELDS) as JsonObject;
  // A cylinder is a doubly curved point with one radius straight: its principal radii too.
  const s = input.surface;
  if (s.kind === 'cylinder') out[s.axis === 'feed' ? 'crossRadius' : 'feedRadius'] = s.radiusMm;
  return out;
}

/** The extras as JSON fields: roughness, the rule of thumb beside it, the simulation. */
export function extrasJson(extras: Extras, scallopHeightMm: number): JsonObject {
  const out: JsonObject = {};
  const r = extras.roughness;
  if (r !== undefined) {
    out.roughness = { Rz: r.rzMm, Ra: r.raMm, Rq: r.rqMm };
    const thumb = ruleOfThumb(scallopHeightMm, r.raMm);
    const rule: JsonObject = { Ra: thumb.raMm, deviation: thumb.deviationMm };
    if (thumb.deviationPercent !== null) rule.deviationPercent = thumb.deviationPercent;
    out.raRuleOfThumb = rule;
  }
  const sim = extras.simulation;
  if (sim !== undefined && !sim.ok) out.simulation = { notApplicable: sim.notApplicable };
  else if (sim !== undefined) {
    const s = sim.result;
    out.simulation = {
      cuspHeight: s.cuspHeightMm,
      Rz: s.roughness.rzMm,
      Ra: s.roughness.raMm,
      Rq: s.roughness.rqMm,
      cells: s.cells,
      placements: s.placements,
      ms: sim.ms,
      cuspHeightBound: s.resolutionBoundMm,
      roughnessBound: s.roughnessBoundMm,
      cellsAcross: s.cellsAcross,
      cellsAlong: s.cellsAlong,
      cellSize: s.cellMm,
    };
  }
  return out;
}

/** Model quantities of the approximations (mm), by their JSON names. */
const MODEL_FIELDS = [
  ['toolCentreHeightMm', 'toolCentreHeight'],
  ['shortRadiusMm', 'shortRadius'],
  ['longRadiusMm', 'longRadius'],
  ['effectiveRadiusMm', 'effectiveRadius'],
  ['combinedRadiusMm', 'combinedRadius'],
] as const;

function forwardEstimateJson(r: ForwardEstimate<unknown>, exact: ExactForward): JsonObject {
  if (!r.ok) return { notApplicable: r.notApplicable };
  const out: JsonObject = {
    halfInterval: r.halfIntervalMm,
    interval: r.intervalMm,
    // As before tilt existed: the deviation of L/2; the step-over's is intervalDeviation.
    deviation: r.halfIntervalMm - exact.halfIntervalMm,
    intervalDeviation: r.deviationMm,
    deviationPercent: r.deviationPercent,
  };
  if (r.realScallopMm !== null) out.realScallopHeight = r.realScallopMm;
  if (r.warning !== null) out.warning = r.warning;
  const model = r as unknown as Record<string, unknown>;
  for (const [from, to] of MODEL_FIELDS) {
    const v = model[from];
    if (typeof v === 'number') out[to] = v;
  }
  return out;
}

/** The forward comparison as the documented JSON object (lengths mm, angles degrees). */
export function forwardJson(c: ForwardComparison, extras: Extras = {}): JsonObject {
  const { exact } = c;
  const exactOut: JsonObject = {
    halfInterval: exact.halfIntervalMm,
    interval: exact.intervalMm,
    halfWidthRight: exact.halfWidthRightMm,
    halfWidthLeft: exact.halfWidthLeftMm,
    contactOffset: exact.contactOffsetMm,
    scallopHeight: exact.cuspHeightMm,
  };
  if (exact.otherCuspHeightMm !== null) exactOut.otherCuspHeight = exact.otherCuspHeightMm;
  exactOut.noScallop = exact.noScallop;
  const target: JsonObject =
    extras.targetRaMm === undefined ? { h: c.input.scallopHeightMm } : { Ra: extras.targetRaMm };
  const out: JsonObject = {
    unit: 'mm',
    input: { ...toolJson(c.input), ...target },
    maxInterval: c.maxIntervalMm,
    exact: exactOut,
  };
  for (const key of APPROXIMATION_KEYS) out[key] = forwardEstimateJson(c.approximations[key], exact);
  if (c.curvature !== null) {
    const k = c.curvature;
    const rows: JsonObject = { plane: forwardEstimateJson(k.plane, exact) };
    for (const key of CORRECTED_KEYS) rows[key] = forwardEstimateJson(k.corrected[key], exact);
    out.curvature = rows;
  }
  return { ...out, ...extrasJson(extras, exact.cuspHeightMm) };
}

function inverseEstimateJson(r: InverseEstimate): JsonObject {
  if (!r.ok) return { notApplicable: r.notApplicable };
  const out: JsonObject = { scallopHeight: r.scallopHeightMm, deviation: r.deviationMm };
  if (r.deviationPercent !== null) out.deviationPercent = r.deviationPercent;
  return out;
}

/** The inverse comparison as the documented JSON object (lengths mm, angles degrees). */
export function inverseJson(c: InverseComparison, extras: Extras = {}): JsonObject {
  const { exact } = c;
  const exactOut: JsonObject = {
    scallopHeight: exact.cuspHeightMm,
    rightCuspHeight: exact.rightCuspHeightMm,
    leftCuspHeight: exact.leftCuspHeightMm,
  };
  if (exact.otherCuspHeightMm !== null) exactOut.otherCuspHeight = exact.otherCuspHeightMm;
  exactOut.interval = exact.intervalMm;
  exactOut.halfInterval = exact.intervalMm / 2;
  exactOut.halfWidthRight = exact.halfWidthRightMm;
  exactOut.halfWidthLeft = exact.halfWidthLeftMm;
  exactOut.contactOffset = exact.contactOffsetMm;
  const out: JsonObject = {
    unit: 'mm',
    input: { ...toolJson(c.input), interval: c.input.intervalMm, halfInterval: c.input.intervalMm / 2 },
    exact: exactOut,
  };
  for (const key of APPROXIMATION_KEYS) out[key] = inverseEstimateJson(c.approximations[key]);
  if (c.curvature !== null) {
    const k = c.curvature;
    const rows: JsonObject = { plane: inverseEstimateJson(k.plane) };
    for (const key of CORRECTED_KEYS) rows[key] = inverseEstimateJson(k.corrected[key]);
    out.curvature = rows;
  }
  return { ...out, ...extrasJson(extras, exact.cuspHeightMm) };
}
