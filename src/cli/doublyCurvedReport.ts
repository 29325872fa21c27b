/**
 * A doubly curved point's answer (issue 19: signed principal radii Rf along the feed, Rc across) as
 * a table for the terminal or as a JSON object: the exact answer, then (forward) the comparison rows
 * of core/procedures/compareDoublyCurved.ts: the plane's answer, each cylinder's (one radius ignored) and the
 * usual correction 1/rho = 1/Reff + 1/Rc of each procedure with an effective radius, each with its
 * deviation from the exact step-over and the scallop its L really leaves; the roughness. Pure;
 * lengths mm, angles degrees.
 */

import { CORRECTED_KEYS, PROCEDURES, type Roughness } from '../core/index';
import { TOOL_FIELDS } from '../core/input/fields';
import { rawOf } from '../core/input/raw';
import type { LengthUnit } from '../core/input/units';
import type { DoublyCurvedComparison, DoublyCurvedRow } from '../core/procedures/compareDoublyCurved';
import type { DoublyCurvedPass } from '../core/surfaces/doublyCurved/index';
import type { ExactInverse } from '../core/surfaces/surface';
import { curvatureLabel, type Extras, extrasJson, type JsonObject, roughnessLines } from './report';
import { exactBlock, flankFacts, givenHeight, toolKind } from './reportExtras';
import { inverseExactJson } from './reportJson';
import { type Column, echo, type Lengths, lengthsIn, NONE, percent, renderTable } from './table';

/** A forward answer at a doubly curved point as the reports show it: the pass, h, the comparison (the exact answer first) and the extras. */
export interface DoublyCurvedForwardReport {
  readonly pass: DoublyCurvedPass;
  readonly h: number;
  readonly comparison: DoublyCurvedComparison;
  readonly extras: Extras;
}

/** An inverse answer at a doubly curved point as the reports show it: the pass, the exact cusps and the roughness. */
export interface DoublyCurvedInverseReport {
  readonly pass: DoublyCurvedPass;
  readonly exact: ExactInverse;
  readonly roughness: Roughness;
}

/** The kind of point from the signs of its radii. */
export function pointKind(rf: number, rc: number): string {
  if (rf > 0 && rc > 0) return rf === rc ? 'convex sphere' : 'dome (both convex)';
  if (rf < 0 && rc < 0) return rf === rc ? 'concave sphere' : 'bowl (both concave)';
  return 'saddle (one convex, one concave)';
}

function caseLine(p: DoublyCurvedPass, L: Lengths): string {
  const kind = toolKind(p.toolRadiusMm, p.cornerRadiusMm);
  return (
    `${kind} R = ${L.echo(p.toolRadiusMm)} ${L.u}, Rcr = ${L.echo(p.cornerRadiusMm)} ${L.u}; ` +
    `lead rho = ${echo(p.leadAngleDeg)} deg, tilt beta = ${echo(p.tiltAngleDeg)} deg; ${p.pattern} passes ` +
    `at a doubly curved point, ${pointKind(p.feedRadiusMm, p.crossRadiusMm)}: ` +
    `Rf = ${L.echo(p.feedRadiusMm)} ${L.u} along the feed, Rc = ${L.echo(p.crossRadiusMm)} ${L.u} across ` +
    '(heights along the normal, L along the surface)'
  );
}

/** Each comparison row: its JSON key and its label. */
function rowsOf(c: DoublyCurvedComparison): Array<[string, string, DoublyCurvedRow]> {
  const out: Array<[string, string, DoublyCurvedRow]> = [
    ['plane', curvatureLabel('plane'), c.plane],
    ['cylinderAlong', 'Cylinder along the feed, exact (Rf ignored)', c.cylinderAlong],
    ['cylinderAcross', 'Cylinder across the feed, exact (Rc ignored)', c.cylinderAcross],
  ];
  for (const key of CORRECTED_KEYS) {
    out.push([key, `${PROCEDURES[key].shortLabel}, 1/rho = 1/Reff + 1/Rc`, c.corrected[key]]);
  }
  return out;
}

/** The forward answer at a doubly curved point as a table. */
export function doublyCurvedForwardTable(a: DoublyCurvedForwardReport, unit: LengthUnit = 'mm'): string {
  const { pass: p, h, comparison: c, extras } = a;
  const L = lengthsIn(unit);
  const e = c.exact;
  const facts: string[][] = [
    ['L', L.length(e.intervalMm), L.u, 'step-over: arc length along the surface between adjacent CC paths'],
    ['L/2', L.length(e.intervalMm / 2), L.u, 'half step-over'],
    ...flankFacts(e, L, 'the cusp'),
    ['h', L.length(e.cuspHeightMm), L.u, p.pattern === 'zigzag' ? 'highest cusp' : 'cusp height'],
  ];
  if (e.otherCuspHeightMm !== null) facts.push(['h2', L.length(e.otherCuspHeightMm), L.u, 'other cusp, zigzag']);
  const out = [caseLine(p, L), givenHeight(h, extras, L), '', ...exactBlock(facts), ''];
  const columns: Column[] = [
    { header: 'shortcut', align: 'left' },
    { header: `L [${L.u}]`, align: 'right' },
    { header: `dev L [${L.u}]`, align: 'right' },
    { header: 'dev [%]', align: 'right' },
    { header: `real h [${L.u}]`, align: 'right' },
    { header: 'note', align: 'left' },
  ];
  const notes: string[] = [];
  const rows: string[][] = [[PROCEDURES.exact.label, L.length(e.intervalMm), NONE, NONE, L.length(e.cuspHeightMm)]];
  for (const [, label, r] of rowsOf(c)) {
    if (!r.ok) {
      notes.push(`[${notes.length + 1}] ${r.notApplicable}`);
      rows.push([label, 'n/a', NONE, NONE, NONE, `[${notes.length}]`]);
    } else {
      rows.push([
        label,
        L.length(r.intervalMm),
        L.deviation(r.deviationMm),
        percent(r.deviationPercent),
        r.realScallopMm === null ? 'wall' : L.length(r.realScallopMm),
      ]);
    }
  }
  out.push('What the shortcuts give at this point, beside the exact answer:', ...renderTable(columns, rows));
  out.push('', 'dev L: step-over minus the exact one; real h: the scallop that step-over really leaves here (exact).');
  if (extras.roughness !== undefined) out.push('', ...roughnessLines(extras.roughness, e.cuspHeightMm, L));
  if (notes.length > 0) out.push('', ...notes);
  return out.join('\n');
}

