/**
 * Long for a reason (over 400 lines): the registry is one table of data (about 290 lines, a few per
 * field) and the lookups typed from it; moved to a module of their own and re-exported from here,
 * the lookups would import the table back (an import cycle).
 *
 * The one field registry: every input the calculator takes, with each name it goes by. The core's
 * property (`toolRadiusMm`), its short symbol (`R`), how it is measured (a length, an angle, a word
 * from a list), the label messages give it, its range, and its name on each channel: the page's URL
 * parameter, the command line's flag, the batch's CSV column, the embed element's attribute and the
 * page's field. Validation, the page, the URL, the command line, the batch, the worker and the embed
 * element (public/embed.js, generated from here by src/build/embedAttributes.ts) take their names
 * from this table, so a field is renamed or added here, once. Pure data, no imports.
 *
 * Lengths are mm and angles degrees inside the program; the page's fields and URL hold the user's
 * unit, converted at the edge (ui/request.ts). The rules themselves (cross-field limits, the
 * posture's limits) are validate.ts's; `range` records the fixed bounds that the rules apply.
 */

/**
 * How a field is measured: a length (mm inside), an angle (degrees), one word of a list, a
 * name (plain text, cleaned as hostile: a tool's name), or a plain number without a unit (a count
 * of teeth, a fraction of a period).
 */
export type FieldKind = 'length' | 'angle' | 'enum' | 'text' | 'number';

/**
 * What a field is:
 * - `tool`: the tool and its posture (ToolInput's four numbers);
 * - `pass`: the pass pattern and the design surface (with the tool: PassInput);
 * - `quantity`: the quantity a problem is given (h, L, a target Ra);
 * - `alias`: another form of a field (the diameter D of R, the half step-over L/2 of L);
 * - `threeAxis`: three-axis machining (issue 20: the tool upright, the surface sloped), its
 *   surface, passes and programmed steps; validated by core/threeAxis/validate.ts;
 * - `finish`: the teeth and their feed (issue 29: the surface the teeth leave, feed marks and areal
 *   parameters); validated by core/finish/finishInput.ts;
 * - `page`: a setting of the page only (unit, mode, view...), in its URL and embed element.
 */
export type FieldGroup = 'tool' | 'pass' | 'quantity' | 'alias' | 'threeAxis' | 'finish' | 'page';

/** The fixed bounds of a number (mm or degrees); null where another field or the posture sets it. */
export interface FieldRange {
  readonly min: number | null;
  readonly max: number | null;
  /** True when the bound itself is accepted (`<=`), false for a strict bound (`<`). */
  readonly minIncluded: boolean;
  readonly maxIncluded: boolean;
  /** The whole rule in words, bounds set by other fields included (`0 <= Rcr <= R`). */
  readonly rule: string;
}

/**
 * A column of the batch's CSV: required (R, Rcr, rho), the target (h or Ra), optional (a default
 * when absent or empty), three-axis (a header with `slope` selects three-axis machining), or finish
 * (the teeth and their feed: a row with flutes and fz gets its feed marks and areal parameters).
 */
export interface CsvColumnSpec {
  readonly column: string;
  readonly role: 'required' | 'target' | 'optional' | 'threeAxis' | 'finish';
}

/** Everything the registry says of one field. */
export interface FieldSpec {
  /** The symbol formulas and short texts use (`R`, `Rcr`, `beta`, `L/2`). */
  readonly short: string;
  /** The property of the core's validated input (`toolRadiusMm`; `surface.radiusMm` inside the surface); null for none. */
  readonly core: string | null;
  readonly kind: FieldKind;
  readonly group: FieldGroup;
  /** The field's name in messages and on the page (`Tool radius R`). */
  readonly label: string;
  /** For `alias`: the field it is another form of. */
  readonly aliasOf?: string;
  /** The unit shown after the field where not the length's or degrees alone: appended to a length's symbol ('/min': mm/min), else the whole unit ('rpm'). */
  readonly unit?: string;
  /** Numbers: the fixed bounds validation applies. */
  readonly range?: FieldRange;
  /** Words: the values accepted (the first is the default, where one applies). */
  readonly values?: readonly string[];
  /** The page's URL query parameter; null when the URL does not take it. */
  readonly url: string | null;
  /** The command line's option, without its `--`; null when the command line does not take it. */
  readonly cli: string | null;
  /** The batch's CSV input column; null when the batch does not read it. */
  readonly csv: CsvColumnSpec | null;
  /** The `<path-interval-calculator>` attribute (lower case: HTML folds attribute names); null for none. */
  readonly embed: string | null;
  /** The page's text field (`state.fields` key); null for a switch or a field the page does not show. */
  readonly page: string | null;
}

