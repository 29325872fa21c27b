/**
 * The shape of a language's catalogue (issue 30): every word the page's chrome, its fields and its
 * headline show, by key. English is the page itself (index.html's text, the field registry's
 * labels, fields.ts's hints): it needs no catalogue and costs the first result nothing. Japanese
 * and German are typed by this shape, so a missing or an extra key fails the type check, and each
 * loads only when chosen (language.ts). Types only: no code.
 */
import type { FinishErrorCode, FinishField } from '../../core/finish/finishInput';
import type { PageFieldKey } from '../../core/input/fields';
import type { AnyInputError, InputErrorCode } from '../../core/input/validate';
import type { CurvatureRowKey, ProcedureKey } from '../../core/procedures/procedures';
import type { ThreeAxisInputError } from '../../core/threeAxis/validate';
import type { CurvedError } from '../../worker/pageProtocol';
import type { PageFieldError } from '../requestTypes';
import type { SceneLabelTexts } from '../sceneLabelTexts';
import type { CalculatorState } from '../state';
import type { CurvedPreset, WaterlinePreset } from '../surfaceState';
import type { FormulaWords, StepperWords, TableWords } from './teachWords';

/** The languages of the page: English (the page as written), Japanese, German. */
export type Lang = 'en' | 'ja' | 'de';

/** The keys of index.html's `data-i18n` elements (tests/ui/i18n/catalogues.test.ts reads the page's). */
export type StaticKey =
  | 'title'
  | 'lede'
  | 'stepOverMeaning'
  | 'centreOffset'
  | 'fullStop'
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
  | 'cuspHeights'
  | 'openFull'
  | 'embedTitle'
  | 'teachingViews'
  | 'alongSurface'
  | 'cuspNormal'
  | 'equivalentLead'
  | 'equivalentTilt'
  | 'lookupNote'
  | 'sheetNote'
  | 'staleBadge'
  | 'typingBadge'
  | 'camera'
  | 'legendTool'
  | 'legendPath'
  | 'legendContact'
  | 'legendDimension'
  | 'legendOffset'
  | 'legendCentre'
  | 'legendAxis'
  | 'legendDesign'
  | 'legendHplane'
  | 'legendPhp'
  | 'legendSection'
  | 'legendLoop'
  | 'legendRidge'
  | 'legendDesignCurved'
  | 'legendHsurface'
  | 'legendCusp'
  | 'legendAxes'
  | 'legendTrace'
  | 'legendExaggeration'
  | 'givenSa'
  | 'surfacePreset'
  | 'present'
  | 'leavePresent'
  | 'presentInputs'
  | 'hideInputs';

/** The keys of index.html's landmarks named by `aria-label` with a `data-i18n-label` (their English the page's). */
export type LabelKey =
  | 'fullCalculator'
  | 'notices'
  | 'inputs'
  | 'results'
  | 'finish'
  | 'targetSa'
  | 'teaching'
  | 'view3d'
  | 'currentAnswer';

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
  | 'Link copied: it opens this calculator with these inputs.'
  | 'Copying was refused by the browser: the link is selected below, copy it by hand.'
  | 'Embed code copied: an iframe and the <path-interval-calculator> element.'
  | 'Copying was refused by the browser: the embed code is selected below, copy it with Ctrl+C.'
  | 'Copy the headline value'
  | 'Copy L/2'
  | 'Copy the programmed step'
  | 'Copy L along the surface'
  | 'Copy the centre offset'
  | 'Copy the current answer'
  | 'Horizontal step Lxy (as programmed)'
  | 'Step-down dz (as programmed)';

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

/**
 * The finish box's words, by their English (finishPanel.ts marks each element with `data-phrase`),
 * and the roughness rows' "h for this Ra" (roughness.ts; language.ts marks it).
 */
