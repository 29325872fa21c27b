/**
 * The finish box's worker messages in the language in force (issue 30): the worker words each
 * refusal in English (core/finish/finishInput.ts describeFinishError, envelope.ts
 * finishFailureWords) and sends its data with it (the field, the code, the bound, what was typed; or
 * which failure of which part); another language words the same data from its catalogue's
 * `finishText`, the field named as the page names it, the bound in the user's unit with the locale's
 * decimal sign. English keeps the worker's sentence. Loaded with the finish box.
 */
import { MAX_FLUTES } from '../../core/finish/finishInput';
import type { FinishSurfaceKind } from '../../core/finish/finishScope';
import { quotedEntry } from '../../core/input/entryMessages';
import type { PageFieldKey } from '../../core/input/fields';
import { formatInputNumber, fromMm, type LengthUnit, unitSymbol } from '../../core/input/units';
import type { FinishFieldMessage } from '../../worker/finishProtocol';
import type { TargetSaMessage } from '../../worker/targetSaProtocol';
import type { Catalogue } from './catalogue';
import { localDecimal } from './langChoice';

/** The page's text field of each finish field (its label in the catalogue). */
const PAGE_KEY: Readonly<Record<FinishFieldMessage['field'], PageFieldKey>> = {
  flutes: 'z',
  fz: 'fz',
  feedRate: 'F',
  spindleSpeed: 'n',
  runout: 'runout',
  runoutPhase: 'runoutPhase',
  passPhase: 'passPhase',
};

/** A finish field's refusal in `catalogue`'s language (null: English, the worker's own sentence). */
export function finishMessageIn(catalogue: Catalogue | null, m: FinishFieldMessage, unit: LengthUnit): string {
  if (catalogue === null) return m.message;
  if (m.failure !== undefined) return catalogue.finishText.failure(m.failure.kind, m.failure.part);
  const e = m.error;
  if (e === undefined) return m.message;
  const u = unitSymbol(unit);
  const isLength = e.field === 'fz' || e.field === 'runout';
  const length = (mm: number) => localDecimal(`${formatInputNumber(fromMm(mm, unit))} ${u}`, catalogue);
  const limit =
    e.limit === undefined ? '' : isLength ? length(e.limit) : localDecimal(formatInputNumber(e.limit), catalogue);
  const rate = Number(e.got);
  return catalogue.finishText.errors[e.code]({
    field: e.field,
    label: catalogue.fields[PAGE_KEY[e.field]].label,
    got: quotedEntry(e.got),
    limit,
    unit: e.field === 'feedRate' ? `${u}/min` : e.field === 'spindleSpeed' ? 'rpm' : isLength ? u : '',
    rateFz: Number.isFinite(rate) ? length(rate) : e.got,
    maxFlutes: MAX_FLUTES,
  });
}

/** The surfaces whose refusal the catalogues word by name. */
const SCOPES = ['cylinder', 'doublyCurved', 'waterlineRevolution'] as const;

/** Where feed marks are not computed, in `catalogue`'s language (null: English, the core's `english`). */
export function finishScopeIn(catalogue: Catalogue | null, kind: FinishSurfaceKind, english: string): string {
  if (catalogue === null) return english;
  const known = SCOPES.find((k) => k === kind);
  return catalogue.finishText.scope(known ?? 'other');
}

/** A target-Sa box's message in `catalogue`'s language (null: English, the worker's own sentence). */
export function targetSaMessageIn(catalogue: Catalogue | null, m: TargetSaMessage, unit: LengthUnit): string {
  if (catalogue === null || m.refusal === undefined) return finishMessageIn(catalogue, m, unit);
  return catalogue.finishText.targetSa[m.refusal];
}
