/**
 * The extras of a case's report (report.ts): the roughness block with the rule of thumb beside it,
 * and the simulation block with its stated bounds. Lengths mm.
 */
import type { FinishInput, FinishReport } from '../core/finish/index';
import { PROCEDURES, type Roughness, raRuleOfThumbMm, type SimulationResult } from '../core/index';
import { type Column, type Lengths, lengthsIn, percent, renderTable } from './table';
import type { X3pFacts } from './x3pOption';

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
  /** The surface the teeth leave (--flutes, --fz: feed marks and areal parameters). */
  readonly finish?: {
    readonly input: FinishInput;
    readonly report: FinishReport;
    /** The x3p file written (--x3p): its path and grid. */
    readonly x3p?: { readonly file: string; readonly facts: X3pFacts };
  };
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
export function roughnessLines(r: Roughness, scallopHeightMm: number, L: Lengths = lengthsIn('mm')): string[] {
  const thumb = ruleOfThumb(scallopHeightMm, r.raMm);
  const off =
    thumb.deviationPercent === null
      ? `${L.deviation(thumb.deviationMm)} ${L.u} off`
      : `${L.deviation(thumb.deviationMm)} ${L.u} (${percent(thumb.deviationPercent)} %) off the exact Ra`;
  const facts: string[][] = [
    ['Rz', L.length(r.rzMm), L.u, 'highest peak minus deepest valley'],
    ['Ra', L.length(r.raMm), L.u, 'mean absolute deviation from the mean line'],
    ['Rq', L.length(r.rqMm), L.u, 'root mean square deviation from the mean line'],
    ['h/4', L.length(thumb.raMm), L.u, `rule of thumb Ra ~ h/4: ${off}`],
  ];
  return [
    'Roughness across the feed (exact, ISO 4287 over one period of the passes):',
    ...indent(renderTable(KEY_VALUE, facts, false)),
  ];
}

/** Lines of the simulation block: the simulated values beside the exact ones, with the stated bounds. */
export function simulationLines(
  sim: SimulationRun,
  exactCuspMm: number,
  exact: Roughness | undefined,
  L: Lengths = lengthsIn('mm'),
): string[] {
  if (!sim.ok) return [`Simulation of the passes: ${sim.notApplicable}.`];
  const s = sim.result;
  const vs = (simulated: number, exactMm: number | undefined) =>
    exactMm === undefined ? '' : `; exact minus simulated ${L.deviation(exactMm - simulated)} ${L.u}`;
  const facts: string[][] = [
    [
      'h',
      L.length(s.cuspHeightMm),
      L.u,
      `highest cusp, within ${L.length(s.resolutionBoundMm)} ${L.u}${vs(s.cuspHeightMm, exactCuspMm)}`,
    ],
    [
      'Rz',
      L.length(s.roughness.rzMm),
      L.u,
      `within ${L.length(s.roughnessBoundMm)} ${L.u}${vs(s.roughness.rzMm, exact?.rzMm)}`,
    ],
    [
      'Ra',
      L.length(s.roughness.raMm),
      L.u,
      `within ${L.length(s.roughnessBoundMm)} ${L.u}${vs(s.roughness.raMm, exact?.raMm)}`,
    ],
    [
      'Rq',
      L.length(s.roughness.rqMm),
      L.u,
      `within ${L.length(s.roughnessBoundMm)} ${L.u}${vs(s.roughness.rqMm, exact?.rqMm)}`,
    ],
  ];
  return [
    `Simulation of the passes (the tool solid on a ${s.cellsAcross} x ${s.cellsAlong} height field, ` +
      `${s.placements} placements, ${Math.round(sim.ms)} ms; independent of the exact solver):`,
    ...indent(renderTable(KEY_VALUE, facts, false)),
  ];
}

/** The columns of a block of facts: symbol, value, unit, what it is. */
export const KEY_VALUE: readonly Column[] = [
  { header: '', align: 'left' },
  { header: '', align: 'right' },
  { header: '', align: 'left' },
  { header: '', align: 'left' },
];

/** The lines indented by two spaces (a block under its heading). */
export function indent(lines: readonly string[]): string[] {
  return lines.map((l) => `  ${l}`);
}

/** The exact answer's facts as a block: its procedure's label, then their table indented. */
export function exactBlock(facts: string[][]): string[] {
  return [`${PROCEDURES.exact.label}:`, ...indent(renderTable(KEY_VALUE, facts, false))];
}

/** What a forward answer was given: the scallop height h, or the target Ra it was solved for and that h. */
export function givenHeight(h: number, extras: Extras, L: Lengths): string {
  return extras.targetRaMm === undefined
    ? `Scallop height h = ${L.echo(h)} ${L.u}`
    : `Target roughness Ra = ${L.echo(extras.targetRaMm)} ${L.u}: scallop height h = ${L.length(h)} ${L.u}`;
}

/** The tool's kind, by its corner radius: ball (Rcr = R), flat (Rcr = 0) or filleted. */
export function toolKind(toolRadiusMm: number, cornerRadiusMm: number): string {
  if (cornerRadiusMm === toolRadiusMm) return 'Ball end mill';
  if (cornerRadiusMm === 0) return 'Flat end mill';
  return 'Filleted end mill';
}

/** The flanks' widths and the contact offset as fact rows; `cusp` says which cusp ('the cusp', 'its cusp'). */
export function flankFacts(
  e: { readonly halfWidthRightMm: number; readonly halfWidthLeftMm: number; readonly contactOffsetMm: number },
  L: Lengths,
  cusp: string,
): string[][] {
  return [
    ['wR', L.length(e.halfWidthRightMm), L.u, `right flank (+Y) from the contact, at ${cusp}`],
    ['wL', L.length(e.halfWidthLeftMm), L.u, `left flank (-Y) from the contact, at ${cusp}`],
    ['y0', L.length(e.contactOffsetMm), L.u, 'contact offset: the tool centre point runs -y0 (in Y) from its CC path'],
  ];
}
