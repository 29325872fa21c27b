/**
 * The finish question between the page and the worker (issue 29; shared/notes/surface-finish.md):
 * the surface the teeth leave on the plane whose step-over the page has answered. Plain data
 * (structured-clone safe). Every reply echoes its request, and the page shows a reply only while
 * its request is the one the inputs on screen ask (sameFinishRequest). Lengths mm, angles degrees.
 */
import type { FinishError, FinishField } from '../core/finish/finishInput';
import type { FinishReport } from '../core/finish/index';
import type { FinishProfiles } from '../core/finish/profiles';
import type { LengthUnit } from '../core/input/units';
import type { PassPattern, ToolInput } from '../core/input/validate';
import type { TeethSurface } from './teethSurface';

/** A finish field's value: a number in mm (lengths) or degrees, its text when it is not one, undefined when empty. */
export type FinishValue = number | string | undefined;

/** The feed marks and areal parameters of passes `intervalMm` apart of a validated tool on a plane. */
export interface FinishRequest {
  readonly tool: ToolInput;
  readonly pattern: PassPattern;
  /** The step-over L of the answer on screen, and its scallop h (mm). */
  readonly intervalMm: number;
  readonly scallopMm: number;
  /** The finish fields as the page holds them (mm, degrees), validated in the worker. */
  readonly values: Readonly<Record<FinishField, FinishValue>>;
  /** The texts as typed (quoted by the messages) and the unit the messages speak. */
  readonly typed: Readonly<Record<FinishField, string>>;
  readonly unit: LengthUnit;
  /**
   * What to compute: the feed marks (hf, period, fz*: fast, shown first) or the areal parameters
   * (slower: asked of a worker of their own, so they never hold the feed marks back).
   */
  readonly part: 'marks' | 'areal';
  /**
   * The three-axis question this plane stands for (its sloped plane at the equivalent posture), as a
   * file name names it (`3-axis_slope30_raster30`, `3-axis_slope30_waterline`); left out on five axes.
   */
  readonly threeAxisName?: string;
  /** Instead, the x3p file of one period cell (`size` by `size` points), named `fileName`. */
  readonly x3p?: { readonly size: number; readonly fileName: string; readonly comment: string };
}

/** Points along each side of the cell's height map drawn on the page. */
export const MAP_SIZE = 256;

/** Points of each profile drawn on the page (along: two feed periods; across: one cross period). */
export const PROFILE_POINTS = 193;

/** One finish field's refusal, worded in the request's unit (the constraint and its limit). */
export interface FinishFieldMessage {
  readonly field: FinishField;
  readonly message: string;
  /** What the message says, as data, for a page to word in its language: the field's refusal (`got` as typed)... */
  readonly error?: Omit<FinishError, 'message'>;
  /** ...or why the part could not be computed (core envelope.ts finishFailureKind), of which part. */
  readonly failure?: { readonly kind: 'not-converged' | 'not-swept'; readonly part: 'marks' | 'areal' };
}

/** The part of the finish asked (the other null), or with `x3p` asked only the file's bytes; or why not. */
export type FinishReply =
  | {
      readonly ok: true;
      readonly request: FinishRequest;
      readonly feedMarks: FinishReport['feedMarks'] | null;
      readonly areal: FinishReport['areal'] | null;
      readonly x3p: Uint8Array | null;
      /** With the areal parameters: one cell's heights (mm, MAP_SIZE x MAP_SIZE, row i + n j: x along the feed). */
      readonly map: Float32Array | null;
      /**
       * With the areal parameters: the profiles along the CC path (two feed periods) and across the
       * feed (one cross period, at the x of the highest feed mark), PROFILE_POINTS each (core profiles.ts).
       */
      readonly profiles?: FinishProfiles | null;
      /** With the areal parameters: the surface over several cells the Machined surface view draws in 3D. */
      readonly surface?: TeethSurface | null;
    }
  | { readonly ok: false; readonly request: FinishRequest; readonly errors: readonly FinishFieldMessage[] };

/** True when both ask the same question (plain data built in one order by the page: compared as JSON). */
export function sameFinishRequest(a: FinishRequest | null, b: FinishRequest | null): boolean {
  return a !== null && b !== null && JSON.stringify(a) === JSON.stringify(b);
}
