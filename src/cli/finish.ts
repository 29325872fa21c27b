/**
 * The surface the teeth leave, on the command line (issue 29; shared/notes/surface-finish.md):
 * with `--flutes` and `--fz` (and optionally `--runout`, `--runout-phase`, `--pass-phase`; the field
 * registry's finish fields) a plane's answer adds the feed marks (hf, its period, the balanced feed
 * fz*) and the areal parameters (Sa ... Sku). Where they are not computed (cylinders, doubly curved
 * points, waterline) the question is refused in one line, never answered as if the tool swept
 * continuously. Lengths mm (the values are already in mm: lengthInput.ts).
 */

import type { PassPattern, ToolInput } from '../core/domain/tool';
import { finishFailureWords } from '../core/finish/envelope';
import type { FinishError, FinishField, FinishInput } from '../core/finish/finishInput';
import { describeFinishError } from '../core/finish/finishInput';
import { type FinishReport, finishReport, finishScopeError, validateFinish } from '../core/finish/index';
import { cliFlag, FINISH_FIELD_IDS, type FieldId } from '../core/input/fields';
import { fromMm, type LengthUnit } from '../core/input/units';
import { csvNumber } from '../core/output/csvWrite';
import type { ValueOption } from './args';
import { indent, KEY_VALUE } from './reportExtras';
import { type Lengths, renderTable } from './table';
import type { X3pFacts } from './x3pOption';

/** The finish fields in the registry's order, with their options (without `--`). */
export const FINISH_FIELDS = FINISH_FIELD_IDS as readonly FinishField[];

/** The option of a finish field, without `--`. */
export function finishOption(field: FinishField): ValueOption {
  return cliFlag(field as FieldId).slice(2) as ValueOption;
}

type Values = Readonly<Partial<Record<ValueOption, string>>>;

/** True when any finish option is given (then --flutes and --fz are both needed: args.ts). */
export function finishRequested(values: Values): boolean {
  return FINISH_FIELDS.some((f) => values[finishOption(f)] !== undefined);
}

/** A finish computed, or why not (input errors, or the surface where it is not computed yet). */
export type { FinishError };
export type FinishRun =
  | { readonly ok: true; readonly input: FinishInput; readonly report: FinishReport }
  | { readonly ok: false; readonly errors: readonly FinishError[] };

/** The refusal of the finish options on a surface where feed marks are not computed yet (named by --flutes). */
export function finishScopeRefusal(surfaceKind: string): FinishError {
  return { field: 'flutes', code: 'not-computed-here', got: '', message: finishScopeError(surfaceKind) ?? '' };
}

/**
 * The finish of passes `intervalMm` apart (mm) of a validated tool on `surfaceKind` ('plane' for
 * the five-axis plane and the three-axis sloped plane), from the options' values in mm.
 */
export function finishOf(
  values: Values,
  tool: ToolInput,
  pattern: PassPattern,
  intervalMm: number,
  surfaceKind: string,
): FinishRun {
  if (finishScopeError(surfaceKind) !== null) return { ok: false, errors: [finishScopeRefusal(surfaceKind)] };
  const v = validateFinish(
    {
      flutes: values[finishOption('flutes')],
      fz: values[finishOption('fz')],
      feedRate: values[finishOption('feedRate')],
      spindleSpeed: values[finishOption('spindleSpeed')],
      runout: values[finishOption('runout')],
      runoutPhase: values[finishOption('runoutPhase')],
      passPhase: values[finishOption('passPhase')],
    },
    tool.toolRadiusMm,
  );
  if (!v.ok) return v;
  try {
    return { ok: true, input: v.value, report: finishReport(tool, pattern, intervalMm, v.value) };
  } catch (e) {
    // The feed marks' event search that did not converge (or a surface left undefined): said, never a
    // number. The areal parameters' own failure is finishReport's arealRefusal, beside the marks.
    const message = finishFailureWords(e, 'marks');
    if (message === null) throw e;
    return { ok: false, errors: [{ field: 'fz', code: 'not-computed-here', got: '', message }] };
  }
}

/**
 * A finish error's words in `unit`, quoting the value as typed (`typed`: the options before their
 * unit was read; else the value in mm); a scope refusal is its own sentence.
 */
export function finishErrorWords(e: FinishError, unit: LengthUnit, typed: Values = {}): string {
  if (e.code === 'not-computed-here') return e.message;
  const given = typed[finishOption(e.field)]?.trim();
  return describeFinishError(given === undefined ? e : { ...e, got: given }, unit);
}

/** The option a finish error names. */
export function finishErrorOption(e: FinishError): string {
  return cliFlag(e.field as FieldId);
}

/** What the three-axis report says of its feed marks: the passes the model takes. */
export const THREE_AXIS_FINISH_NOTE =
  'Feed marks on the slope: every pass fed the same way (one-way, in the posture the slope gives); the descending passes of a zigzag raster are not modelled yet.';

