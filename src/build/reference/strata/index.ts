/**
 * The reference data set's strata, in file order (stratum i draws from seed REFERENCE_SEED + i, so
 * append new strata at the end to keep the others' rows).
 */
import type { Stratum } from '../draft.ts';
import { cylinderCrossConcave, cylinderCrossConvex, cylinderFeedConcave, cylinderFeedConvex } from './cylinder.ts';
import { doublyCurved } from './doublyCurved.ts';
import { invalidDoublyCurved, invalidPass, invalidTargetRa, invalidThreeAxis } from './invalid.ts';
import { planeInverse, planeLead, planePostureOneWay, planeRoughness, planeTargetRa, planeZigzag } from './plane.ts';
import { threeAxisRaster, threeAxisWaterlinePlane, threeAxisWaterlineRevolution } from './threeAxis.ts';

export const STRATA: readonly Stratum[] = [
  planeLead,
  planePostureOneWay,
  planeZigzag,
  planeInverse,
  planeRoughness,
  cylinderFeedConvex,
  cylinderFeedConcave,
  cylinderCrossConvex,
  cylinderCrossConcave,
  doublyCurved,
  threeAxisRaster,
  threeAxisWaterlinePlane,
  threeAxisWaterlineRevolution,
  invalidPass,
  invalidTargetRa,
  invalidDoublyCurved,
  invalidThreeAxis,
  planeTargetRa,
];