/**
 * A setting of the page only (not a field of the core, nor of the command line or the batch): one
 * word of `values` (the first is the default), under the URL parameter `name` and, unless
 * `inEmbed` is false, the embed element's attribute of the same name.
 */
function pageSetting<const N extends string, const V extends readonly string[], const E extends boolean = true>(
  name: N,
  label: string,
  values: V,
  inEmbed: E = true as E,
) {
  return {
    short: name,
    core: null,
    kind: 'enum',
    group: 'page',
    label,
    values,
    url: name,
    cli: null,
    csv: null,
    embed: (inEmbed ? name : null) as E extends true ? N : null,
    page: null,
  } as const;
}

/** The registry, in the order the command line lists its options and the page its fields. */
export const FIELDS = {
  R: {
    short: 'R',
    core: 'toolRadiusMm',
    kind: 'length',
    group: 'tool',
    label: 'Tool radius R',
    range: { min: 0.001, max: 1000, minIncluded: true, maxIncluded: true, rule: '0.001 <= R <= 1000 mm' },
    url: 'R',
    cli: 'R',
    csv: { column: 'R', role: 'required' },
    embed: 'r',
    page: 'R',
  },
  D: {
    short: 'D',
    core: null,
    kind: 'length',
    group: 'alias',
    aliasOf: 'R',
    label: 'Tool diameter D',
    url: 'D',
    cli: 'D',
    csv: null,
    embed: 'd',
    page: null,
  },
  Rcr: {
    short: 'Rcr',
    core: 'cornerRadiusMm',
    kind: 'length',
    group: 'tool',
    label: 'Corner radius Rcr',
    range: { min: 0, max: null, minIncluded: true, maxIncluded: true, rule: '0 <= Rcr <= R' },
    url: 'Rcr',
    cli: 'Rcr',
    csv: { column: 'Rcr', role: 'required' },
    embed: 'rcr',
    page: 'Rcr',
  },
  rho: {
    short: 'rho',
    core: 'leadAngleDeg',
    kind: 'angle',
    group: 'tool',
    label: 'Lead angle rho',
    range: { min: 0, max: 90, minIncluded: true, maxIncluded: false, rule: '0 <= rho < 90 degrees' },
    url: 'rho',
    cli: 'rho',
    csv: { column: 'rho', role: 'required' },
    embed: 'rho',
    page: 'rho',
  },
  tilt: {
    short: 'beta',
    core: 'tiltAngleDeg',
    kind: 'angle',
    group: 'tool',
    label: 'Tilt angle beta',
    range: { min: -90, max: 90, minIncluded: false, maxIncluded: false, rule: '-90 < beta < 90 degrees' },
    url: 'tilt',
    cli: 'tilt',
    csv: { column: 'tilt', role: 'optional' },
    embed: 'tilt',
    page: 'tilt',
  },
  pattern: {
    short: 'pattern',
    core: 'pattern',
    kind: 'enum',
    group: 'pass',
    label: 'Pass pattern',
    values: ['one-way', 'zigzag'],
    url: 'pattern',
    cli: 'pattern',
    csv: { column: 'pattern', role: 'optional' },
    embed: 'pattern',
    page: null,
  },
  surfaceRadius: {
    short: 'Rs',
    core: 'surface.radiusMm',
    kind: 'length',
    group: 'pass',
    label: 'Surface radius Rs',
    range: {
      min: 0.001,
      max: 1e6,
      minIncluded: true,
      maxIncluded: true,
      rule: '0.001 <= |Rs| <= 1e6 mm, > 0 convex, < 0 concave; none for a plane',
    },
    url: 'surfaceRadius',
    cli: 'surface-radius',
    csv: { column: 'surfaceRadius', role: 'optional' },
    embed: 'surface-radius',
    page: 'Rs',
  },
  surfaceAxis: {
    short: 'axis',
    core: 'surface.axis',
    kind: 'enum',
    group: 'pass',
    label: 'Cylinder axis',
    values: ['feed', 'cross'],
    url: 'surfaceAxis',
    cli: 'surface-axis',
    csv: { column: 'surfaceAxis', role: 'optional' },
    embed: 'surface-axis',
    page: null,
  },
  h: {
    short: 'h',
    core: 'scallopHeightMm',
    kind: 'length',
    group: 'quantity',
    label: 'Scallop height h',
    range: { min: 1e-9, max: null, minIncluded: true, maxIncluded: false, rule: '1e-9 mm <= h < the posture limit' },
    url: 'h',
    cli: 'h',
    csv: { column: 'h', role: 'target' },
    embed: 'h',
    page: 'h',
  },
  ra: {
    short: 'Ra',
    core: 'targetRaMm',
    kind: 'length',
    group: 'quantity',
    label: 'Roughness Ra',
    range: { min: 1e-9, max: null, minIncluded: true, maxIncluded: false, rule: '1e-9 mm <= Ra < the largest Ra' },
    url: 'ra',
    cli: 'ra',
    csv: { column: 'Ra', role: 'target' },
    embed: 'ra',
    page: 'ra',
  },
  /** The surface the teeth leave (issue 29): the best (L, fz) pair for a target Sa (command line, page's `target=sa`). */
  targetSa: {
    short: 'Sa',
    core: 'targetSaMm',
    kind: 'length',
    group: 'quantity',
    label: 'Target Sa',
    range: { min: 1e-9, max: null, minIncluded: true, maxIncluded: false, rule: '1e-9 mm <= Sa < the largest Ra' },
    url: 'sa',
    cli: 'target-sa',
    csv: null,
    embed: 'sa',
    page: 'sa',
  },
  /** The best (L, fz) pair whose scallop h and feed marks hf are both at most a target Rz (command line). */
  targetRz: {
    short: 'Rz',
    core: 'targetRzMm',
    kind: 'length',
    group: 'quantity',
    label: 'Target Rz',
    range: { min: 1e-9, max: null, minIncluded: true, maxIncluded: false, rule: '1e-9 mm <= Rz < the posture limit' },
    url: null,
    cli: 'target-rz',
    csv: null,
    embed: null,
    page: null,
  },
  interval: {
    short: 'L',
    core: 'intervalMm',
    kind: 'length',
    group: 'quantity',
    label: 'Step-over L',
    range: { min: 2e-9, max: null, minIncluded: true, maxIncluded: false, rule: '2e-9 mm <= L < the widest step-over' },
    url: 'L',
    cli: 'interval',
    // `interval` is a result column of the batch (the exact step-over): its input is named as in the URL.
    csv: { column: 'L', role: 'target' },
    embed: 'l',
    page: 'L',
  },
  halfInterval: {
    short: 'L/2',
    core: null,
    kind: 'length',
    group: 'alias',
    aliasOf: 'interval',
    label: 'Half path interval L/2',
    url: null,
    cli: 'half-interval',
    csv: null,
    embed: null,
    page: null,
  },
  slope: {
    short: 'alpha',
    core: 'slopeDeg',
    kind: 'angle',
    group: 'threeAxis',
    label: 'Slope alpha',
    range: {
      min: 0,
      max: 90,
      minIncluded: true,
      maxIncluded: true,
      rule: '0 <= alpha <= 90 degrees (90 only for waterline on a concave meridian: elsewhere a vertical wall is cut flat or overhangs); above 0 for waterline',
    },
    url: 'slope',
    cli: 'slope',
    csv: { column: 'slope', role: 'threeAxis' },
    embed: 'slope',
    page: 'slope',
  },
  passes: {
    short: 'passes',
    core: 'passes',
    kind: 'enum',
    group: 'threeAxis',
    label: 'Pass strategy',
    values: ['raster', 'waterline'],
    url: 'passes',
    cli: 'passes',
    csv: { column: 'passes', role: 'threeAxis' },
    embed: 'passes',
    page: null,
  },
  rasterAngle: {
    short: 'psi',
    core: 'rasterAngleDeg',
    kind: 'angle',
    group: 'threeAxis',
    label: 'Raster angle psi',
    range: { min: 0, max: 90, minIncluded: true, maxIncluded: true, rule: '0 <= psi <= 90 degrees from the fall line' },
    url: 'rasterAngle',
    cli: 'raster-angle',
    csv: { column: 'rasterAngle', role: 'threeAxis' },
    embed: 'raster-angle',
    page: 'psi',
  },
  feedRadius: {
    short: 'Rf',
    core: 'feedRadiusMm',
    kind: 'length',
    group: 'threeAxis',
    label: 'Feed radius Rf',
    range: {
      min: 0.001,
      max: 1e6,
      minIncluded: true,
      maxIncluded: true,
      rule: '0.001 <= |Rf| <= 1e6 mm, > 0 convex, < 0 concave; none for straight',
    },
    url: 'feedRadius',
    cli: 'feed-radius',
    csv: { column: 'feedRadius', role: 'threeAxis' },
    embed: 'feed-radius',
    page: 'Rf',
  },
  crossRadius: {
    short: 'Rc',
    core: 'crossRadiusMm',
    kind: 'length',
    group: 'threeAxis',
    label: 'Cross radius Rc',
    range: {
      min: 0.001,
      max: 1e6,
      minIncluded: true,
      maxIncluded: true,
      rule: '0.001 <= |Rc| <= 1e6 mm, > 0 convex, < 0 concave; none for straight',
    },
    url: 'crossRadius',
    cli: 'cross-radius',
    csv: { column: 'crossRadius', role: 'threeAxis' },
    embed: 'cross-radius',
    page: 'Rc',
  },
  horizontalStep: {
    short: 'Lxy',
    core: 'horizontalStepMm',
    kind: 'length',
    group: 'threeAxis',
    label: 'Horizontal step Lxy',
    range: { min: 1e-9, max: null, minIncluded: true, maxIncluded: false, rule: '1e-9 mm <= Lxy < the widest step' },
    url: 'Lxy',
    cli: 'horizontal-step',
    csv: null,
    embed: 'lxy',
    page: 'Lxy',
  },
  stepDown: {
    short: 'dz',
    core: 'stepDownMm',
    kind: 'length',
    group: 'threeAxis',
    label: 'Step-down dz',
    range: {
      min: 1e-9,
      max: null,
      minIncluded: true,
      maxIncluded: false,
      rule: '1e-9 mm <= dz < the largest step-down',
    },
    url: 'dz',
    cli: 'step-down',
    csv: null,
    embed: 'dz',
    page: 'dz',
  },
  /** The surface the teeth leave (issue 29; shared/notes/surface-finish.md): the number of teeth. */
  flutes: {
    short: 'z',
    core: 'flutes',
    kind: 'number',
    group: 'finish',
    label: 'Flutes z',
    range: { min: 1, max: 64, minIncluded: true, maxIncluded: true, rule: 'a whole number of teeth, 1 <= z <= 64' },
    url: 'z',
    cli: 'flutes',
    csv: { column: 'flutes', role: 'finish' },
    embed: 'flutes',
    page: 'z',
  },
  fz: {
    short: 'fz',
    core: 'feedPerToothMm',
    kind: 'length',
    group: 'finish',
    label: 'Feed per tooth fz',
    range: { min: 1e-6, max: null, minIncluded: true, maxIncluded: true, rule: '1e-6 mm <= fz <= R' },
    url: 'fz',
    cli: 'fz',
    csv: { column: 'fz', role: 'finish' },
    embed: 'fz',
    page: 'fz',
  },
  /** Feed rate and spindle speed, which give fz = F / (n z) (the page: used while fz is empty). */
  feedRate: {
    short: 'F',
    core: 'feedRateMmPerMin',
    kind: 'length',
    unit: '/min',
    group: 'finish',
    label: 'Feed rate F',
    range: { min: 0, max: null, minIncluded: false, maxIncluded: true, rule: 'F > 0, with n' },
    url: 'F',
    cli: 'feed-rate',
    csv: { column: 'feedRate', role: 'finish' },
    embed: 'feed-rate',
    page: 'F',
  },
  spindleSpeed: {
    short: 'n',
    core: 'spindleRpm',
    kind: 'number',
    unit: 'rpm',
    group: 'finish',
    label: 'Spindle speed n',
    range: { min: 0, max: null, minIncluded: false, maxIncluded: true, rule: 'n > 0, with F' },
    url: 'rpm',
    cli: 'rpm',
    csv: { column: 'rpm', role: 'finish' },
    embed: 'rpm',
    page: 'n',
  },
  runout: {
    short: 'e',
    core: 'runoutMm',
    kind: 'length',
    group: 'finish',
    label: 'Runout e',
    range: { min: 0, max: null, minIncluded: true, maxIncluded: true, rule: '0 <= e <= R/10 (default 0)' },
    url: 'runout',
    cli: 'runout',
    csv: { column: 'runout', role: 'finish' },
    embed: 'runout',
    page: 'runout',
  },
  runoutPhase: {
    short: 'phi_e',
    core: 'runoutPhaseDeg',
    kind: 'angle',
    group: 'finish',
    label: 'Runout phase',
    range: {
      min: null,
      max: null,
      minIncluded: true,
      maxIncluded: true,
      rule: 'any finite angle in degrees from tooth 0 (default 0)',
    },
    url: 'runoutPhase',
    cli: 'runout-phase',
    csv: { column: 'runoutPhase', role: 'finish' },
    embed: 'runout-phase',
    page: 'runoutPhase',
  },
  passPhase: {
    short: 'q',
    core: 'passPhase',
    kind: 'number',
    group: 'finish',
    label: 'Pass phase q',
    range: { min: 0, max: 1, minIncluded: true, maxIncluded: false, rule: '0 <= q < 1 of the feed period (default 0)' },
    url: 'passPhase',
    cli: 'pass-phase',
    csv: { column: 'passPhase', role: 'finish' },
    embed: 'pass-phase',
    page: 'passPhase',
  },
  unit: pageSetting('unit', 'Unit', ['mm', 'in'] as const),
  /** The machine: five-axis (lead and tilt given) or three-axis (the tool upright, the slope sets them; issue 20). */
  machine: pageSetting('machine', 'Machine', ['5axis', '3axis'] as const),
  mode: pageSetting('mode', 'Mode', ['forward', 'inverse'] as const),
  target: pageSetting('target', 'Given in forward mode', ['h', 'ra', 'sa'] as const),
  /**
   * A teaching view shown alone (with `embed`), or `result`: an embed's compact card (the inputs in a
   * line, the answer and Copy; src/ui/embedCard.ts), no teaching view.
   */
  view: pageSetting('view', 'Teaching view', [
    'profile',
    'chart',
    'tables',
    'stepper',
    'formulas',
    'surface',
    'result',
  ] as const),
  /** Light, dark, or auto (the system's colour scheme, as without it; the embed element resolves it to its host page's). */
  theme: pageSetting('theme', 'Theme', ['light', 'dark', 'auto'] as const),
  /** The page's language (issue 30): English, Japanese, German; an embed's `lang` attribute. */
  lang: pageSetting('lang', 'Language', ['en', 'ja', 'de'] as const),
  /** The projector's layout (the 3D scene and the open view fill the screen); the full page only, so no attribute. */
  present: pageSetting('present', 'Presentation mode', ['1'] as const, false),
  // The element sets `embed` itself: no attribute.
  embed: pageSetting('embed', 'Embedded', ['1', 'true'] as const, false),
  /**
   * The name of the saved or library tool the fields hold (issue 28 point 3), named with the answer
   * and carried by Copy link; read as hostile text (src/ui/toolName.ts). The full page's only.
   */
  tool: {
    short: 'tool',
    core: null,
    kind: 'text',
    group: 'page',
    label: 'Tool name',
    url: 'tool',
    cli: null,
    csv: null,
    embed: null,
    page: null,
  },
} as const satisfies Readonly<Record<string, FieldSpec>>;

