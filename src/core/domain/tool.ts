/**
 * The tool and its posture, and how adjacent passes run: domain types shared by every layer of the
 * core (validation, tool geometry, surfaces, procedures). Types only: this module imports nothing,
 * so it sits below every other core module and closes no import cycle.
 */

/** A validated tool and posture: lengths in mm, angles in degrees. */
export interface ToolInput {
  /** Tool radius `R` in mm, 0.001 <= R <= 1000 (input/validate.ts's MIN_ and MAX_TOOL_RADIUS_MM). */
  readonly toolRadiusMm: number;
  /** Corner (tip) radius `Rcr` in mm, 0 <= Rcr <= R. */
  readonly cornerRadiusMm: number;
  /** Lead angle `rho` (inclination along the feed) in degrees, 0 <= rho < 90. */
  readonly leadAngleDeg: number;
  /** Tilt angle `beta` (inclination across the feed, + leans the shank to +Y) in degrees, -90 < beta < 90. */
  readonly tiltAngleDeg: number;
}

/** How adjacent passes run: every pass the same way, or alternating (posture relative to the feed). */
export type PassPattern = 'one-way' | 'zigzag';

/** Both pass patterns, in the order the page and the tables list them. */
export const PASS_PATTERNS: readonly PassPattern[] = ['one-way', 'zigzag'];
