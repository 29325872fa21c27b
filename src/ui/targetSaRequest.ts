/**
 * The target-Sa question the inputs on screen ask (issue 29), built from the answer on screen: with
 * `target=sa` the page's request is the target Ra at Ra = Sa (fiveAxisRequest.ts: the curve's end L0,
 * where fz -> 0), whose validated pass and target this takes, with the teeth fields as the page holds
 * them (the feed's fields are not read: fz is the answer). Only a plane's answer asks: the page
 * refuses a target Sa elsewhere before it asks the solver. Pure; loaded with the target-Sa box.
 */
import { isSolveReply, type PageReply } from '../worker/pageProtocol';
import type { TargetSaField, TargetSaRequest } from '../worker/targetSaProtocol';
import type { FinishInputs } from './finishRequest';

/** The teeth fields a target Sa reads, in the request's order. */
const TEETH: readonly TargetSaField[] = ['flutes', 'runout', 'runoutPhase', 'passPhase'];

/** The request for the answer on screen (a target Ra's on a plane, standing for the target Sa), or null. */
export function targetSaAsk(inputs: FinishInputs, reply: PageReply | null): TargetSaRequest | null {
  if (reply === null || !isSolveReply(reply) || !reply.ok || reply.request.mode !== 'ra') return null;
  const { targetRaMm, ...pass } = reply.request.input;
  if (pass.surface.kind !== 'plane') return null;
  const values = Object.fromEntries(TEETH.map((f) => [f, inputs.values[f]])) as TargetSaRequest['values'];
  const typed = Object.fromEntries(TEETH.map((f) => [f, inputs.typed[f]])) as TargetSaRequest['typed'];
  return { pass, targetSaMm: targetRaMm, values, typed, unit: inputs.unit };
}