type Fields = typeof FIELDS;

/** Every registry entry's id. */
export type FieldId = keyof Fields;

/** The fields an input error can name: the tool, the pass and the problems' quantities (validate.ts). */
export type FieldName = {
  [K in FieldId]: Fields[K]['group'] extends 'tool' | 'pass' | 'quantity' ? K : never;
}[FieldId];

/** The tool and posture fields (ToolInput), in order. */
export type ToolFieldName = { [K in FieldId]: Fields[K]['group'] extends 'tool' ? K : never }[FieldId];

/** The tool, posture, pattern and surface fields (PassInput), in order. */
export type PassFieldName = { [K in FieldId]: Fields[K]['group'] extends 'tool' | 'pass' ? K : never }[FieldId];

/** The page's text fields (`state.fields` keys). */
export type PageFieldKey = { [K in FieldId]: Fields[K]['page'] }[FieldId] & string;

/** The command line's value options (without `--`). */
export type CliOption = { [K in FieldId]: Fields[K]['cli'] }[FieldId] & string;

/** The batch's input columns. */
export type CsvColumn = { [K in FieldId]: Fields[K]['csv'] extends { column: infer C } ? C : never }[FieldId];

/** The registry as a plain list, in its order. */
const ENTRIES = Object.entries(FIELDS) as ReadonlyArray<readonly [FieldId, FieldSpec]>;