export type FinishPhrase =
  | 'h for this Ra'
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
  | 'not used with a target Sa: fz is its answer'
  | 'Target Sa: the best step-over and feed per tooth'
  | 'Step-over L'
  | 'Feed per tooth fz'
  | 'use this pair'
  | 'L * fz (area per tooth)'
  | 'Sa it leaves'
  | 'Scallop h at this L'
  | 'L0 (fz -> 0: Ra = Sa)'
  | 'Computing the pairs of step-over and feed per tooth that leave this Sa (a few seconds)...'
  | 'The pair with the largest L * fz (the area machined per tooth: the fastest finish at a given spindle speed) among those whose areal Sa is the target (plane, straight teeth, no runout). "use this pair" solves for the scallop height at that L with that fz, both rounded down.'
  | 'Every pair that leaves this Sa: the dot is the best, the curve ends at L0 where fz -> 0'
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
  /** index.html's landmarks' accessible names, by their `data-i18n-label` keys. */
  readonly labels: Readonly<Record<LabelKey, string>>;
  /** Each field's label and hint (the paper's symbols kept: L, h, Rcr, rho...). */
  readonly fields: Readonly<Record<PageFieldKey, FieldWords>>;
  /** The tool size given as a diameter: its label and hint, and the corner radius's hint then. */
  readonly diameter: FieldWords & { readonly cornerHint: string };
  /** The unit word of an angle field ("deg"). */
  readonly degrees: string;
  /** A field's slider, named after its field: `${label}${slider}` (English: " slider"). */
  readonly slider: string;
  /** The headline's labels. */
  readonly headline: {
    readonly stepOver: string;
    readonly scallopHeight: string;
    /** A target Sa's: the step-over at the curve's end, fz -> 0 (results.ts ZERO_FEED_LABEL). */
    readonly zeroFeed: string;
  };
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
  /** The shop sheet's words (shopSheet.ts; its English in shopSheetWords.ts) and its refusals' own sentences. */
  readonly sheet: SheetWords & { readonly refusals: SheetRefusalWords };
  /** The sentences the page words itself around a number (language.ts puts them into the language). */
  readonly said: SaidWords;
  /** Each three-axis error code's sentence (errorText.ts gives the field, the limit and what was typed). */
  readonly threeAxis: Readonly<Record<ThreeAxisInputError['code'], (t: ThreeAxisText) => string>>;
  /** The "L against lead and tilt" charts' captions, axis titles, legends and notes (views/chartView.ts). */
  readonly chart: ChartWords;
  /** The three-axis chart "step against slope" (views/slopeChart.ts, pageChartText.ts). */
  readonly slope: SlopeWords;
  /** A doubly curved point's charts of L against each radius (views/radiusChart.ts, pageChartText.ts). */
  readonly radius: RadiusWords;
  /** The line over a view that does not draw a page question itself (views/curvedViewText.ts, threeAxisViewText.ts). */
  readonly viewNotes: ViewNoteWords;
  /** The finish box's sentences the page words around the worker's answer (finishPanel.ts, finishText.ts). */
  readonly finishText: FinishWords;
  /** The Machined surface view's words (views/surfaceView.ts; English in views/surfaceWords.ts). */
  readonly surface: SurfaceWords;
  /** The 3D scene's dimension labels and accessible name (sceneLabels.ts; made by sceneText.ts). */
  readonly scene: SceneWords;
  /** The cross-feed profile's words (views/profileView.ts, profileDrawing.ts; English in views/profileWords.ts). */
  readonly profile: ProfileWords;
  /** The procedures' names on the page (the registry, procedures.ts, keeps the English for the CLI, CSV, JSON). */
  readonly procedures: ProcedureNames;
  /** A doubly curved point's refusal on its field, worded from its data (curvedText.ts; English curvedRequest.ts). */
  readonly curved: (e: CurvedError, state: CalculatorState) => PageFieldError;
  /** A radius field's own error (missing, not a number: `value` null, a sign typed), worded by curvedText.ts (English: curvedRequest.ts radiusMm). */
  readonly radiusField: (key: 'Rf' | 'Rc', text: string, value: number | null) => PageFieldError;
  /** A link notice's details (linkNotices.ts; English: the page's own, state.ts and others). */
  readonly linkNotices: LinkNoticeWords;
  /** The step-through's words (views/stepperView.ts; English in views/stepperWords.ts). */
  readonly stepper: StepperWords;
  /** The formulas view's words (views/formulasView.ts; English in views/formulaWords.ts). */
  readonly formulas: FormulaWords;
  /** The paper's tables' words (views/tablesView.ts; English in views/tableWords.ts). */
  readonly tables: TableWords;
}

/**
 * A doubly curved point's refusals (the worker's data, worded by curvedText.ts; English in
 * curvedRequest.ts describeCurvedError): labels as the page names the fields, lengths with their unit
 * and the locale's decimal sign, `got` what was typed (shortened).
 */
export interface CurvedWords {
  /** L past the widest step-over that leaves a scallop here. */
  readonly beyondMax: (label: string, max: string, got: string) => string;
  /** h above a flank's or the shank's limit (on the right or the left). */
  readonly aboveLimit: (label: string, limit: string, got: string, shank: boolean, right: boolean) => string;
  /** A radius outside the range accepted. */
  readonly outOfRange: (label: string, from: string, to: string, got: string) => string;
  /** The other radius held (its symbol; its signed length, or null when straight). */
  readonly held: (other: string, radius: string | null) => string;
  /** What the radius must be, the other held, for the tool not to gouge (`radius` the bound). */
  readonly gouging: (
    kind: 'concave-at-least' | 'convex-at-most' | 'not-concave' | 'other',
    label: string,
    radius: string,
    held: string,
    got: string,
  ) => string;
  /** A radius field's own errors: empty (enter one, or choose straight), not a number, a sign or 0 typed (the side is chosen beside it). */
  readonly missing: (label: string) => string;
  readonly notNumber: (label: string, got: string) => string;
  readonly positive: (label: string, got: string) => string;
  /** The target Ra's bound says "on this surface" (errors); here it is "at this point": [from, to]. */
  readonly atPoint: readonly [string, string];
}

/** A procedure's names: in full with its equations (the results table), short (legends and charts). */
export interface ProcedureName {
  readonly label: string;
  readonly shortLabel: string;
}

