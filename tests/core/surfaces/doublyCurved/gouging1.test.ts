/** Gouging at a doubly curved point: limits against the brute force (part 1 of 2, run in parallel). */
import { describe, it } from 'vitest';
import { checkGougingCase, describeCase, GOUGING_CASES } from './gougingCases';

describe('doubly curved gouging against the brute force (part 1)', () => {
  for (const c of GOUGING_CASES.slice(0, 4)) it(describeCase(c), () => checkGougingCase(c));
});