/** The ids of the entries that `keep` selects, in the registry's order. */
function idsWhere<K extends FieldId>(keep: (spec: FieldSpec) => boolean): readonly K[] {
  return ENTRIES.filter(([, spec]) => keep(spec)).map(([id]) => id as K);
}

/** The tool and posture fields: R, Rcr, rho, tilt. */
export const TOOL_FIELDS: readonly ToolFieldName[] = idsWhere((s) => s.group === 'tool');

/** The fields of a pass: the tool fields, then the pattern and the surface. */
export const PASS_FIELDS: readonly PassFieldName[] = idsWhere((s) => s.group === 'tool' || s.group === 'pass');

/** Every field an input error can name. */
export const FIELD_NAMES: readonly FieldName[] = idsWhere(
  (s) => s.group === 'tool' || s.group === 'pass' || s.group === 'quantity',
);

/** The label of each field as messages name it. */
export const FIELD_LABELS: Readonly<Record<FieldName, string>> = Object.fromEntries(
  FIELD_NAMES.map((name) => [name, FIELDS[name].label]),
) as Record<FieldName, string>;

/** True for fields measured as lengths (mm inside; converted to the user's unit at the edges). */
export function isLengthField(id: FieldId): boolean {
  return FIELDS[id].kind === 'length';
}