/**
 * The procedures' names in a language, keyed by the registry's ids; the authors' names and the
 * paper's equation numbers kept, the words around them translated.
 */
export interface ProcedureNames {
  readonly names: Readonly<Record<ProcedureKey, ProcedureName>>;
  /** A cylinder's rows: the plane's exact answer (the curvature ignored), each procedure corrected. */
  readonly rows: Readonly<Record<CurvatureRowKey, ProcedureName>>;
  /**
   * A doubly curved point's comparison rows (resultsOther.ts), by their English: the exact answer
   * here, the plane's and each cylinder's exact answers; a corrected procedure is its row's short
   * name with the formula.
   */
  readonly curved: Readonly<
    Record<
      | 'Exact (this doubly curved point)'
      | 'Plane, exact (both curvatures ignored)'
      | 'Cylinder along the feed, exact (Rf ignored)'
      | 'Cylinder across the feed, exact (Rc ignored)',
      string
    >
  >;
  /** After a lead-only procedure's name in the table when the tool is tilted (English ", lead only"). */
  readonly leadOnly: string;
  /** The heading row above a cylinder's rows (results.ts: "On the cylinder: curvature ignored, or corrected the usual way"). */
  readonly cylinderHead: string;
  /** The results table's accessible name, its box's (a scrolling region), and a procedure's row's hover title. */
  readonly table: string;
  readonly region: string;
  readonly select: string;
  /** The results table's head (results.ts), by its English words; `L/2` and `h` are symbols. */
  readonly head: Readonly<Record<'Procedure' | 'Model' | 'Deviation' | 'Deviation [%]' | 'Scallop it leaves', string>>;
  /** A cylinder's rows' hover titles: what each assumes (English: the registry's CURVATURE_ROWS assumes). */
  readonly assumes: Readonly<Record<CurvatureRowKey, string>>;
  /** A doubly curved point's rows' hover titles (resultsOther.ts), by their English. */
  readonly curvedTitles: Readonly<Record<CurvedRowTitle, string>>;
  /** The table's notes (results.ts, resultsText.ts; read back by tableNotes.ts). */
  readonly notes: TableNoteWords;
}

/** A doubly curved point's rows' hover titles (resultsOther.ts), in English. */
export type CurvedRowTitle =
  | 'The exact step-over at this point.'
  | 'The exact answer on a plane at the same posture.'
  | 'The exact answer on the cylinder of radius Rc with its axis along the feed.'
  | 'The exact answer on the cylinder of radius Rf with its axis across the feed.'
  | 'The usual correction: the effective radius combined with the radius across the feed.';

/**
 * The results table's notes, sentence by sentence (results.ts, resultsText.ts, the worker's reasons;
 * i18n/tableNotes.ts reads each back): the procedures' names given in the language, lengths with
 * their unit and the locale's decimal sign, the paper's symbols kept.
 */
export interface TableNoteWords {
  /** A flat end lying flat on a plane: no scallop at any step-over up to its diameter. */
  readonly noScallop: string;
  /** With tilt: the lead-only models (their names, joined). */
  readonly leadOnly: (names: string) => string;
  /** On a cylinder: the procedures above as on a plane; the rows below. */
  readonly cylinder: string;
  /** On a cylinder across the feed: each corrected row equals its procedure's. */
  readonly crossAxis: string;
  /** A doubly curved point's comparison rows (forward); given for the forward problem only (inverse). */
  readonly curved: string;
  readonly curvedInverse: string;
  /**
   * A row's value beyond its model: its name, h or L/2 and its value, the model (its circle, its
   * ellipse, the combined circle), the limit's name (Reff, the ellipse's height Rlong sin(rho) or
   * half-width Rlong, the combined radius rho) and its value.
   */
  readonly beyond: (
    name: string,
    what: 'h' | 'L/2',
    value: string,
    model: 'circle' | 'ellipse' | 'combined',
    limit: 'Reff' | 'height' | 'halfWidth' | 'rho',
    limitValue: string,
  ) => string;
  /** A row's L past the widest step-over that leaves a scallop (on this cylinder, or a plane). */
  readonly wall: (name: string, interval: string, max: string, cylinder: boolean) => string;
  /** A row's own reason (a model's, worded as a chart gap's: chart.reasons), after its name. */
  readonly reason: (name: string, reason: string) => string;
  /** The plane's row: the step-over at or beyond the widest one on a plane. */
  readonly planeBeyond: string;
  /** A corrected row on a concave surface tighter than Reff (its effective radius with unit, or null when not given). */
  readonly notPositive: (name: string, reff: string | null) => string;
  /** A doubly curved point's row: h at or above the flank limit; h above the combined circle's widest point (its radius). */
  readonly flankLimit: (name: string) => string;
  readonly combinedWidest: (name: string, radius: string) => string;
}

/**
 * The cross-feed profile's words (views/profileView.ts, profileDrawing.ts, profileScaleBars.ts;
 * English in views/profileWords.ts): lengths given as text with their unit, the procedures' names
 * kept (marked English on the page).
 */
