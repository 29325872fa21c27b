/**
 * The page's questions beyond a plane or a cylinder, and their answers, beside protocol.ts's:
 * a doubly curved point (issue 19: two principal radii, five-axis) and three-axis machining
 * (issue 20: the tool upright on a sloped plane or a surface of revolution). Plain data crossing
 * the worker boundary; lengths mm, angles degrees. Every reply echoes its request, so the page shows
 * a reply only while it answers the inputs on screen (samePageRequest).
 */

import type { InputError } from '../core/input/validate';
import type { DoublyCurvedComparison } from '../core/procedures/compareDoublyCurved';
import type { RoughnessSummary } from '../core/roughness/raTarget';
import type { DoublyCurvedLimits, RadiusLimit } from '../core/surfaces/doublyCurved';
import type {
  DoublyCurvedForward,
  DoublyCurvedForwardInput,
  DoublyCurvedInverseInput,
  DoublyCurvedPass,
} from '../core/surfaces/doublyCurved/types';
import type { Question, QuestionAnswer, QuestionError } from '../core/surfaces/question';
import type { SlopeSweep } from '../core/threeAxis/slopeSweep';
import type { ThreeAxisAnswer, ThreeAxisInputError, ThreeAxisProblem } from '../core/threeAxis/validate';
import type { WaterlineGeometry } from '../core/threeAxis/waterlineRevolution';
import { type SceneGeometry, type SliderLimits, type SolveReply, type SolveRequest, sameRequest } from './protocol';

/** A target roughness at a doubly curved point: Ra (mm, 0 < Ra below the largest the tool leaves there). */
export interface DoublyCurvedRaInput extends DoublyCurvedPass {
  readonly targetRaMm: number;
}

/**
 * A doubly curved point (both radii curved): a scallop height to the step-over, a target Ra to the
 * scallop height that leaves it and its step-over, or a step-over to the cusps.
 */
export type CurvedRequest =
  | { readonly mode: 'curved-forward'; readonly input: DoublyCurvedForwardInput }
  | { readonly mode: 'curved-ra'; readonly input: DoublyCurvedRaInput }
  | { readonly mode: 'curved-inverse'; readonly input: DoublyCurvedInverseInput };

/** True for a doubly curved point's question. */
export function isCurvedRequest(request: PageRequest): request is CurvedRequest {
  return request.mode === 'curved-forward' || request.mode === 'curved-ra' || request.mode === 'curved-inverse';
}

/** Three-axis machining: a validated problem (core/threeAxis/validate.ts). */
export interface ThreeAxisRequest {
  readonly mode: 'three-axis';
  readonly input: ThreeAxisProblem;
}

/** Every question the page's `solve` job takes. */
export type PageRequest = SolveRequest | CurvedRequest | ThreeAxisRequest;

/**
 * A question over the registries (core surfaces/question.ts): any registered machine mode over any
 * registered surface it has a posture on, answered by the surface's model at the mode's posture.
 * The product's own combinations keep their requests above (their replies carry the views' parts);
 * a mode or surface registered beside them is asked this way, with no other change.
 */
export interface QuestionRequest {
  readonly mode: 'question';
  readonly input: Question;
}

/** The answer to a QuestionRequest (the worker validates the question again: it trusts no caller). */
export type QuestionReply =
  | { readonly ok: true; readonly request: QuestionRequest; readonly answer: QuestionAnswer; readonly solveMs: number }
  | { readonly ok: false; readonly request: QuestionRequest; readonly errors: readonly QuestionError[] };

/** Every question the worker's one `solve` job takes: the page's, and any over the registries. */
export type SolverRequest = PageRequest | QuestionRequest;

/** The reply of the `solve` job to a request of type R. */
export type SolverReplyOf<R extends SolverRequest> = R extends QuestionRequest ? QuestionReply : PageReply;

/** True for a question over the registries. */
export function isQuestionRequest(request: SolverRequest): request is QuestionRequest {
  return request.mode === 'question';
}

/** True for a plane's or a cylinder's question (protocol.ts's SolveRequest: the teaching views, the table...). */
export function isSolveRequest(request: SolverRequest): request is SolveRequest {
  return request.mode === 'forward' || request.mode === 'inverse' || request.mode === 'ra';
}

/** True when two plain values (numbers, text, null, arrays and objects of them) are equal. */
function samePlain(a: unknown, b: unknown): boolean {
  if (a === b) return true;
  if (typeof a !== 'object' || typeof b !== 'object' || a === null || b === null) return false;
  const ka = Object.keys(a);
  const kb = Object.keys(b);
  if (ka.length !== kb.length) return false;
  return ka.every((k) => samePlain((a as Record<string, unknown>)[k], (b as Record<string, unknown>)[k]));
}

/** True when both requests ask the same question (every input equal); null equals nothing. */
export function samePageRequest(a: PageRequest | null, b: PageRequest | null): boolean {
  if (a === null || b === null || a.mode !== b.mode) return false;
  if (isSolveRequest(a)) return sameRequest(a, b as SolveRequest);
  return samePlain(a.input, b.input);
}

