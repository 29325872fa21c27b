/**
 * One case's answer as a table for the terminal or as a JSON object. Pure: comparison in, text
 * or plain data out. Names come from the core's procedure registry; lengths mm, angles degrees.
 */
import {
  APPROXIMATION_KEYS,
  type ApproximationKey,
  type ExactForward,
  type ForwardComparison,
  type ForwardEstimate,
  type InverseComparison,
  type InverseEstimate,
  type PassInput,
  PROCEDURES,
} from '../core/index';
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

function caseLine(input: PassInput): string {
  return (
    `${toolKind(input)} R = ${echo(input.toolRadiusMm)} mm, Rcr = ${echo(input.cornerRadiusMm)} mm; ` +
    `lead rho = ${echo(input.leadAngleDeg)} deg, tilt beta = ${echo(input.tiltAngleDeg)} deg; ${input.pattern} passes`
  );
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

/** The forward answer (scallop height to step-over) as a table. */
export function forwardTable(c: ForwardComparison): string {
  const { input, exact } = c;
  const zigzag = input.pattern === 'zigzag';
  const out = [caseLine(input), `Scallop height h = ${echo(input.scallopHeightMm)} mm`, ''];
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
    const r: ForwardEstimate<unknown> = c.approximations[key];
    const label = forwardLabel(key, input.tiltAngleDeg);
    if (!r.ok) {
      rows.push([label, 'n/a', 'n/a', NONE, NONE, NONE, notes.add(r.notApplicable)]);
      continue;
    }
    const marker = r.warning === null ? '' : notes.add(`${PROCEDURES[key].shortLabel}: ${r.warning}`);
    rows.push([
      label,
      length(r.intervalMm),
      length(r.halfIntervalMm),
      deviation(r.deviationMm),
      percent(r.deviationPercent),
      r.realScallopMm === null ? 'wall' : length(r.realScallopMm),
      marker,
    ]);
  }
  out.push(...renderTable(columns, rows));
  out.push('', 'dev L: step-over minus the exact one; real h: the scallop that step-over really leaves (exact).');
  if (notes.lines.length > 0) out.push('', ...notes.lines);
  return out.join('\n');
}

/** The inverse answer (step-over to scallop height) as a table. */
export function inverseTable(c: InverseComparison): string {
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
    const r: InverseEstimate = c.approximations[key];
    const label = inverseLabel(key, input.tiltAngleDeg);
    if (!r.ok) rows.push([label, 'n/a', NONE, NONE, notes.add(r.notApplicable)]);
    else rows.push([label, length(r.scallopHeightMm), deviation(r.deviationMm), percent(r.deviationPercent)]);
  }
  out.push(...renderTable(columns, rows));
  out.push('', 'dev: scallop height minus the exact one.');
  if (notes.lines.length > 0) out.push('', ...notes.lines);
  return out.join('\n');
}

/** JSON data: numbers are always finite; a value that does not exist is left out, never null. */
export type JsonValue = number | string | boolean | JsonValue[] | { [key: string]: JsonValue };
type JsonObject = { [key: string]: JsonValue };

function toolJson(input: PassInput): JsonObject {
  return {
    R: input.toolRadiusMm,
    Rcr: input.cornerRadiusMm,
    rho: input.leadAngleDeg,
    tilt: input.tiltAngleDeg,
    pattern: input.pattern,
  };
}

/** Model quantities of the approximations (mm), by their JSON names. */
const MODEL_FIELDS = [
  ['toolCentreHeightMm', 'toolCentreHeight'],
  ['shortRadiusMm', 'shortRadius'],
  ['longRadiusMm', 'longRadius'],
  ['effectiveRadiusMm', 'effectiveRadius'],
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
export function forwardJson(c: ForwardComparison): JsonObject {
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
  const out: JsonObject = {
    unit: 'mm',
    input: { ...toolJson(c.input), h: c.input.scallopHeightMm },
    maxInterval: c.maxIntervalMm,
    exact: exactOut,
  };
  for (const key of APPROXIMATION_KEYS) out[key] = forwardEstimateJson(c.approximations[key], exact);
  return out;
}

function inverseEstimateJson(r: InverseEstimate): JsonObject {
  if (!r.ok) return { notApplicable: r.notApplicable };
  const out: JsonObject = { scallopHeight: r.scallopHeightMm, deviation: r.deviationMm };
  if (r.deviationPercent !== null) out.deviationPercent = r.deviationPercent;
  return out;
}

/** The inverse comparison as the documented JSON object (lengths mm, angles degrees). */
export function inverseJson(c: InverseComparison): JsonObject {
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
  return out;
}