export interface ProfileWords {
  /** The plot's accessible name: on a plane, on a cylinder (its side and axis), at a doubly curved point (each radius's side). */
  readonly plotPlane: string;
  readonly plotCylinder: (side: 'convex' | 'concave', axis: 'feed' | 'cross') => string;
  readonly plotCurved: (rf: 'convex' | 'concave', rc: 'convex' | 'concave') => string;
  /** The note over a cylinder's section (its side, its radius with unit) and a doubly curved point's (each radius in words). */
  readonly noteCylinder: (side: 'convex' | 'concave', radius: string, axis: 'feed' | 'cross') => string;
  readonly noteCurved: (rf: string, rc: string) => string;
  /** What the exaggeration stretches on a plane and on a curved surface, and the curvature kept. */
  readonly heightsPlane: string;
  readonly heightsSurface: string;
  readonly curvatureTrue: string;
  /** The scale line: true scale, or `heights` exaggerated k times; chosen automatically; capped (the k wanted). */
  readonly scale: (k: number, heights: string, auto: boolean, capped: number | null, curvature: string) => string;
  /** The exaggeration's choice: its name, automatic, true scale, k times. */
  readonly exaggeration: string;
  readonly auto: string;
  readonly trueScale: string;
  readonly vertical: (k: number) => string;
  /** The buttons. */
  readonly zoomIn: string;
  readonly zoomOut: string;
  readonly reset: string;
  readonly cusp: string;
  /** The note under the plot on the approximations' profiles. */
  readonly approximations: string;
  /** The legend: the ring ellipse, a procedure's next pass (after its name), each cylinder's. */
  readonly ring: string;
  readonly nextPass: string;
  readonly cylinderAlong: string;
  readonly cylinderAcross: string;
  /** After L measured along an arc (with its separator); the height bar's text (its length with unit, k). */
  readonly arc: string;
  readonly high: (length: string, k: number) => string;
}

/** The 3D scene's words: its labels put into the language (the word "arc", the decimal sign) and its name. */
export interface SceneWords {
  readonly labels: (english: SceneLabelTexts) => SceneLabelTexts;
}

/** What a finish field's refusal is made of (the core's FinishError data), in the language and unit on screen. */
export interface FinishErrorText {
  readonly field: FinishField;
  /** The field's name in the language. */
  readonly label: string;
  /** What was typed, shortened to 24 characters. */
  readonly got: string;
  /** The bound it broke with its unit (the locale's decimal sign), or ''. */
  readonly limit: string;
  /** The field's unit symbol: mm or in for fz and e, mm/min or in/min for F, rpm for n, '' else. */
  readonly unit: string;
  /** With rate-too-small and rate-too-large: the fz that F / (n z) gives, with its unit. */
  readonly rateFz: string;
  /** The most teeth accepted. */
  readonly maxFlutes: number;
}

/**
 * The finish box's sentences around the worker's answer (finishPanel.ts; English: the core's and
 * the panel's own), worded on the page from the worker's data: a field's refusal by its code, why
 * the marks could not be computed, where feed marks are not computed, a worker restarted, the
 * areal rows' titles, the cell map's name and scale, the x3p download's lines. The worker's own
 * reason for a restart stays English.
 */
export interface FinishWords {
  readonly errors: Readonly<Record<FinishErrorCode, (t: FinishErrorText) => string>>;
  /** The search did not converge, or thin slivers are cut by no tooth: of the feed marks or the areal parameters. */
  readonly failure: (kind: 'not-converged' | 'not-swept', part: 'marks' | 'areal') => string;
  /** Feed marks are not computed on this kind of surface. */
  readonly scope: (kind: 'cylinder' | 'doublyCurved' | 'waterlineRevolution' | 'other') => string;
  /** The finish's worker gave up or was restarted (its reason worded by workerReason.ts, an exception's text left to the hover title). */
  readonly worker: (gaveUp: boolean, reason: string) => string;
  /**
   * The target-Sa box's own refusals (the worker's TargetSaMessage refusal; English its sentence in
   * jobs/targetSa.ts and core roughness/targetSa.ts) and its worker's restart (English in targetSaPanel.ts).
   */
  readonly targetSa: {
    readonly runout: string;
    readonly tooLong: string;
    readonly worker: (gaveUp: boolean, reason: string) => string;
  };
  /** The areal rows' titles after Sa. */
  readonly areal: Readonly<Record<'Sq' | 'Sz' | 'Sp' | 'Sv' | 'Ssk' | 'Sku', string>>;
  /** The cell map's accessible name, and its caption: the period and the pass width (with units), Sz. */
  readonly mapLabel: string;
  readonly mapScale: (period: string, across: string, sz: string) => string;
  /** The x3p download: computing, no file (the worker's reason, or null), the worker gave up, saved. */
  readonly x3pComputing: string;
  readonly x3pNone: (reason: string | null) => string;
  readonly x3pGaveUp: (reason: string) => string;
  readonly x3pSaved: (fileName: string, size: number) => string;
}

/**
 * The Machined surface view's words (views/surfaceView.ts; English in views/surfaceWords.ts):
 * lengths and heights given as text with their units, counts as numbers.
 */
