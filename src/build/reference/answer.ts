/**
 * The calculator's answer to one row of the reference data set, from the row's inputs as text:
 * the same validation and solvers the command line's batch uses (a slope row is three-axis, a row
 * with a feed or cross radius a doubly curved point, else a plane or a cylinder), so the generator
 * writes it and the check (tests/build/referenceData.test.ts) solves it again the same way.
 */

import { validateDoublyCurved } from '../../core/roughness/doublyCurvedValidate.ts';
import { exactRoughness, scallopHeightForRaMm, validateTargetRa } from '../../core/roughness/roughness.ts';
import { doublyCurvedForward, doublyCurvedInverse } from '../../core/surfaces/doublyCurved/solve.ts';
import { exactForward, exactInverse } from '../../core/surfaces/solve.ts';
import { validateForward, validateInverse } from '../../core/surfaces/validate.ts';
import { solveThreeAxis } from '../../core/threeAxis/solve.ts';
import { validateThreeAxis } from '../../core/threeAxis/validate.ts';
import type { ReferenceRow } from './columns.ts';

/** The quantities a row asks. */
export type ReferenceQuantity = 'interval' | 'scallopHeight' | 'Rz' | 'Ra' | 'Rq' | 'errorLimit';

/** What the calculator answers to a row: a value (mm), or the first error with its code, field and limit. */
export type CalculatorAnswer =
  | { readonly ok: true; readonly valueMm: number }
  | { readonly ok: false; readonly code: string; readonly field: string; readonly limit: number | null };

interface FirstError {
  readonly code: string;
  readonly field: string;
  /** Absent (core input errors) or null (three-axis errors) where the fault has no limit. */
  readonly limit?: number | null;
}

function refused(errors: readonly FirstError[]): CalculatorAnswer {
  const e = errors[0];
  if (e === undefined) throw new Error('a refused input without an error');
  return { ok: false, code: e.code, field: e.field, limit: e.limit ?? null };
}

const cell = (row: ReferenceRow, name: string): string => row[name] ?? '';
/** An optional input: undefined when empty (its default), as the batch reads an empty cell. */
const optional = (row: ReferenceRow, name: string): string | undefined =>
  cell(row, name) === '' ? undefined : cell(row, name);

/** A row's inputs by name: the tool's always (as text), the others named, optional ones undefined when empty. */
interface RawRow {
  readonly R: string;
  readonly Rcr: string;
  readonly rho: string;
  readonly [name: string]: string | undefined;
}

function rawOf(row: ReferenceRow, required: readonly string[], optionals: readonly string[]): RawRow {
  const raw: Record<string, string | undefined> = {};
  for (const name of required) raw[name] = cell(row, name);
  for (const name of optionals) raw[name] = optional(row, name);
  return { ...raw, R: cell(row, 'R'), Rcr: cell(row, 'Rcr'), rho: cell(row, 'rho') };
}

/** A three-axis row (slope given): forward (h to L) or inverse (L to the cusp height). */
function threeAxisAnswer(row: ReferenceRow): CalculatorAnswer {
  const raw = rawOf(row, ['slope', 'passes', 'rasterAngle', 'feedRadius', 'crossRadius', 'tilt'], []);
  const forward = row.mode === 'forward';
  const v = validateThreeAxis(raw, forward ? 'h' : 'interval', forward ? cell(row, 'h') : cell(row, 'interval'));
  if (!v.ok) return refused(v.errors);
  const r = solveThreeAxis(v.value);
  if (!r.ok) return refused(r.errors);
  return { ok: true, valueMm: forward ? r.value.intervalMm : r.value.cuspHeightMm };
}

/** A doubly curved point (a feed or cross radius given, no slope). */
function doublyCurvedAnswer(row: ReferenceRow): CalculatorAnswer {
  const raw = rawOf(row, ['feedRadius', 'crossRadius'], ['tilt', 'pattern']);
  const forward = row.mode === 'forward';
  const v = validateDoublyCurved(raw, forward ? 'h' : 'interval', forward ? cell(row, 'h') : cell(row, 'interval'));
  if (!v.ok) return refused(v.errors);
  const p = v.value;
  if (forward) return { ok: true, valueMm: doublyCurvedForward({ ...p, scallopHeightMm: p.valueMm }).intervalMm };
  return { ok: true, valueMm: doublyCurvedInverse({ ...p, intervalMm: p.valueMm }).cuspHeightMm };
}

/** A plane or a cylinder: forward, inverse, roughness or a target Ra. */
function passAnswer(row: ReferenceRow): CalculatorAnswer {
  const tool = rawOf(row, ['surfaceRadius'], ['tilt', 'pattern', 'surfaceAxis']);
  if (row.mode === 'inverse') {
    const v = validateInverse({ ...tool, interval: cell(row, 'interval') });
    if (!v.ok) return refused(v.errors);
    return { ok: true, valueMm: exactInverse(v.value).cuspHeightMm };
  }
  if (row.mode === 'target-ra') {
    const v = validateTargetRa({ ...tool, ra: cell(row, 'Ra') });
    if (!v.ok) return refused(v.errors);
    const t = v.value;
    return { ok: true, valueMm: scallopHeightForRaMm(t, t.pattern, t.targetRaMm, t.surface) };
  }
  const v = validateForward({ ...tool, h: cell(row, 'h') });
  if (!v.ok) return refused(v.errors);
  if (row.mode === 'forward') return { ok: true, valueMm: exactForward(v.value).intervalMm };
  const r = exactRoughness(v.value);
  const q = row.quantity;
  return { ok: true, valueMm: q === 'Rz' ? r.rzMm : q === 'Ra' ? r.raMm : r.rqMm };
}

/**
 * The calculator's answer to a row (its inputs and `mode`, and `quantity` for roughness rows).
 * Throws only on a row the data set never holds (an unknown mode).
 */
export function calculatorAnswer(row: ReferenceRow): CalculatorAnswer {
  if (!['forward', 'inverse', 'roughness', 'target-ra'].includes(cell(row, 'mode')))
    throw new Error(`row ${row.id}: unknown mode "${row.mode}"`);
  if (cell(row, 'slope') !== '') return threeAxisAnswer(row);
  if (cell(row, 'feedRadius') !== '' || cell(row, 'crossRadius') !== '') return doublyCurvedAnswer(row);
  return passAnswer(row);
}
