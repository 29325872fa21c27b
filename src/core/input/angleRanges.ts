/**
 * The five-axis posture's angle rules, stated once (the field registry's rho and tilt ranges say
 * the same in words and numbers: tests/core/surfaces/fiveAxisRanges.test.ts checks them against
 * these): both the validation (surfaces/validate.ts) and the five-axis machine mode
 * (surfaces/modes/fiveAxis.ts) ask these. A leaf, so that the page's first script takes it without
 * the mode registry. Angles degrees.
 */

/** True for a lead angle the posture takes: 0 <= rho < 90 degrees (NaN: false). */
export function leadAngleInRange(deg: number): boolean {
  return deg >= 0 && deg < 90;
}

/** True for a tilt angle the posture takes: -90 < tilt < 90 degrees (NaN: false). */
export function tiltAngleInRange(deg: number): boolean {
  return deg > -90 && deg < 90;
}