export interface SurfaceWords {
  /** The simulation's state: the inputs invalid, its solver gave up, running (percent done or null). */
  readonly invalid: string;
  readonly failed: string;
  readonly pending: (percent: number | null) => string;
  /** Why the worker did not simulate: not a plane, no scallop, or no reason given (another stays the worker's). */
  readonly reasons: Readonly<Record<'planes-only' | 'no-scallop' | 'none', string>>;
  /** The simulation stopped on an exception (the worker's "No simulation: ..."): the English gives its own text; another language a sentence of its own (its text in the hover title). */
  readonly exception: (detail: string) => string;
  /** The heights' scale (k null: true scale) and the colour's unit. */
  readonly exaggeration: (k: number | null, unit: string) => string;
  /** The simulated cusp against the exact one, their difference within or beyond the bound, the grid and passes. */
  readonly comparison: (
    simulated: string,
    exact: string,
    diff: string,
    within: boolean,
    bound: string,
    cells: string,
    passes: number,
  ) => string;
  /** The profilometer trace's accessible name, its caption (passes, the exact Rz, Ra, Rq) and its mean line. */
  readonly traceLabel: string;
  readonly traceCaption: (passes: number, rz: string, ra: string, rq: string) => string;
  readonly meanLine: string;
  /** The 3D view's accessible name. */
  readonly sceneLabel: string;
}

/**
 * The neutral line over a teaching view for a doubly curved point or a three-axis question (English
 * in views/viewNoteWords.ts): what the view works on and where the question is answered.
 */
export interface ViewNoteWords {
  /** A doubly curved point: what each view that does not draw it works on, then where it is answered. */
  readonly curved: Readonly<Record<'tables' | 'stepper' | 'formulas' | 'surface', string>>;
  readonly curvedAnswered: string;
  /** The three-axis question in words: its slope and raster angle (degrees, without °), or waterline (null). */
  readonly question: (slope: string, psi: string | null) => string;
  /** The paper's tables in three-axis mode; waterline on a surface of revolution (nothing to draw). */
  readonly tables: string;
  readonly revolution: (question: string) => string;
  /** The upright tool over the question as the tool at the equivalent lead and tilt (degrees, without their unit) on a plane (the surface view, the others). */
  readonly equivalent: (question: string, lead: string, tilt: string, surface: boolean) => string;
}

/**
 * A doubly curved point's charts' words (views/radiusChart.ts, pageChartText.ts; English in
 * views/radiusWords.ts): `self` and `other` the radii's symbols (Rf, Rc), lengths with their unit.
 */
export interface RadiusWords {
  /** A signed radius: convex or concave and its size, or straight. */
  readonly radius: (kind: 'convex' | 'concave' | 'straight', size: string) => string;
  /** The caption: L against |self| on a log axis, the other held, the current radius. */
  readonly title: (u: string, self: string, other: string, held: string, current: string) => string;
  readonly xLabel: (self: string, u: string) => string;
  readonly description: (title: string) => string;
  /** A band without L: gouging, or h at or above the flank or shank limit. */
  readonly band: { readonly gouging: string; readonly limit: string };
  /** The legend: its head at the current radius, each branch's name, a value missing. */
  readonly legendHead: (self: string, current: string) => string;
  readonly branch: (self: string, kind: 'convex' | 'concave' | 'straight') => string;
  readonly seeBelow: string;
  /** The values at the current point: the radii, L, and L with each radius straight. */
  readonly summary: (rf: string, rc: string, L: string, rfStraight: string, rcStraight: string) => string;
  /** A gap's note: the branch (convex or concave), |self| about `from` (to `to`), the other radius and the value it is held at, and why. */
  readonly gap: (
    side: string,
    self: string,
    from: string,
    to: string | null,
    other: string,
    held: string,
    reason: 'gouging' | 'limit',
  ) => string;
}

/**
 * The three-axis chart's words (views/slopeChart.ts and pageChartText.ts; English in
 * views/slopeWords.ts): numbers given as text with their units (angles with °), the symbols kept.
 */
export interface SlopeWords {
  /** The captions: the programmed step against the slope for h; the scallop a constant step leaves. */
  readonly stepTitle: (u: string, h: string, slope: string) => string;
  readonly cuspTitle: (u: string, constant: string, h: string) => string;
  /** The axis titles. */
  readonly slopeAxis: string;
  readonly stepAxis: (u: string) => string;
  readonly scallopAxis: (u: string) => string;
  /** A chart's description for a screen reader: its caption and the crossing sentence. */
  readonly description: (title: string, sentence: string) => string;
  /** The legends: their head at the current slope; a strategy's step (psi: its raster angle); the flat floor's; a constant step's scallop; none. */
  readonly legendHead: (slope: string) => string;
  readonly strategy: (passes: 'raster' | 'waterline', psi: string) => string;
  readonly floor: string;
  readonly scallopOf: (constant: string) => string;
  readonly none: string;
  /** A band without a step (its title). */
  readonly gap: string;
  /** No step above `slope`: h reaches the largest scallop the tool can leave (or the surface's end). */
  readonly noStepAbove: (slope: string, h: string, revolution: boolean) => string;
  /** Where raster (at psi) and waterline cross for h (`both`: the step there and the slope), or that they do not. */
  readonly crossing: (
    crossing: string | null,
    psi: string,
    h: string,
    both: string | null,
    revolution: boolean,
  ) => string;
  /** Slopes where a constant step leaves no scallop (from, to or null at one sample), and why by the core's code. */
  readonly refusal: (step: string, from: string, to: string | null, code: string) => string;
}

