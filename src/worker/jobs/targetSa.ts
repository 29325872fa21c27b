/**
 * The `targetSa` job (issue 29): the best pair (L, fz) for a target Sa and the curve of pairs (core
 * roughness/targetSa.ts), of the plane the page answered, with the scallop h at the best step-over.
 * The teeth are validated here by the core (finishInput.ts: whole teeth, runout up to R/10), each
 * refusal one line on its field in the user's unit, its data beside it (a page words it in its
 * language); runout is refused (the inverse does not take it), named as such. Takes seconds (the page shows a waiting line meanwhile); loaded on the first such question.
 */
import { describeFinishError, maxFeedPerToothMm, validateFinish } from '../../core/finish/finishInput';
import { TARGET_SA_RUNOUT, TargetSaTooLongError, targetSaPairs } from '../../core/roughness/targetSa';
import type { TargetSaReply, TargetSaRequest } from '../targetSaProtocol';

/** Answers a target Sa; never throws for a bad value: each is a message on its field. */
export function targetSa(request: TargetSaRequest): TargetSaReply {
  const v = request.values;
  const pass = request.pass;
  // The feed is the answer: any accepted fz stands in for it while the teeth are validated.
  const checked = validateFinish(
    {
      flutes: v.flutes,
      fz: maxFeedPerToothMm(pass.toolRadiusMm),
      runout: v.runout,
      runoutPhase: v.runoutPhase,
      passPhase: v.passPhase,
    },
    pass.toolRadiusMm,
  );
  if (!checked.ok) {
    const errors = checked.errors.map((e) => {
      const field = e.field as keyof TargetSaRequest['typed'];
      const typed = (request.typed[field] ?? '').trim();
      const { message: _english, ...data } = typed === '' ? e : { ...e, got: typed };
      return { field: e.field, message: describeFinishError(data, request.unit), error: data };
    });
    return { ok: false, request, errors };
  }
  const { feedPerToothMm: _feed, ...teeth } = checked.value;
  if (teeth.runoutMm > 0)
    return { ok: false, request, errors: [{ field: 'runout', message: TARGET_SA_RUNOUT, refusal: 'runout' }] };
  let answer: ReturnType<typeof targetSaPairs>;
  try {
    answer = targetSaPairs(pass, teeth, request.targetSaMm);
  } catch (e) {
    // A search past its budget: said on the target field, never a number.
    if (!(e instanceof TargetSaTooLongError)) throw e;
    return { ok: false, request, errors: [{ field: 'flutes', message: e.message, refusal: 'tooLong' }] };
  }
  return { ok: true, request, answer };
}