/** The inverse answer (step-over to cusp heights) at a doubly curved point as a table. */
export function doublyCurvedInverseTable(a: DoublyCurvedInverseReport, unit: LengthUnit = 'mm'): string {
  const { pass: p, exact: e, roughness } = a;
  const L = lengthsIn(unit);
  const facts: string[][] = [['h', L.length(e.cuspHeightMm), L.u, 'scallop height (the highest cusp)']];
  if (e.otherCuspHeightMm !== null) {
    facts.push(
      ['h2', L.length(e.otherCuspHeightMm), L.u, 'other cusp, zigzag'],
      ['hR', L.length(e.rightCuspHeightMm), L.u, 'cusp between right flanks (wR = L/2)'],
      ['hL', L.length(e.leftCuspHeightMm), L.u, 'cusp between left flanks (wL = L/2)'],
    );
  }
  facts.push(...flankFacts(e, L, 'its cusp'));
  return [
    caseLine(p, L),
    `Step-over L = ${L.echo(e.intervalMm)} ${L.u} (L/2 = ${L.echo(e.intervalMm / 2)} ${L.u}) along the surface between CC paths`,
    '',
    ...exactBlock(facts),
    '',
    ...roughnessLines(roughness, e.cuspHeightMm, L),
  ].join('\n');
}

/** The tool's fields and the pattern, in this order (the registry's names). */
const PASS_INPUT_FIELDS = [...TOOL_FIELDS, 'pattern'] as const;

/**
 * The pass as JSON input fields (the registry's names): the tool's and the pattern read back by
 * each field's core property (core input/raw.ts), then the point's two radii.
 */
function inputJson(p: DoublyCurvedPass): JsonObject {
  return { ...(rawOf(p, PASS_INPUT_FIELDS) as JsonObject), feedRadius: p.feedRadiusMm, crossRadius: p.crossRadiusMm };
}

function rowJson(r: DoublyCurvedRow & { readonly combinedRadiusMm?: number }): JsonObject {
  if (!r.ok) return { notApplicable: r.notApplicable };
  const out: JsonObject = {
    interval: r.intervalMm,
    intervalDeviation: r.deviationMm,
    deviationPercent: r.deviationPercent,
  };
  if (r.realScallopMm !== null) out.realScallopHeight = r.realScallopMm;
  if (r.combinedRadiusMm !== undefined) out.combinedRadius = r.combinedRadiusMm;
  return out;
}

/** The forward answer at a doubly curved point as JSON (lengths mm, angles degrees). */
export function doublyCurvedForwardJson(a: DoublyCurvedForwardReport): JsonObject {
  const { pass: p, h, comparison: c, extras } = a;
  const e = c.exact;
  const exact: JsonObject = {
    interval: e.intervalMm,
    halfInterval: e.intervalMm / 2,
    halfWidthRight: e.halfWidthRightMm,
    halfWidthLeft: e.halfWidthLeftMm,
    contactOffset: e.contactOffsetMm,
    scallopHeight: e.cuspHeightMm,
  };
  if (e.otherCuspHeightMm !== null) exact.otherCuspHeight = e.otherCuspHeightMm;
  const comparison: JsonObject = {};
  for (const [key, , r] of rowsOf(c)) comparison[key] = rowJson(r);
  const target: JsonObject = extras.targetRaMm === undefined ? { h } : { Ra: extras.targetRaMm };
  return {
    unit: 'mm',
    input: { ...inputJson(p), ...target },
    maxInterval: c.maxIntervalMm,
    exact,
    comparison,
    ...extrasJson(extras, e.cuspHeightMm),
  };
}

/** The inverse answer at a doubly curved point as JSON. */
export function doublyCurvedInverseJson(a: DoublyCurvedInverseReport): JsonObject {
  const { pass: p, exact: e, roughness } = a;
  const exact = inverseExactJson(e);
  return {
    unit: 'mm',
    input: { ...inputJson(p), interval: e.intervalMm, halfInterval: e.intervalMm / 2 },
    exact,
    ...extrasJson({ roughness }, e.cuspHeightMm),
  };
}
