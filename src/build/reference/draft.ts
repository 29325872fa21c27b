/**
 * What a stratum of the reference data set proposes: a row's inputs, what it asks, and how its
 * independent reference is computed (run by the generator only after the calculator has answered
 * the row, so a refused or non-finite row costs no brute force). Shared helpers for drawing cases.
 */
import type { ReferenceQuantity } from './answer.ts';

/** An independent reference value of a row's quantity. */
export interface ReferenceValue {
  readonly valueMm: number;
  /** The method's own stated uncertainty, mm. */
  readonly uncertaintyMm: number;
  /** The method's key (the JSON description's `methods`). */
  readonly method: string;
  /** Methods that polish from a sampled brute force: its value and stated bound, mm. */
  readonly sampledMm?: number;
  readonly sampledBoundMm?: number;
}

/** A proposed row. Inputs are numbers (written in full) or text; absent inputs stay empty. */
export interface Draft {
  readonly stratum: string;
  readonly mode: 'forward' | 'inverse' | 'roughness' | 'target-ra';
  readonly quantity: ReferenceQuantity;
  readonly inputs: Readonly<Record<string, number | string>>;
  /** The reference, given the calculator's answer (mm; NaN for a refused row); null where none applies. */
  readonly reference: (answerMm: number) => ReferenceValue | null;
}

/** A stratum: a name, how many rows it proposes, and the proposals from its own seeded generator. */
export interface Stratum {
  readonly name: string;
  readonly count: number;
  readonly drafts: (rand: () => number, count: number) => Iterable<Draft>;
}

/** A value rounded to `digits` significant digits, so that inputs read as a person would type them. */
export function sig(x: number, digits = 6): number {
  return x === 0 ? 0 : Number(x.toPrecision(digits));
}

/** Log-uniform in [lo, hi]. */
export function logUniform(rand: () => number, lo: number, hi: number): number {
  return lo * (hi / lo) ** rand();
}

/** The three tool ends the strata cycle through. */
export const TOOL_KINDS = ['ball', 'bull-nose', 'flat'] as const;
export type ToolKind = (typeof TOOL_KINDS)[number];

/** A tool of the given kind with R log-uniform in [rLo, rHi] mm, 6 significant digits. */
export function drawTool(rand: () => number, kind: ToolKind, rLo: number, rHi: number): { R: number; Rcr: number } {
  const R = sig(logUniform(rand, rLo, rHi));
  const Rcr = kind === 'ball' ? R : kind === 'flat' ? 0 : sig(R * (0.05 + 0.9 * rand()));
  return { R, Rcr };
}

/** A signed angle of size in [lo, hi] degrees, 4 significant digits. */
export function signedAngle(rand: () => number, lo: number, hi: number): number {
  return sig((rand() < 0.5 ? -1 : 1) * (lo + (hi - lo) * rand()), 4);
}

/** A row's tool and posture inputs, tilt and pattern left empty at their defaults (0, one-way), as a user would. */
export function toolInputs(R: number, Rcr: number, rho: number, tilt: number, pattern: 'one-way' | 'zigzag') {
  return {
    R,
    Rcr,
    rho,
    ...(tilt === 0 ? {} : { tilt }),
    ...(pattern === 'one-way' ? {} : { pattern }),
  };
}
