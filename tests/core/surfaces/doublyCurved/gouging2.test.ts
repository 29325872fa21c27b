/** Gouging at a doubly curved point: limits against the brute force (part 2 of 2, run in parallel). */
import { describe, it } from 'vitest';
import { checkGougingCase, describeCase, GOUGING_CASES } from './gougingCases';

describe('doubly curved gouging against the brute force (part 2)', () => {
  for (const c of GOUGING_CASES.slice(4, 8)) it(describeCase(c), () => checkGougingCase(c));
});