/**
 * The five-axis comparison charts' words (views/chartView.ts; English in views/chartWords.ts): the
 * numbers given as text (degrees without their unit, `u` a unit symbol or %), the procedures' names
 * and the solvers' reasons for a gap kept as they are.
 */
export interface ChartWords {
  /** The captions: L against the lead, the approximations' error along the lead, L against the tilt. */
  readonly leadTitle: (u: string, rho: string) => string;
  readonly errorTitle: (u: string) => string;
  readonly tiltTitle: (u: string, beta: string) => string;
  /** The axis titles: the lead, the tilt, the error in `u`. */
  readonly leadAxis: string;
  readonly tiltAxis: string;
  readonly errorAxis: (u: string) => string;
  /** A chart's description for a screen reader, after its caption. */
  readonly description: (title: string) => string;
  /** The legend's head: the values at the current angle. */
  readonly legendHead: (angle: 'rho' | 'beta', deg: string) => string;
  /** After a lead-only model's name with a tilt; a value missing (the notes say why); none. */
  readonly leadOnly: string;
  readonly seeBelow: string;
  readonly none: string;
  /** The error unit's and the lead axis's choices and their names. */
  readonly errorIn: { readonly pct: string; readonly length: string; readonly name: string };
  readonly rhoScale: { readonly log: string; readonly linear: string; readonly name: string };
  /** The values at the current posture (`values`: "Exact 2.8872 mm, Sekine ..."); outside the charted range. */
  readonly summary: (rho: string, beta: string, values: string) => string;
  readonly noSummary: string;
  /** On a cylinder: what the exact curve and the approximations are. */
  readonly cylinder: (concave: boolean, axis: 'feed' | 'cross') => string;
  /** A gap's note before its reason: the procedures, the angle, from (and to, or null at one sample). */
  readonly gap: (names: string, angle: 'rho' | 'beta', from: string, to: string | null) => string;
  /**
   * A gap's reason (the core's sentence, core/procedures/sweepGaps.ts noAnswerReason, read back by
   * views/gapReasons.ts): each model's own, and h above the widest point of a circle or an ellipse
   * (`symbol` its radius or height, a symbol kept).
   */
  readonly reasons: Readonly<Record<GapReason, string>>;
  readonly widest: (shape: 'circle' | 'ellipse', symbol: string) => string;
}

/** The solvers' reasons for a gap in a chart (core/procedures/sweepGaps.ts, approximations.ts), by kind. */
export type GapReason =
  | 'exact'
  | 'sekineRhoZero'
  | 'sekineShort'
  | 'redonnetRhoZero'
  | 'bediRhoZero'
  | 'overflow'
  | 'flatBottom'
  | 'sharpEdge'
  | 'flatEnd';

/** What a three-axis error's sentence is made of, in the language and unit on screen. */
export interface ThreeAxisText {
  readonly e: ThreeAxisInputError;
  /** The field's name in the language (the tool diameter's when the size is given as D). */
  readonly label: string;
  /** What was typed (or the value given), shortened to 24 characters. */
  readonly got: string;
  /** The bound it broke with its unit (a length in the user's unit; an angle in degrees), or ''. */
  readonly limit: string;
  /** A length (mm) in the user's unit with its symbol, the locale's decimal sign. */
  readonly length: (mm: number) => string;
  /** The field is a length (else an angle, or the passes). */
  readonly isLength: boolean;
  /** The passes are waterline (else raster). */
  readonly waterline: boolean;
  /** No bound to stay below (none given, or below the smallest length accepted): no answer here at all. */
  readonly noLimit: boolean;
  /** The tool radius's range, a surface radius's range, and the smallest length accepted, in the unit. */
  readonly toolRange: readonly [string, string];
  readonly radiusRange: readonly [string, string];
  readonly minLength: string;
}

/** A surface's side at the contact. */
export type Side = 'convex' | 'concave';