/** The page's text fields, in the registry's order (the form's order). */
export const PAGE_FIELD_KEYS: readonly PageFieldKey[] = ENTRIES.flatMap(([, s]) =>
  s.page === null ? [] : [s.page as PageFieldKey],
);

/** The field behind a page's text field (a tool, pass or quantity field, or a three-axis one). */
export function fieldOfPageKey(key: PageFieldKey): FieldName | ThreeAxisFieldName {
  const found = ENTRIES.find(([, s]) => s.page === key);
  if (found === undefined) throw new Error(`no field has the page key ${key}`);
  return found[0] as FieldName | ThreeAxisFieldName;
}

/** The page's text field of a field, or null for a switch (pattern, axis) or none. */
export function pageKeyOf(id: FieldId): PageFieldKey | null {
  return FIELDS[id].page as PageFieldKey | null;
}

/** The command line's value options, in the registry's order. */
export const CLI_OPTIONS: readonly CliOption[] = ENTRIES.flatMap(([, s]) =>
  s.cli === null ? [] : [s.cli as CliOption],
);

/** The command-line option of a field, with its `--` (`--surface-radius`). */
export function cliFlag(id: FieldId): string {
  const cli = FIELDS[id].cli;
  if (cli === null) throw new Error(`the command line has no option for ${id}`);
  return `--${cli}`;
}

