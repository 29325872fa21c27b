/**
 * The shape of a language's catalogue (issue 30): every word the page's chrome, its fields and its
 * headline show, by key. English is the page itself (index.html's text, the field registry's
 * labels, fields.ts's hints): it needs no catalogue and costs the first result nothing. Japanese
 * and German are typed by this shape, so a missing or an extra key fails the type check, and each
 * loads only when chosen (language.ts). Types only: no code.
 */
import type { PageFieldKey } from '../../core/input/fields';
import type { AnyInputError, InputErrorCode } from '../../core/input/validate';

/** The languages of the page: English (the page as written), Japanese, German. */
export type Lang = 'en' | 'ja' | 'de';

/** The keys of index.html's `data-i18n` elements (tests/ui/i18n/catalogues.test.ts reads the page's). */
export type StaticKey =
  | 'title'
  | 'lede'
  | 'language'
  | 'machine'
  | 'machine5'
  | 'machine3'
  | 'unit'
  | 'inch'
  | 'sizeAs'
  | 'sizeD'
  | 'sizeR'
  | 'preset'
  | 'shelf'
  | 'passes'
  | 'raster'
  | 'waterline'
  | 'solveFor'
  | 'forward'
  | 'inverse'
  | 'given'
  | 'givenH'
  | 'givenRa'
  | 'pattern'
  | 'oneWay'
  | 'zigzag'
  | 'surface'
  | 'plane'
  | 'convex'
  | 'concave'
  | 'curved'
  | 'axis'
  | 'axisFeed'
  | 'axisCross'
  | 'finish'
  | 'downloadTable'
  | 'shopSheet'
  | 'copyLink'
  | 'copyEmbed'
  | 'cameraIso'
  | 'cameraFeed'
  | 'cameraTop'
  | 'rightFlank'
  | 'leftFlank'
  | 'contactOffset'
  | 'cuspHeights';

/** The words of the question named beside an answer (questionWords.ts), and its list separator ", ". */
export type QuestionWord =
  | ', '
  | '5-axis'
  | '3-axis'
  | 'lead'
  | 'tilt'
  | 'one-way'
  | 'zigzag'
  | 'plane'
  | 'convex cylinder'
  | 'concave cylinder'
  | 'along the feed'
  | 'across the feed'
  | 'curved point'
  | 'across'
  | 'straight'
  | 'convex'
  | 'concave'
  | 'waterline'
  | 'slope'
  | 'raster'
  | 'flat floor';

/** The results' status lines and buttons, by their English (put into the language by language.ts's pass). */
export type Phrase =
  | 'Typing: the results follow when you pause or press Enter.'
  | 'Updating: these numbers are for the previous inputs.'
  | 'Out of date: the solver gave up; these numbers are for earlier inputs.'
  | 'No answer: the solver gave up.'
  | 'No scallop: a flat end on a flat floor lies flat, so L = 2R for any h.'
  | 'Copy'
  | 'Copied'
  | 'Copy failed'
  | 'Copy the headline value'
  | 'Copy L/2'
  | 'Copy the programmed step'
  | 'Copy L along the surface'
  | 'Copy the centre offset'
  | 'Copy the current answer';

/** The teaching views' tab names, by their English (views/*View.ts titles, threeAxisViewText.ts chartTitle). */
export type TabName =
  | 'Cross-feed profile'
  | 'L against lead and tilt'
  | 'Step against slope'
  | 'L against each radius'
  | "The paper's tables"
  | '3D procedure, step by step'
  | 'Formulas'
  | 'Machined surface';

/** The finish box's words, by their English (finishPanel.ts marks each element with `data-phrase`). */
export type FinishPhrase =
  | 'Finish: the feed marks the teeth leave'
  | 'Scallop h (across the feed)'
  | 'Feed marks hf (along the CC path)'
  | 'Ra (across the feed)'
  | 'Sa (areal)'
  | 'Feed period'
  | 'Balanced feed fz* (hf = h)'
  | 'use the balanced feed'
  | 'Download x3p'
  | 'none: hf stays below h at every fz up to R'
  | 'Computing the feed marks and the areal parameters...'
  | 'Computing the areal parameters...'
  | 'Areal parameters over one period cell (ISO 25178-2, no filter, the design plane as reference); straight teeth, M3. The x3p file holds that cell, 256 x 256 heights (ISO 25178-72).'
  | 'Along the CC path (y = 0), two feed periods'
  | 'Across the feed, one period of the passes, where the feed marks stand highest:'
  | "The teeth's surface (z teeth, fz per tooth, passes L apart; feed periods x pass periods shown):"
  | 'Continuous passes: the tool sweeps without teeth.'
  | 'Along the feed, lengths drawn longer by';

/** A field's label (with the paper's symbol kept) and the hint under it. */
export interface FieldWords {
  readonly label: string;
  readonly hint: string;
}

/** One language's words. */
export interface Catalogue {
  readonly lang: Exclude<Lang, 'en'>;
  /** index.html's chrome, by its `data-i18n` keys. */
  readonly page: Readonly<Record<StaticKey, string>>;
  /** Each field's label and hint (the paper's symbols kept: L, h, Rcr, rho...). */
  readonly fields: Readonly<Record<PageFieldKey, FieldWords>>;
  /** The tool size given as a diameter: its label and hint, and the corner radius's hint then. */
  readonly diameter: FieldWords & { readonly cornerHint: string };
  /** The unit word of an angle field ("deg"). */
  readonly degrees: string;
  /** A field's slider, named after its field: `${label}${slider}` (English: " slider"). */
  readonly slider: string;
  /** The headline's labels. */
  readonly headline: { readonly stepOver: string; readonly scallopHeight: string };
  /** The results' status lines and the Copy buttons' words. */
  readonly phrases: Readonly<Record<Phrase, string>>;
  /** The finish box's words. */
  readonly finish: Readonly<Record<FinishPhrase, string>>;
  /** The teaching views' tab names. */
  readonly tabs: Readonly<Record<TabName, string>>;
  /** The question's words beside an answer (questionWords.ts). */
  readonly question: Readonly<Record<QuestionWord, string>>;
  /** Each input error code's sentence (errorText.ts gives the field, the limit and what was typed). */
  readonly errors: Readonly<Record<InputErrorCode, (t: ErrorText) => string>>;
}

/** What an error's sentence is made of, in the language and unit on screen. */
export interface ErrorText {
  readonly e: AnyInputError;
  /** The field's name in the language (the tool diameter's when the size is given as D). */
  readonly label: string;
  /** What was typed, shortened to 24 characters as the English messages quote it. */
  readonly got: string;
  /** The bound it broke, with its unit (a length in the user's unit; an angle in degrees), or ''. */
  readonly limit: string;
  /** A length (mm) in the user's unit with its symbol, the locale's decimal sign. */
  readonly length: (mm: number) => string;
  /** An angle (degrees) as a number, the locale's decimal sign, without its unit. */
  readonly angle: (deg: number) => string;
  /** The unit's symbol (mm, in). */
  readonly unit: string;
  /** The tool size is given as the diameter D (limits set by R then read D/2). */
  readonly diameter: boolean;
}
