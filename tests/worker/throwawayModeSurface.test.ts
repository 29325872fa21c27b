/**
 * The registries' promise, "one module and one line" (issue 27 point 3): a throwaway surface
 * (tests/support/throwaway/drumSurface.ts) and a throwaway machine mode (fixedLeadMode.ts), each one
 * module and one registry line (registerSurfaceModel, registerMode: from this test), are validated
 * and answered by the core's one question (surfaces/question.ts), the page's builder of such a
 * question (ui/questionRequest.ts, from the state's fields in mm and in inches), the command line's
 * reader (cli/question.ts answerRegistryQuestion) and the worker's one `solve` job (workerApi.ts:
 * the lazily loaded page job) with no other change; a combination the mode has
 * no posture for is refused in its one line; removing them leaves both registries and every answer
 * as before.
 */
import { afterEach, describe, expect, it } from 'vitest';
import { answerRegistryQuestion } from '../../src/cli/question';
import { modeKinds, registerMode } from '../../src/core/surfaces/modes';
import { type Question, validateQuestion } from '../../src/core/surfaces/question';
import { registerSurfaceModel, surfaceKinds } from '../../src/core/surfaces/registry';
import { exactForward, exactInverse } from '../../src/core/surfaces/solve';
import { buildQuestionRequest } from '../../src/ui/registryQuestionRequest';
import { type CalculatorState, defaultState } from '../../src/ui/state';
import type { QuestionReply, QuestionRequest } from '../../src/worker/pageProtocol';
import { workerApi } from '../../src/worker/workerApi';
import { DRUM_AS_CYLINDER, drumModel } from '../support/throwaway/drumSurface';
import { fixedLeadMode } from '../support/throwaway/fixedLeadMode';

const TOOL = { toolRadiusMm: 5, cornerRadiusMm: 1.5 };
const drumQuestion = (target: Question['target'], lead = 12): Question => ({
  tool: TOOL,
  mode: { kind: 'throwawayFixedLead', leadAngleDeg: lead } as Question['mode'],
  surface: { kind: 'throwawayDrum' },
  pattern: 'zigzag',
  target,
});
const productQuestion: Question = {
  tool: TOOL,
  mode: { kind: 'threeAxis', slopeDeg: 30, passes: 'raster', rasterAngleDeg: 20 } as Question['mode'],
  surface: { kind: 'plane' },
  pattern: 'one-way',
  target: { quantity: 'h', mm: 0.01 },
};

async function ask(input: Question): Promise<QuestionReply> {
  const request: QuestionRequest = { mode: 'question', input };
  return (await workerApi.solve(request)) as QuestionReply;
}

let removers: Array<() => void> = [];
afterEach(() => {
  for (const remove of removers) remove();
  removers = [];
});

const KINDS = { mode: 'throwawayFixedLead', surface: 'throwawayDrum' };

/** The page's state of the drum question: R 5, Rcr 1.5, lead 12, zigzag, h 0.01 mm (or in inches). */
function pageState(unit: 'mm' | 'in', fields: Partial<CalculatorState['fields']> = {}): CalculatorState {
  const s = defaultState(unit);
  const inch = (mm: number) => String(mm / 25.4);
  const lengths = unit === 'mm' ? { R: '5', Rcr: '1.5', h: '0.01' } : { R: inch(5), Rcr: inch(1.5), h: inch(0.01) };
  return { ...s, size: 'R', pattern: 'zigzag', fields: { ...s.fields, ...lengths, rho: '12', ...fields } };
}