/** The batch's columns of one role, in the registry's order. */
function csvColumns(role: CsvColumnSpec['role']): readonly CsvColumn[] {
  return ENTRIES.flatMap(([, s]) => (s.csv !== null && s.csv.role === role ? [s.csv.column as CsvColumn] : []));
}

/** The batch's required columns (R, Rcr, rho), its targets (h or Ra) and its optional columns, in the order they are echoed. */
export const CSV_REQUIRED_COLUMNS = csvColumns('required');
export const CSV_TARGET_COLUMNS = csvColumns('target');
export const CSV_OPTIONAL_COLUMNS = csvColumns('optional');
/** The batch's three-axis columns (slope, passes, rasterAngle, feedRadius, crossRadius), in the order they are echoed. */
export const CSV_THREE_AXIS_COLUMNS = csvColumns('threeAxis');
/** The finish fields (issue 29): the teeth and their feed, in the registry's order. */
export const FINISH_FIELD_IDS: readonly FieldId[] = idsWhere((s) => s.group === 'finish');
/** The optional finish columns (issue 29): a row with flutes and fz gets feed marks and areal parameters. */
export const CSV_FINISH_COLUMNS = csvColumns('finish');

/** The three-axis fields (slope, passes, raster angle, the surface's radii, the programmed steps), in order. */
export type ThreeAxisFieldName = { [K in FieldId]: Fields[K]['group'] extends 'threeAxis' ? K : never }[FieldId];
export const THREE_AXIS_FIELDS: readonly ThreeAxisFieldName[] = idsWhere((s) => s.group === 'threeAxis');

