/**
 * The shapes of the words of three teaching views (issue 30): the step-through of the paper's 3D
 * procedure, the formulas and the paper's tables. English is each view's own (views/stepperWords.ts,
 * formulaWords.ts, tableWords.ts); Japanese and German are typed by these shapes in their catalogues,
 * so a missing or an extra key fails the type check. Numbers come as text (lengths with their unit,
 * angles without theirs, the point as decimal sign: the view puts the locale's in); the paper's
 * symbols (L, h, Rcr, rho, d_s, gamma, P_hp, wR, wL) stay. Types only: no code.
 */
import type { ProcedureKey } from '../../core/procedures/procedures';

/** A flank of the step-through: right (+Y) or left (-Y). */
export type Flank = 'right' | 'left';

/**
 * The step-through's words (views/stepperView.ts): the caption of each of its steps (the paper's
 * Figure 1's boxes named), the counter, the d_s / Rcr gauge, the buttons and the notes. `gamma`
 * and the other angles are numbers in degrees without their unit; lengths have theirs.
 */
export interface StepperWords {
  /** Before a step's caption: "Step k of n. ". */
  readonly step: (k: number, n: number) => string;
  /** The flank's name, as a caption starts with it. */
  readonly side: (flank: Flank) => string;
  /** Runs of frames shown as one step: sections of the approach, passes of the search (first, last, how many). */
  readonly merged: (what: 'sections' | 'passes', from: number, to: number, count: number) => string;
  /** Box 2: the first section, where the ring is h/2 above its lowest point. */
  readonly start: (side: string, gamma: string, ds: string, rcr: string) => string;
  /** Boxes 6-11: a section on the way to d_s = Rcr (`gap` is Rcr - d_s; `merged` the run's words or ''). */
  readonly approach: (side: string, merged: string, gamma: string, ds: string, gap: string) => string;
  /** Boxes 12-14: the single-contact section found; none found. */
  readonly single: (side: string, gamma: string) => string;
  readonly noSingle: (side: string) => string;
  /** Boxes 16-25: a search pass (its sections, their range, the best point: its reach out from the contact or null). */
  readonly search: (
    side: string,
    sections: number,
    from: string,
    to: string,
    gamma: string,
    out: string | null,
    merged: string,
  ) => string;
  /** A flank converged: its width wR or wL at gamma*. */
  readonly flankConverged: (side: string, width: 'wR' | 'wL', out: string, gamma: string) => string;
  /** Box 26: both flanks converged, untilted (each flank's L/2) or tilted (wR, wL), against the exact solver's. */
  readonly closingUntilted: (half: string, exact: string) => string;
  readonly closingTilted: (wR: string, wL: string, exactR: string, exactL: string) => string;
  /** Why a step shows the previous step's section and point again (by the step's phase). */
  readonly same: Readonly<Record<'single-contact' | 'search' | 'converged', string>>;
  /** The counter: "step k of n". */
  readonly counter: (k: number, n: number) => string;
  /** The gauge: its label, no d_s in a search step, the ratio with d_s and Rcr. */
  readonly gaugeLabel: string;
  readonly noDs: string;
  readonly ds: (ratio: string, ds: string, rcr: string) => string;
  /** The buttons' words and names, the controls' group name. */
  readonly play: string;
  readonly playOne: string;
  readonly pause: string;
  readonly back: string;
  readonly forward: string;
  readonly names: Readonly<Record<'controls' | 'first' | 'back' | 'forward' | 'last', string>>;
  /** The notes: what the scene shows, reduced motion, a cylinder (shown for a plane only). */
  readonly intro: string;
  readonly motion: string;
  readonly cylinder: string;
}

/** The posture formulas' line titles (threeAxisViewText.ts postureFormulaLines), by their English. */
export type PostureLabel = 'Slope and raster angle' | 'D' | 'Lead' | 'Tilt' | 'Programmed step';

/**
 * The formulas view's words (views/formulasView.ts): what each procedure assumes, the notes around
 * the equations, and the three-axis posture's box. The equations themselves are the paper's symbols.
 */
export interface FormulaWords {
  /** What each procedure assumes (English: the registry's `assumes`). */
  readonly assumes: Readonly<Record<ProcedureKey, string>>;
  /** After a lead-only model's assumptions when the tool is tilted. */
  readonly leadOnly: string;
  /** The equations' box's accessible name, after the procedure's name. */
  readonly maths: (name: string) => string;
  /** On a cylinder: its signed radius with unit and its axis. */
  readonly cylinder: (radius: string, axis: 'feed' | 'cross') => string;
  /** The procedures whose model does not apply here (their short names, joined). */
  readonly notApplicable: (names: string) => string;
  /** The units' line: the length unit, the small one (µm or thou). */
  readonly units: (unit: string, small: string) => string;
  /** Three-axis: the posture box's title and line, each formula line (its title, formula, value), the angles' formula. */
  readonly postureTitle: string;
  readonly postureIntro: string;
  readonly postureLine: (label: string, formula: string, value: string) => string;
  readonly postureLabels: Readonly<Record<PostureLabel, string>>;
  readonly anglesFormula: string;
}

/** The paper's tables' words (views/tablesView.ts): the notes, the captions, the head, the boxes' and rows' names. */
export interface TableWords {
  readonly note: string;
  readonly why: string;
  /** The two tables' captions and short names (their boxes' names start with them). */
  readonly halfCaption: string;
  readonly heightCaption: string;
  readonly halfName: string;
  readonly heightName: string;
  /** A box's accessible name after the table's short name. */
  readonly region: (name: string) => string;
  /** The head's first column, and the printed 3D L/2's column. */
  readonly table: string;
  readonly printedHalf: string;
  /** A row's hover title. */
  readonly load: string;
}