describe('a throwaway surface and mode: one module and one line each', () => {
  it('unregistered, they are refused by validation and the worker, each in one line naming it', async () => {
    const v = validateQuestion(drumQuestion({ quantity: 'h', mm: 0.01 }));
    expect(!v.ok && v.errors.map((e) => e.message)).toEqual([
      'No machine mode of kind "throwawayFixedLead" is registered.',
      'No surface model of kind "throwawayDrum" is registered.',
    ]);
    const reply = await ask(drumQuestion({ quantity: 'h', mm: 0.01 }));
    expect(reply.ok).toBe(false);
    const built = buildQuestionRequest(pageState('mm'), KINDS);
    expect(!built.ok && built.errors.map((e) => e.message)).toEqual([
      'No machine mode of kind "throwawayFixedLead" is registered.',
      'No surface model of kind "throwawayDrum" is registered.',
    ]);
    const cli = answerRegistryQuestion({ R: '5', Rcr: '1.5', h: '0.01' }, KINDS, 'h');
    expect(cli.ok).toBe(false);
  });

  it('registered, validation and the worker job answer them: the cylinder R100 at lead 12, tilt 0, both ways', async () => {
    const kindsBefore = [modeKinds(), surfaceKinds()];
    const product = await ask(productQuestion);
    removers.push(registerSurfaceModel(drumModel), registerMode(fixedLeadMode));
    expect(modeKinds()).toContain('throwawayFixedLead');
    expect(surfaceKinds()).toContain('throwawayDrum');

    const tool = { ...TOOL, leadAngleDeg: 12, tiltAngleDeg: 0 };
    const h = 0.01;
    const own = exactForward({ ...tool, pattern: 'zigzag', surface: DRUM_AS_CYLINDER, scallopHeightMm: h });
    const forward = await ask(drumQuestion({ quantity: 'h', mm: h }));
    if (!forward.ok) throw new Error(JSON.stringify(forward.errors));
    expect(forward.answer.intervalMm).toBe(own.intervalMm);
    expect(forward.answer.posture).toEqual({ leadAngleDeg: 12, tiltAngleDeg: 0, pattern: 'zigzag' });
    const L = 0.8 * own.intervalMm;
    const inverse = await ask(drumQuestion({ quantity: 'interval', mm: L }));
    if (!inverse.ok) throw new Error(JSON.stringify(inverse.errors));
    expect(inverse.answer.cuspHeightMm).toBe(
      exactInverse({ ...tool, pattern: 'zigzag', surface: DRUM_AS_CYLINDER, intervalMm: L }).cuspHeightMm,
    );

    // The page's builder, in mm and in inches, asks the worker the same question (its request answered alike).
    for (const unit of ['mm', 'in'] as const) {
      const built = buildQuestionRequest(pageState(unit), KINDS);
      if (!built.ok) throw new Error(JSON.stringify(built.errors));
      const reply = (await workerApi.solve(built.request)) as QuestionReply;
      expect(reply.ok && Math.abs(reply.answer.intervalMm - own.intervalMm)).toBeLessThan(1e-12 * own.intervalMm);
    }
    const pageSteep = buildQuestionRequest(pageState('mm', { rho: '45' }), KINDS);
    expect(!pageSteep.ok && pageSteep.errors).toEqual([
      { key: 'rho', message: 'Lead angle must be from 0 to 30 degrees on this head (got 45).' },
    ]);
    // A refusal in inches on the page: the limit in inches, the value quoted as typed.
    const wideInch = buildQuestionRequest({ ...pageState('in', { L: '0.7874' }), mode: 'inverse' }, KINDS);
    expect(!wideInch.ok && wideInch.errors.map((e) => ('key' in e ? e.key : null))).toEqual(['L']);
    expect(!wideInch.ok && wideInch.errors[0]?.message).toMatch(
      /^Step-over L must be below 0\.\d+ in here \(got 0\.7874\): passes this far apart leave a wall\.$/,
    );
    // The command line's reader (options by the field registry's names, lengths in mm).
    const cli = answerRegistryQuestion({ R: '5', Rcr: '1.5', rho: '12', pattern: 'zigzag', h: '0.01' }, KINDS, 'h');
    expect(cli.ok && cli.answer.intervalMm).toBe(own.intervalMm);

    // The mode's own parameters, its refusal on a surface it has no posture for, and the drum's limits.
    const steep = await ask(drumQuestion({ quantity: 'h', mm: h }, 45));
    expect(!steep.ok && steep.errors.map((e) => e.message)).toEqual([
      'Lead angle must be from 0 to 30 degrees on this head (got 45).',
    ]);
    const onPoint = await ask({
      ...drumQuestion({ quantity: 'h', mm: h }),
      surface: { kind: 'doublyCurved', feedRadiusMm: 50, crossRadiusMm: 50 } as Question['surface'],
    });
    expect(!onPoint.ok && onPoint.errors.map((e) => e.message)).toEqual([
      'The fixed-lead head has no posture on a surface of kind "doublyCurved": the plane or the drum only.',
    ]);
    const wide = await ask(drumQuestion({ quantity: 'interval', mm: 20 }));
    expect(!wide.ok && wide.errors[0]?.message).toMatch(/^Step-over L must be below \d+(\.\d+)? mm here \(got 20\)/);
    // A product mode over the throwaway surface: five-axis has a posture everywhere.
    const five = await ask({
      ...drumQuestion({ quantity: 'h', mm: h }),
      mode: { kind: 'fiveAxis', leadAngleDeg: 12, tiltAngleDeg: 0 } as Question['mode'],
    });
    expect(five.ok && five.answer.intervalMm).toBe(own.intervalMm);

    // Removed: the registries and the answers are as before.
    for (const remove of removers) remove();
    removers = [];
    expect([modeKinds(), surfaceKinds()]).toEqual(kindsBefore);
    expect((await ask(drumQuestion({ quantity: 'h', mm: h }))).ok).toBe(false);
    const again = await ask(productQuestion);
    expect(again.ok && product.ok && again.answer).toEqual(product.ok && product.answer);
  });
});