/** Sentences the page words in English around numbers (results.ts, copy.ts, fields.ts), in a language. */
export interface SaidWords {
  /** A flat end lying flat on a plane: no scallop; `diameter` is L = 2R with its unit. */
  readonly noScallopPlane: (diameter: string) => string;
  /** Copy's spoken confirmation: the value copied, its unit, the question it answers (or null). */
  readonly copied: (value: string, unit: string, question: string | null) => string;
  /** Copy's spoken failure: the value and its unit to copy by hand. */
  readonly copyFailed: (value: string, unit: string) => string;
  /** An empty optional field's slider (aria-valuetext). */
  readonly empty: string;
  /**
   * A worker that stopped after `restarts` restarts in a row, or was restarted (`restarts` null):
   * the words before and after its reason (the worker's own, kept in English).
   */
  readonly restarted: (who: 'results' | 'views', restarts: string | null) => readonly [string, string];
  /** Before the link values replaced (each named in English, by the link's parameter names). */
  readonly linkReplaced: string;
  /** The roughness's rule of thumb (Ra ~ h/4 with its unit, its error in % against the exact Ra, signed). */
  readonly ruleOfThumb: (ra: string, pct: string) => string;
  /** L as a share of the tool diameter (%, a number). */
  readonly diameterShare: (pct: string) => string;
  /** No Rz, Ra, Rq for waterline passes on a surface of revolution (roughness.ts REVOLUTION_NOTE). */
  readonly revolution: string;
  /** A catalogue tool (toolPresets.ts): its diameter, its corner radius (null: a ball end), the paper's tool number (or null). */
  readonly preset: (d: string, r: string | null, paperTool: string | null) => string;
  /** The preset box's "custom" and its metric group; the chips' legend with its units. */
  readonly custom: string;
  readonly metric: string;
  readonly catalogueTools: (units: string) => string;
  /**
   * A worker's reason for a restart (worker/client.ts, read back by workerReason.ts) as a sentence in
   * the language; an exception's own text is not in it (the page shows it in a hover title).
   */
  readonly reason: (kind: WorkerReason) => string;
  /** A value a formula or the table cannot give (English "n/a"). */
  readonly notAvailable: string;
  /**
   * What L and the heights mean on a cylinder (resultsText.ts surfaceMeaning): its side, its radius
   * with its unit, its axis along or across the feed.
   */
  readonly cylinderMeaning: (side: Side, radius: string, axis: 'feed' | 'cross') => string;
  /** What they mean at a doubly curved point (resultsText.ts curvedMeaning): each radius's side and size with its unit. */
  readonly curvedMeaning: (feed: readonly [Side, string], cross: readonly [Side, string]) => string;
  /** A radius's side box's name (fields.ts buildSide: "Feed radius Rf: convex, concave or straight"), from its field's label. */
  readonly sideBox: (label: string) => string;
  /** The copy-link fallback text box's name (copyLink.ts: "Link to this state"). */
  readonly linkText: string;
  /** A target Ra or Sa (its symbol) asked of three-axis machining (threeAxisRequest.ts: not offered, give h). */
  readonly targetNotOffered: (symbol: string) => string;
  /** The surface box's presets (surfaceState.ts PRESET_LABELS) and its "custom radii", by their keys. */
  readonly surfacePresets: Readonly<Record<SurfacePresetKey, string>>;
  /** The line under the surface box for raster passes on a sloped plane (fields.ts). */
  readonly rasterNote: string;
  /** The lookup table's status when its worker was restarted or gave up (lookupDownload.ts), its reason worded. */
  readonly tableWorker: (gaveUp: boolean, reason: string) => string;
  /**
   * The lookup table's status while it is computed, and once saved (lookupFile.ts tableSummary): the
   * file, its rows, h's range and unit, the grid's other axes (degrees as numbers without their unit),
   * the cells left empty. Numbers with the locale's decimal sign.
   */
  readonly tableComputing: string;
  readonly tableSaved: (
    file: string,
    rows: number,
    h: readonly [string, string],
    unit: string,
    axes:
      | {
          readonly kind: 'five-axis';
          readonly lead: readonly [string, string];
          readonly tilt: readonly [string, string];
        }
      | { readonly kind: 'three-axis'; readonly slope: readonly [string, string]; readonly step: 'Lxy' | 'dz' },
    empty: number,
  ) => string;
}

/** The surface box's presets' keys (surfaceState.ts), and its "custom radii". */
export type SurfacePresetKey = CurvedPreset | WaterlinePreset | 'custom';

/**
 * A link notice's details (i18n/linkNotices.ts reads them back from the page's English): the
 * parameters' names and the values quoted (`Rcr="abc"`) given as they are, kept.
 */
export interface LinkNoticeWords {
  /** Between two details. */
  readonly separator: string;
  /** A number the link's others need is missing: its default used. */
  readonly missing: (name: string, fallback: string) => string;
  /** Not a number: left empty, its default used, a plane (a cylinder's radius's default), a straight line. */
  readonly notNumber: (
    quoted: string,
    then: { readonly kind: 'empty' | 'straight' } | { readonly kind: 'default' | 'plane'; readonly value: string },
  ) => string;
  /** fz given: the feed rate and spindle speed given are not used. */
  readonly notUsed: (given: string, unused: readonly [string, string]) => string;
  /** R and D both given: R (quoted with its value) used. */
  readonly both: (a: string, b: string, used: string) => string;
  /** A cylinder's radius and a doubly curved point's radii both given: the radii used. */
  readonly surfaceBoth: (radius: string, rf: string, rc: string) => string;
  /** A parameter given `times` times: the first used, the others (quoted; `more` not quoted) ignored. */
  readonly repeated: (name: string, times: number, first: string, ignored: readonly string[], more: number) => string;
  /**
   * A choice not among its values: the first used, the language shown, the system's colour scheme
   * followed, presentation mode off; null: a view not one of the views (none used).
   */
  readonly notOneOf: (
    quoted: string,
    values: readonly string[],
    then:
      | { readonly kind: 'using' | 'showing'; readonly value: string }
      | { readonly kind: 'system' | 'presentOff' }
      | null,
  ) => string;
}