/** The field read from a CSV column, or null for a column the batch does not read. */
export function fieldOfCsvColumn(column: string): FieldName | null {
  const found = ENTRIES.find(([, s]) => s.csv?.column === column);
  return found === undefined ? null : (found[0] as FieldName);
}

/** The CSV column of a field (it must have one). */
export function csvColumnOf(id: FieldId): CsvColumn {
  const csv = FIELDS[id].csv;
  if (csv === null) throw new Error(`the batch has no column for ${id}`);
  return csv.column as CsvColumn;
}

/** Every URL query parameter the page reads, in the registry's order. */
export const URL_PARAMS: readonly string[] = ENTRIES.flatMap(([, s]) => (s.url === null ? [] : [s.url]));

/** The URL query parameter of a field (it must have one). */
export function urlParamOf(id: FieldId): string {
  const url = FIELDS[id].url;
  if (url === null) throw new Error(`the URL has no parameter for ${id}`);
  return url;
}

/**
 * The `<path-interval-calculator>` attributes and the URL query parameter each becomes, in the
 * registry's order: every field the URL takes, but `embed` (the element sets it).
 */
export const EMBED_ATTRIBUTES: ReadonlyArray<readonly [attribute: string, param: string]> = ENTRIES.flatMap(([, s]) =>
  s.embed === null || s.url === null ? [] : [[s.embed, s.url] as const],
);

/** The embed element's attribute for a URL query parameter, or null when the element has none. */
export function embedAttributeOfParam(param: string): string | null {
  return EMBED_ATTRIBUTES.find(([, p]) => p === param)?.[0] ?? null;
}
