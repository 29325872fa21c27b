/**
 * The reference data set's strata, in file order (stratum i draws from seed REFERENCE_SEED + i, so
 * append new strata at the end to keep the others' rows).
 */
import type { Stratum } from '../draft.ts';
import { planeInverse, planeLead, planePostureOneWay, planeRoughness, planeZigzag } from './plane.ts';

export const STRATA: readonly Stratum[] = [planeLead, planePostureOneWay, planeZigzag, planeInverse, planeRoughness];