/** The kinds of a worker's reason for a restart (worker/client.ts): it failed, threw, did not load, stopped answering. */
export type WorkerReason = 'failed' | 'threw' | 'load' | 'stopped';

/**
 * The surface of a shop sheet, for its title line: lengths given already in the user's unit with
 * their symbol (`30 mm`); a radius of a surface of revolution null when straight.
 */
export type SheetSurface =
  | { readonly kind: 'plane' }
  | { readonly kind: 'sloped-plane' }
  | { readonly kind: 'cylinder'; readonly concave: boolean; readonly radius: string; readonly axis: 'feed' | 'cross' }
  | { readonly kind: 'doubly-curved'; readonly feed: string; readonly cross: string }
  | { readonly kind: 'revolution'; readonly feed: string | null; readonly cross: string | null };

/**
 * The sentences of a shop sheet's refusals that are the sheet's own (core/output/shopSheet.ts
 * SheetRefusal; English: the core's reasons): the lead out of range, the tool gouging a doubly
 * curved point, h at or above that point's limit (with its unit) and what was given, waterline passes
 * without a step-down. The others are the input errors' and the three-axis errors' sentences.
 */
export interface SheetRefusalWords {
  readonly leadRange: string;
  readonly curvedGouge: string;
  readonly curvedWall: (limit: string, got: string) => string;
  readonly noStepDown: string;
}

/** What a sheet's cells give: the step-over L, the horizontal step Lxy (raster) or the step-down dz (waterline). */
export type SheetStep = 'interval' | 'horizontalStep' | 'stepDown';

/**
 * The shop sheet's words (issue 30): every heading, label, note and unit word of the sheet, as
 * functions of its numbers (given as text in the user's unit, `u` its symbol). The symbols (L, Lxy,
 * dz, h, Rcr, the marks' letters W, G, X) stay; the CSV stays English.
 */
export interface SheetWords {
  /** The heading: `Shop sheet: L (mm)`. */
  readonly title: (step: string, u: string) => string;
  /** The tool line: its diameter, radius and corner radius, each with its unit. */
  readonly tool: (d: string, r: string, rcr: string) => string;
  /** Five-axis machining: the tilt (degrees, a number), the pattern, the surface's words. */
  readonly fiveAxis: (tiltDeg: string, pattern: 'one-way' | 'zigzag', surface: string) => string;
  /** Three-axis machining: the passes, the raster angle from the fall line (degrees) or null, the surface's words. */
  readonly threeAxis: (passes: 'raster' | 'waterline', angleDeg: string | null, surface: string) => string;
  /** The surface in words. */
  readonly surface: (s: SheetSurface) => string;
  /** What the rows, the columns and the cells are, in unit `u`. */
  readonly axes: (u: string, columns: 'lead' | 'slope', step: SheetStep) => string;
  /** The last title line: how the numbers were made, and the date (YYYY-MM-DD). */
  readonly made: (date: string) => string;
  /** The table's accessible name (a scrolling region). */
  readonly region: string;
  /** The table's caption (screen readers). */
  readonly caption: (step: string, u: string, columns: 'lead' | 'slope') => string;
  /** The corner's column axis name (lead or slope) and the degrees' unit word. */
  readonly column: Readonly<Record<'lead' | 'slope', string>>;
  readonly deg: string;
  /** After the user's own height in its row (screen readers): ` (your h)`. */
  readonly yourH: string;
  /** Where a refused cell is: its row's h (with unit) and its column (degrees). */
  readonly where: (h: string, columns: 'lead' | 'slope', deg: string) => string;
  /** A mark's button name, and the line a tap on it writes (its reason stays the core's English). */
  readonly markLabel: (letter: string, where: string) => string;
  readonly markReason: (letter: string, where: string) => string;
  /** Each mark's legend. */
  readonly marks: Readonly<Record<'wall' | 'gouge' | 'range', string>>;
  /** The no-scallop star's legend. */
  readonly noScallop: string;
  /** The legend of the bold row: the user's h with its unit. */
  readonly ownRow: (h: string) => string;
  /** How to read a mark's reason, with a pointer and on a touch screen. */
  readonly hintHover: string;
  readonly hintTouch: string;
  /** The heights field's label, and its message for a bad list (`got`: what was wrong, or null). */
  readonly heightsLabel: (u: string, max: number) => string;
  readonly heightsError: (u: string, max: number, got: string | null) => string;
  /** The buttons, and the line after a download. */
  readonly csv: string;
  readonly print: string;
  readonly close: string;
  readonly saved: (fileName: string) => string;
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
