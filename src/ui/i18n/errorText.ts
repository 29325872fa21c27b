/**
 * An input error's words in a catalogue's language (issue 30): the same error data the core words
 * in English (core/input/inputErrors.ts describeInputError: the field, the code, the bound it broke,
 * what was typed) with the field named in the language, the numbers in the user's unit with the
 * locale's decimal sign, and the sentence from the catalogue's `errors`, one per error code (typed
 * as a Record: a code without words fails the type check). Loaded with language.ts.
 */
import { quotedEntry } from '../../core/input/entryMessages';
import { FIELDS, pageKeyOf } from '../../core/input/fields';
import { formatAngleDeg, formatInputNumber, fromMm, type LengthUnit, unitSymbol } from '../../core/input/units';
import type { AnyInputError, DescribeOptions } from '../../core/input/validate';
import {
  MIN_THREE_AXIS_LENGTH_MM,
  THREE_AXIS_SURFACE_RADIUS_RANGE_MM,
  THREE_AXIS_TOOL_RADIUS_RANGE_MM,
} from '../../core/threeAxis/errors';
import type { ThreeAxisInputError } from '../../core/threeAxis/validate';
import type { Catalogue, ErrorText } from './catalogue';

export type { ErrorText } from './catalogue';

import { localDecimal } from './langChoice';

/** The message of `e` in `catalogue`'s language and `unit` (the page's options of describeInputError). */
export function describeInputErrorIn(
  catalogue: Catalogue,
  e: AnyInputError,
  unit: LengthUnit,
  options: DescribeOptions = {},
): string {
  const diameter = options.toolSizeAsDiameter === true && e.field === 'R';
  const key = pageKeyOf(e.field);
  const label = diameter
    ? catalogue.diameter.label
    : key !== null
      ? catalogue.fields[key].label
      : FIELDS[e.field].label;
  const scale = diameter ? 2 : 1;
  const u = unitSymbol(unit);
  const length = (mm: number) => localDecimal(`${formatInputNumber(fromMm(mm * scale, unit))} ${u}`, catalogue);
  const isLength = FIELDS[e.field].kind === 'length';
  const limit =
    e.limit === undefined
      ? ''
      : isLength
        ? length(e.limit)
        : localDecimal(`${formatAngleDeg(e.limit)} ${catalogue.degrees}`, catalogue);
  const typed = options.typed ?? e.got;
  const got = quotedEntry(typed);
  return catalogue.errors[e.code]({
    e,
    label,
    got,
    limit,
    length,
    angle: (deg: number) => localDecimal(formatAngleDeg(deg), catalogue),
    unit: u,
    diameter: options.toolSizeAsDiameter === true,
  });
}

/**
 * A radius-gouging error's parts (a doubly curved point), for each language's sentence: this
 * radius's and the other's symbols, the other radius held (its length in the unit on screen, or
 * null: straight), this radius's bound as a magnitude, what it must be, and what the other must be
 * with this one held.
 */
export function radiusGougingParts(t: ErrorText): {
  readonly me: 'Rf' | 'Rc';
  readonly them: 'Rf' | 'Rc';
  readonly held: string | null;
  readonly mag: string;
  readonly kind: 'concave-at-least' | 'convex-at-most' | 'not-concave' | 'none';
  readonly other: { readonly kind: string; readonly radius: string | null } | null;
} {
  const feed = t.e.field === 'feedRadius';
  const r = t.e.radiusLimit;
  const o = r?.other;
  return {
    me: feed ? 'Rf' : 'Rc',
    them: feed ? 'Rc' : 'Rf',
    held: r?.heldMm === undefined || !Number.isFinite(r.heldMm) ? null : t.length(r.heldMm),
    mag: t.e.limit === undefined ? '' : t.length(Math.abs(t.e.limit)),
    kind: r?.kind ?? 'none',
    other: o === undefined ? null : { kind: o.kind, radius: o.radiusMm === undefined ? null : t.length(o.radiusMm) },
  };
}

/**
 * A three-axis error (the validation's or a solver's: core/threeAxis) in `catalogue`'s language and
 * `unit`, from its data (field, code, limit, what was given) rather than the core's English
 * sentence; `typed` replaces the value given (the text as typed in the user's unit).
 */
export function describeThreeAxisErrorIn(
  catalogue: Catalogue,
  e: ThreeAxisInputError,
  unit: LengthUnit,
  typed: string | null,
  waterline: boolean,
): string {
  const key = pageKeyOf(e.field);
  const label = key !== null ? catalogue.fields[key].label : catalogue.page.passes;
  const u = unitSymbol(unit);
  const length = (mm: number) => localDecimal(`${formatInputNumber(fromMm(mm, unit))} ${u}`, catalogue);
  const isLength = FIELDS[e.field].kind === 'length';
  const limit =
    e.limit === null || !Number.isFinite(e.limit)
      ? ''
      : isLength
        ? length(e.limit)
        : localDecimal(`${formatAngleDeg(e.limit)}°`, catalogue);
  const given =
    typed !== null && typed !== '' ? typed : isLength && typeof e.got === 'number' ? length(e.got) : String(e.got);
  const got = quotedEntry(given);
  const [toolLo, toolHi] = THREE_AXIS_TOOL_RADIUS_RANGE_MM;
  const [radiusLo, radiusHi] = THREE_AXIS_SURFACE_RADIUS_RANGE_MM;
  return catalogue.threeAxis[e.code]({
    e,
    label,
    got,
    limit,
    length,
    isLength,
    waterline,
    noLimit: limit === '' || (e.limit ?? 0) < MIN_THREE_AXIS_LENGTH_MM,
    toolRange: [length(toolLo), length(toolHi)],
    radiusRange: [length(radiusLo), length(radiusHi)],
    minLength: length(MIN_THREE_AXIS_LENGTH_MM),
  });
}
