/**
 * The page's language in force and its words (issue 30): null is English, the page as written.
 * Read by the modules that write words (fields.ts, results.ts); set by language.ts once a
 * catalogue has loaded, with the pass that puts the results into its words. Small: it loads with
 * the first result; what only another language needs loads with language.ts.
 */
import type { LengthUnit } from '../../core/input/units';
import { type AnyInputError, type DescribeOptions, describeInputError } from '../../core/input/validate';
import type { ThreeAxisInputError } from '../../core/threeAxis/validate';
import type { Catalogue, FieldWords } from './catalogue';

/** An input error's words in the language in force (language.ts's errorText.ts). */
export type ErrorDescriber = (e: AnyInputError, unit: LengthUnit, options: DescribeOptions) => string;

/** A three-axis error's words in the language in force: what was typed, and whether the passes are waterline. */
export type ThreeAxisDescriber = (
  e: ThreeAxisInputError,
  unit: LengthUnit,
  typed: string | null,
  waterline: boolean,
) => string;

let current: Catalogue | null = null;
// The results' root is typed `object` here: this module is read by Node's tests of the page's
// builders (no DOM); language.ts's pass takes the page's element.
/** Puts the results drawn in English into the language in force (language.ts's), or none. */
let localizer: ((root: object) => void) | null = null;
let describer: ErrorDescriber | null = null;
let threeAxisDescriber: ThreeAxisDescriber | null = null;

/**
 * Makes `catalogue` (null: English) the page's words, with the pass over the drawn results and the
 * input errors' words in its language.
 */
export function setCatalogue(
  catalogue: Catalogue | null,
  results: ((root: object) => void) | null,
  errors: ErrorDescriber | null,
  threeAxisErrors: ThreeAxisDescriber | null = null,
): void {
  current = catalogue;
  localizer = catalogue === null ? null : results;
  describer = catalogue === null ? null : errors;
  threeAxisDescriber = catalogue === null ? null : threeAxisErrors;
}

/** A three-axis error in the language in force, or null in English (the page words the core's message). */
export function describeThreeAxis(
  e: ThreeAxisInputError,
  unit: LengthUnit,
  typed: string | null,
  waterline: boolean,
): string | null {
  return threeAxisDescriber?.(e, unit, typed, waterline) ?? null;
}

/** An input error in the language in force and `unit` (English: the core's describeInputError). */
export function describeError(e: AnyInputError, unit: LengthUnit, options: DescribeOptions = {}): string {
  return describer === null ? describeInputError(e, unit, options) : describer(e, unit, options);
}

/** The catalogue in force, or null for English. */
export function catalogue(): Catalogue | null {
  return current;
}

/** A field's words in the language in force, from its English ones. */
export function fieldWords(key: keyof Catalogue['fields'], english: FieldWords): FieldWords {
  return current?.fields[key] ?? english;
}

/** Puts the results just drawn (in English) under `root` into the language in force; nothing in English. */
export function localize(root: object): void {
  localizer?.(root);
}