/** The report's block: the feed marks and the areal parameters (lengths in the user's unit). */
export function finishLines(
  run: {
    readonly input: FinishInput;
    readonly report: FinishReport;
    readonly x3p?: { readonly file: string; readonly facts: X3pFacts };
  },
  scallopHeightMm: number,
  L: Lengths,
): string[] {
  const { report: r, input } = run;
  const m = r.feedMarks;
  const teeth = `${input.flutes} ${input.flutes === 1 ? 'tooth' : 'teeth'}`;
  const runout =
    input.runoutMm > 0 ? `, runout ${L.echo(input.runoutMm)} ${L.u} at ${input.runoutPhaseDeg} degrees` : '';
  const balanced =
    m.balancedFz === null
      ? ['fz*', '-', '', `no feed makes the marks as tall as the scallop (${L.length(scallopHeightMm)} ${L.u})`]
      : ['fz*', L.length(m.balancedFz), L.u, 'balanced feed per tooth: feed marks as tall as the scallop h'];
  const marks: string[][] = [
    ['hf', L.length(m.height), L.u, 'feed-mark height along the CC path (highest minus lowest)'],
    ['period', L.length(m.period), L.u, input.runoutMm > 0 ? 'one turn (z fz): runout makes the teeth unequal' : 'fz'],
    balanced,
  ];
  const head = [
    `Feed marks (${teeth}, fz ${L.echo(input.feedPerToothMm)} ${L.u}${runout}; straight teeth, M3):`,
    ...indent(renderTable(KEY_VALUE, marks, false)),
    '',
  ];
  const a = r.areal;
  if (a === null) return [...head, `Areal parameters: ${r.arealRefusal ?? ''}`];
  const areal: string[][] = [
    ['Sa', L.length(a.Sa), L.u, 'mean absolute height from the mean plane'],
    ['Sq', L.length(a.Sq), L.u, 'root mean square height'],
    ['Sz', L.length(a.Sz), L.u, 'highest peak to deepest valley (Sp + Sv)'],
    ['Sp', L.length(a.Sp), L.u, 'highest peak above the mean'],
    ['Sv', L.length(a.Sv), L.u, 'deepest valley below the mean'],
    ['Ssk', a.Ssk.toFixed(4), '', 'skewness'],
    ['Sku', a.Sku.toFixed(4), '', 'kurtosis'],
  ];
  const x3p = run.x3p;
  const file =
    x3p === undefined
      ? []
      : [
          '',
          `x3p file written: ${x3p.file} (${x3p.facts.nx} x ${x3p.facts.ny} points over ${x3p.facts.cellsX} x ${x3p.facts.cellsY} cells; ` +
            `dx = ${L.length(x3p.facts.dxMm)} ${L.u}, dy = ${L.length(x3p.facts.dyMm)} ${L.u}; heights in metres, ISO 25178-72)`,
        ];
  return [
    ...head,
    'Areal parameters over one period cell (ISO 25178-2, primary surface, no filter, design plane as reference):',
    ...indent(renderTable(KEY_VALUE, areal, false)),
    ...file,
  ];
}

/** The JSON members: `feedMarks {height, period, balancedFz}` and `areal {Sa ... Sku}` (balancedFz left out where none). */
export function finishJson(
  report: FinishReport,
  x3p?: { readonly file: string; readonly facts: X3pFacts },
): {
  feedMarks: { height: number; period: number; balancedFz?: number };
  /** Left out where the areal surface is not defined, `arealRefusal` saying why. */
  areal?: { [symbol: string]: number };
  arealRefusal?: string;
  x3p?: { [key: string]: string | number };
} {
  const m = report.feedMarks;
  const out: ReturnType<typeof finishJson> = {
    feedMarks: {
      height: m.height,
      period: m.period,
      ...(m.balancedFz === null ? {} : { balancedFz: m.balancedFz }),
    },
    ...(report.areal === null ? { arealRefusal: report.arealRefusal ?? '' } : { areal: { ...report.areal } }),
  };
  if (x3p !== undefined) {
    const f = x3p.facts;
    out.x3p = { file: x3p.file, nx: f.nx, ny: f.ny, cellsX: f.cellsX, cellsY: f.cellsY, dx: f.dxMm, dy: f.dyMm };
  }
  return out;
}

/** The finish's result cells of a batch row (FINISH_RESULT_COLUMNS, each after a comma). */
const EMPTY_CELLS = ','.repeat(10);

/**
 * A batch row's finish cells (batchHeader.ts FINISH_RESULT_COLUMNS, each after a comma; lengths in
 * `unit`): empty without teeth (no finish value in the row), else computed, or the row's error
 * (a bad value, or a surface where feed marks are not computed). `tool` null: a doubly curved point.
 */
export function finishCells(
  values: Values,
  tool: ToolInput | null,
  pattern: PassPattern,
  intervalMm: number,
  surfaceKind: string,
  unit: LengthUnit,
  typed: Values = values,
):
  | { readonly ok: true; readonly text: string; readonly note: string }
  | { readonly ok: false; readonly message: string } {
  if (!finishRequested(values)) return { ok: true, text: EMPTY_CELLS, note: '' };
  const run =
    tool === null
      ? ({ ok: false, errors: [finishScopeRefusal(surfaceKind)] } as const)
      : finishOf(values, tool, pattern, intervalMm, surfaceKind);
  if (!run.ok) return { ok: false, message: run.errors.map((e) => finishErrorWords(e, unit, typed)).join(' ') };
  const { feedMarks: m, areal: a } = run.report;
  const length = (mm: number) => csvNumber(fromMm(mm, unit));
  const marks = [length(m.height), length(m.period), m.balancedFz === null ? '' : length(m.balancedFz)];
  // No areal surface (a flat end lying flat): its cells empty and the row's error column says why.
  const areal =
    a === null
      ? ['', '', '', '', '', '', '']
      : [length(a.Sa), length(a.Sq), length(a.Sz), length(a.Sp), length(a.Sv), csvNumber(a.Ssk), csvNumber(a.Sku)];
  return { ok: true, text: `,${[...marks, ...areal].join(',')}`, note: run.report.arealRefusal ?? '' };
}