/**
 * Why a doubly curved input is refused, as data (the page words it in the user's unit): a radius
 * out of range, the tool gouging (each radius's limit with the other held), a scallop height at or
 * above the flanks' or shank's limit, a step-over at or beyond the widest that leaves a scallop.
 */
export type CurvedError =
  | { readonly field: 'feedRadius' | 'crossRadius'; readonly code: 'out-of-range'; readonly gotMm: number }
  | {
      readonly field: 'feedRadius' | 'crossRadius';
      readonly code: 'gouging';
      /** What this radius must be with the other held (gouging.ts). */
      readonly limit: RadiusLimit;
      /** The other radius held, signed mm (Infinity: straight). */
      readonly otherMm: number;
    }
  | {
      readonly field: 'h';
      readonly code: 'above-limit';
      readonly limitMm: number;
      readonly limitBy: DoublyCurvedLimits['limitBy'];
    }
  | { readonly field: 'interval'; readonly code: 'beyond-max'; readonly maxMm: number }
  | { readonly field: 'ra'; readonly code: 'beyond-max-ra'; readonly maxMm: number };

/** The exact answer at a doubly curved point (mm; reaches and L arc lengths along the equator): the forward answer's fields, and these. */
export interface CurvedSummary extends DoublyCurvedForward {
  readonly pattern: DoublyCurvedPass['pattern'];
  /** The widest step-over that leaves a scallop here. */
  readonly maxIntervalMm: number;
  /** The flank and shank limits (radial heights). */
  readonly limits: DoublyCurvedLimits;
}

/** The answer to a doubly curved question. */
export type CurvedReply =
  | {
      readonly ok: true;
      readonly request: CurvedRequest;
      readonly limits: SliderLimits | null;
      readonly exact: CurvedSummary;
      /**
       * Forward: the plane's, each cylinder's and the usual correction's step-overs beside the exact
       * one (core compareDoublyCurved); null for the inverse problem.
       */
      readonly comparison: Omit<DoublyCurvedComparison, 'exact' | 'maxIntervalMm'> | null;
      /**
       * Rz, Ra, Rq along the normal of the surface left at the exact step-over (core
       * roughness/doublyCurved.ts), beside the rule of thumb; its scallopHeightMm is the h a target
       * Ra comes to.
       */
      readonly roughness: RoughnessSummary;
      /** What the 3D scene draws: the torus patch, the tool, the cusps (worker/data/curvedScene.ts). */
      readonly scene: SceneGeometry;
      readonly solveMs: number;
    }
  | {
      readonly ok: false;
      readonly request: CurvedRequest;
      readonly limits: SliderLimits | null;
      /** The tool's and posture's errors (validate.ts), or this point's. */
      readonly errors: readonly (InputError | CurvedError)[];
    };

/** The answer to a three-axis question. */
export type ThreeAxisReply =
  | {
      readonly ok: true;
      readonly request: ThreeAxisRequest;
      readonly limits: SliderLimits | null;
      /** L, Lxy, dz, the cusp and the equivalent lead and tilt (core solveThreeAxis). */
      readonly answer: ThreeAxisAnswer;
      /** Waterline on a surface of revolution: the pair of passes in the meridian plane; null otherwise. */
      readonly waterline: {
        readonly geometry: WaterlineGeometry;
        readonly slopeNextDeg: number;
        readonly radialStepMm: number;
      } | null;
      /**
       * The slope sweep for the chart (200 slopes from 0 to the largest valid one) at the scallop
       * height of this answer, with the step programmed here held constant; null without a scallop.
       */
      readonly sweep: SlopeSweep | null;
      /**
       * On a plane, the slope (degrees) where raster passes (at this raster angle; 0 for waterline)
       * and waterline passes program the same step for this h (core rasterWaterlineCrossingDeg);
       * null where they do not cross or without a scallop.
       */
      readonly crossingDeg: number | null;
      /**
       * On a sloped plane, Rz, Ra, Rq of the one-way passes (the plane's at the equivalent lead and
       * tilt, core roughness/slopedPlane.ts) beside the rule of thumb; null on a surface of revolution
       * (waterline passes there are not congruent: no period to measure over).
       */
      readonly roughness: RoughnessSummary | null;
      /** What the 3D scene draws (worker/data/curvedScene.ts); null where nothing is (no scallop). */
      readonly scene: SceneGeometry | null;
      readonly solveMs: number;
    }
  | {
      readonly ok: false;
      readonly request: ThreeAxisRequest;
      readonly errors: readonly ThreeAxisInputError[];
      readonly limits: SliderLimits | null;
    };

/** Every answer of the page's `solve` job. */
export type PageReply = SolveReply | CurvedReply | ThreeAxisReply;

/** True for a plane's or a cylinder's answer. */
export function isSolveReply(reply: PageReply | QuestionReply): reply is SolveReply {
  return isSolveRequest(reply.request);
}
