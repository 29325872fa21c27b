/**
 * The worker's `solve` job for a question over the registries (core surfaces/question.ts): any
 * registered machine mode over any registered surface it has a posture on. The question is
 * validated again (the worker trusts no caller): a refused one gets its one-line errors, never an
 * exception.
 */
import { answerQuestion, validateQuestion } from '../../core/surfaces/question';
import type { QuestionReply, QuestionRequest } from '../pageProtocol';

/** Answers a question over the registries. Never throws for any numeric input. */
export function solveQuestion(request: QuestionRequest): QuestionReply {
  const t0 = performance.now();
  const v = validateQuestion(request.input);
  if (!v.ok) return { ok: false, request, errors: v.errors };
  return { ok: true, request, answer: answerQuestion(v.value), solveMs: performance.now() - t0 };
}
