/**
 * Command-line arguments: options to a request, or a usage error worded in one line.
 * Pure (no I/O). Values are kept as typed, so `--rho -5` reaches validation and its message.
 */

import { CLI_OPTIONS, type CliOption, cliFlag, FINISH_FIELD_IDS, THREE_AXIS_FIELDS } from '../core/input/fields';
import type { ThreeAxisQuantity } from '../core/threeAxis/validate';
import { type RegistryKinds, registryKinds } from './registryOptions';
import { readPair, X3P_DEFAULT_SIZE, X3P_MAX_CELLS, X3P_MAX_POINTS } from './x3pOption';

/**
 * The command line's settings that take a value but are no field: the length unit, the machine
 * mode and surface kind named from their registries (registryOptions.ts), and the x3p file of the
 * surface the teeth leave (its path, its grid's points and its period cells).
 */
export const SETTING_OPTIONS = ['unit', 'machine', 'surface', 'x3p', 'x3p-size', 'x3p-cells'] as const;

/** The words `--unit` takes: every length in and out in mm or in inches. */
export const CLI_LENGTH_UNITS = ['mm', 'inch'] as const;

/** Options that take a value: one per field of the field registry that the command line takes, and the settings. */
export type ValueOption = CliOption | (typeof SETTING_OPTIONS)[number];
export const VALUE_OPTIONS: readonly ValueOption[] = [...CLI_OPTIONS, ...SETTING_OPTIONS];

/** Options that take no value (not fields: what to do and how to write it). */
export const FLAG_OPTIONS = ['json', 'inverse', 'simulate', 'batch', 'help', 'slope-sweep'] as const;
type FlagOption = (typeof FLAG_OPTIONS)[number];

/** What the command line was asked to do. */
export type Request =
  | { readonly kind: 'help' }
  | {
      readonly kind: 'batch';
      /** The settings given with --batch (only --unit). */
      readonly values: Readonly<Partial<Record<ValueOption, string>>>;
    }
  | {
      /** `forward`: the step-over for a scallop height (--h); `ra`: for a target roughness (--ra). */
      readonly kind: 'forward' | 'ra';
      readonly json: boolean;
      /** True with --simulate: the passes are also simulated (plane only). */
      readonly simulate: boolean;
      readonly values: Readonly<Partial<Record<ValueOption, string>>>;
    }
  | {
      readonly kind: 'inverse';
      readonly json: boolean;
      readonly simulate: boolean;
      readonly values: Readonly<Partial<Record<ValueOption, string>>>;
      /** True when the step-over was given as its half (`--half-interval`). */
      readonly half: boolean;
    }
  | {
      /** Three-axis machining (--slope): the quantity given, h or a step (the inverse). */
      readonly kind: 'threeAxis';
      readonly json: boolean;
      readonly values: Readonly<Partial<Record<ValueOption, string>>>;
      readonly quantity: ThreeAxisQuantity;
    }
  | {
      /**
       * --slope-sweep: three-axis machining over the slopes, the programmed step for h at each and
       * the scallop one constant step leaves (the flat floor's, or --horizontal-step / --step-down).
       */
      readonly kind: 'slopeSweep';
      readonly json: boolean;
      readonly values: Readonly<Partial<Record<ValueOption, string>>>;
    }
  | {
      /**
       * --machine or --surface naming a registered mode or surface the product's own paths do not
       * answer: the one question over the registries (core surfaces/question.ts), given --h or --interval.
       */
      readonly kind: 'question';
      readonly json: boolean;
      readonly values: Readonly<Partial<Record<ValueOption, string>>>;
      readonly kinds: RegistryKinds;
      readonly quantity: 'h' | 'interval';
    }
  | {
      /** --target-sa or --target-rz: the best (step-over, feed per tooth) pair for a finish (targetFinish.ts). */
      readonly kind: 'target';
      readonly target: 'sa' | 'rz';
      readonly json: boolean;
      readonly values: Readonly<Partial<Record<ValueOption, string>>>;
    }
  | { readonly kind: 'usage'; readonly error: string };

function isValueOption(name: string): name is ValueOption {
  return (VALUE_OPTIONS as readonly string[]).includes(name);
}

function isFlagOption(name: string): name is FlagOption {
  return (FLAG_OPTIONS as readonly string[]).includes(name);
}

/** The longest text an error echoes as given: longer text is cut, with an ellipsis. */
export const ECHO_MAX_CHARS = 200;

/** Text as an error echoes it: at most {@link ECHO_MAX_CHARS} characters, then `...`. */
export function cut(text: string): string {
  return text.length > ECHO_MAX_CHARS ? `${text.slice(0, ECHO_MAX_CHARS)}...` : text;
}

function usage(error: string): Request {
  return { kind: 'usage', error };
}

/**
 * Reads `--name value`, `--name=value` and flags. `-h` is `--help`, and help wins over every
 * other argument. A repeated option and contradictory combinations are usage errors.
 */
export function parseArgs(args: readonly string[]): Request {
  const values: Partial<Record<ValueOption, string>> = {};
  const flags = new Set<FlagOption>();
  const order: string[] = [];
  let error: string | null = null;
  let help = false;
  for (let i = 0; i < args.length; i++) {
    const arg = args[i] as string;
    if (arg === '-h' || arg === '--help') {
      help = true;
      continue;
    }
    if (error !== null) continue; // keep scanning for a help request only
    if (!arg.startsWith('--') || arg === '--') {
      error = `unexpected argument "${cut(arg)}"`;
      continue;
    }
    const eq = arg.indexOf('=');
    const name = eq === -1 ? arg.slice(2) : arg.slice(2, eq);
    if (isFlagOption(name)) {
      if (eq !== -1) error = `--${name} takes no value`;
      else if (flags.has(name)) error = `--${name} is given more than once`;
      else {
        flags.add(name);
        order.push(name);
      }
    } else if (isValueOption(name)) {
      let value: string;
      if (eq !== -1) value = arg.slice(eq + 1);
      else {
        const next = args[i + 1];
        if (next === undefined || next.startsWith('--')) {
          error = `--${name} needs a value`;
          continue;
        }
        value = next;
        i++;
      }
      if (values[name] !== undefined) error = `--${name} is given more than once`;
      else {
        values[name] = value;
        order.push(name);
      }
    } else error = `unknown option --${cut(name)}`;
  }
  if (help) return { kind: 'help' };
  if (error !== null) return usage(error);
  // An empty principal radius is straight (the batch's meaning of an empty cell): as if not given.
  for (const name of ['feed-radius', 'cross-radius'] as const) {
    if (values[name]?.trim() === '') delete values[name];
  }

  if (values.R !== undefined && values.D !== undefined) {
    return usage('--R and --D do not go together: give the tool radius R or the diameter D');
  }
  const unit = values.unit?.trim().toLowerCase();
  if (unit !== undefined && unit !== 'mm' && unit !== 'inch' && unit !== 'in') {
    return usage(`--unit must be mm or inch (got "${cut(values.unit ?? '')}")`);
  }
  if (flags.has('batch')) {
    const other = order.find((name) => name !== 'batch' && name !== 'unit');
    if (other === 'json') return usage('--json does not go with --batch: the batch output is CSV');
    if (other !== undefined) {
      return usage(`--${other} does not go with --batch: every case comes from the CSV on stdin`);
    }
    return { kind: 'batch', values };
  }
  const json = flags.has('json');
  const target = targetRequest(values, flags, json);
  if (target !== null) return target;
  const teeth = finishUsage(values, flags);
  if (teeth !== null) return usage(teeth);
  // --machine and --surface: a registered mode and surface; the product's must match the other options.
  const named = registryKinds(values, flags);
  if (typeof named === 'string') return usage(named);
  if (named !== null) {
    const quantity = (['h', 'interval'] as const).filter((q) => values[q] !== undefined);
    if (quantity.length !== 1)
      return usage(`--machine ${named.modeName} over --surface ${named.surface} takes --h <mm> or --interval <mm>`);
    if (FINISH_OPTIONS.some((o) => values[o] !== undefined))
      return usage(`--flutes does not go with --machine ${named.modeName} over --surface ${named.surface}`);
    return { kind: 'question', json, values, kinds: named, quantity: quantity[0] ?? 'h' };
  }
  if (flags.has('slope-sweep')) return slopeSweepRequest(values, flags, json);
  if (values.slope !== undefined) return threeAxisRequest(values, flags, json);
  // The principal radii are also a five-axis surface (a doubly curved point): not three-axis only.
  const threeAxisOnly = THREE_AXIS_FIELDS.find(
    (id) => id !== 'feedRadius' && id !== 'crossRadius' && values[FIELD_OPTION[id]] !== undefined,
  );
  if (threeAxisOnly !== undefined) {
    return usage(`${cliFlag(threeAxisOnly)} is for three-axis machining: give the surface's slope with --slope <deg>`);
  }
  const simulate = flags.has('simulate');
  const hasInterval = values.interval !== undefined;
  const hasHalf = values['half-interval'] !== undefined;
  if (hasInterval && hasHalf) return usage('give the step-over once: --interval (L) or --half-interval (L/2)');
  if (values.h !== undefined && (hasInterval || hasHalf)) {
    return usage(
      `--h and --${hasHalf ? 'half-interval' : 'interval'} do not go together: give --h for the step-over, or the step-over for the scallop height`,
    );
  }
  if (flags.has('inverse') && values.h !== undefined) {
    return usage('--inverse computes h: give --interval <mm> or --half-interval <mm> instead of --h');
  }
  const hasRa = values.ra !== undefined;
  if (hasRa && values.h !== undefined) {
    return usage('--h and --ra do not go together: give the scallop height --h or the target roughness --ra');
  }
  if (hasRa && (flags.has('inverse') || hasInterval || hasHalf)) {
    const other = flags.has('inverse') ? 'inverse' : hasHalf ? 'half-interval' : 'interval';
    return usage(
      `--ra and --${other} do not go together: --ra finds the step-over for a roughness; the inverse gives the roughness of a step-over`,
    );
  }
  const radius = values['surface-radius']?.trim();
  const onPlane = radius === undefined || radius === '' || radius === 'plane';
  const principal = (['feed-radius', 'cross-radius'] as const).find((name) => values[name] !== undefined);
  if (principal !== undefined) {
    const cylinder = (['surface-radius', 'surface-axis'] as const).find((name) => values[name] !== undefined);
    if (cylinder !== undefined) {
      return usage(
        `--${cylinder} and --${principal} do not go together: give the surface once, as --surface-radius with --surface-axis (a cylinder) or as --feed-radius and --cross-radius`,
      );
    }
    if (simulate) {
      return usage(
        '--simulate works on a plane only: the simulation of the passes does not model a curved surface (leave out the radii or --simulate)',
      );
    }
  }
  if (values['surface-axis'] !== undefined && radius === undefined) {
    return usage('--surface-axis needs --surface-radius <mm>: a plane has no axis');
  }
  if (simulate && !onPlane) {
    return usage(
      '--simulate works on a plane only: the simulation of the passes does not model a cylinder (leave out --surface-radius or --simulate)',
    );
  }
  if (flags.has('inverse') || hasInterval || hasHalf) return { kind: 'inverse', json, simulate, values, half: hasHalf };
  return { kind: hasRa ? 'ra' : 'forward', json, simulate, values };
}

/** What a target finds, and so cannot be given beside it; and what it does not model. */
const NOT_WITH_TARGET: ReadonlyArray<readonly [string, string]> = [
  ['h', 'the target sets the scallop'],
  ['ra', 'give one target'],
  ['interval', 'the step-over is the answer'],
  ['half-interval', 'the step-over is the answer'],
  ['inverse', 'the step-over is the answer'],
  ['fz', 'the feed per tooth is the answer'],
  ['feed-rate', 'the feed per tooth is the answer'],
  ['rpm', 'the feed per tooth is the answer'],
  ['simulate', 'the pair is answered without a simulation'],
  ['x3p', 'ask --fz at the step-over found for the file'],
  ['x3p-size', 'ask --fz at the step-over found for the file'],
  ['x3p-cells', 'ask --fz at the step-over found for the file'],
  ['surface-radius', 'the pairs are answered on a plane'],
  ['surface-axis', 'the pairs are answered on a plane'],
  ['feed-radius', 'the pairs are answered on a plane'],
  ['cross-radius', 'the pairs are answered on a plane'],
  ['slope', 'the pairs are answered for a five-axis lead and tilt'],
  ['slope-sweep', 'the pairs are answered for a five-axis lead and tilt'],
  ['machine', 'the pairs are answered for a five-axis lead and tilt on a plane'],
  ['surface', 'the pairs are answered for a five-axis lead and tilt on a plane'],
];

/**
 * --target-sa / --target-rz (targetFinish.ts): one of them, with --flutes, on a plane at a five-axis
 * posture; null when neither is given.
 */
function targetRequest(
  values: Readonly<Partial<Record<ValueOption, string>>>,
  flags: ReadonlySet<string>,
  json: boolean,
): Request | null {
  const sa = values['target-sa'] !== undefined;
  const rz = values['target-rz'] !== undefined;
  if (!sa && !rz) return null;
  if (sa && rz) return usage('--target-sa and --target-rz do not go together: give one target');
  const name = sa ? 'target-sa' : 'target-rz';
  for (const [option, why] of NOT_WITH_TARGET) {
    const given = flags.has(option) || (values as Record<string, string | undefined>)[option] !== undefined;
    if (given) return usage(`--${option} does not go with --${name}: ${why}`);
  }
  for (const id of THREE_AXIS_FIELDS) {
    if (values[FIELD_OPTION[id]] !== undefined)
      return usage(`${cliFlag(id)} does not go with --${name}: the pairs are answered on a plane`);
  }
  if (values.flutes === undefined)
    return usage(`--${name} needs --flutes <N>: the feed per tooth found depends on the teeth`);
  return { kind: 'target', target: sa ? 'sa' : 'rz', json, values };
}

/**
 * The finish options (issue 29: --flutes, --fz, --runout, --runout-phase, --pass-phase; the field
 * registry's finish fields): the feed marks need both the teeth and their feed; the slope sweep does
 * not take them (it answers step-overs only). Null when they are fine (or not given).
 */
function finishUsage(
  values: Readonly<Partial<Record<ValueOption, string>>>,
  flags: ReadonlySet<string>,
): string | null {
  const given = FINISH_OPTIONS.filter((o) => values[o] !== undefined);
  if (given.length === 0) {
    const x3p = (['x3p', 'x3p-size', 'x3p-cells'] as const).find((o) => values[o] !== undefined);
    return x3p === undefined
      ? null
      : `--${x3p} needs --flutes <N> and --fz <mm>: the file holds the surface the teeth leave`;
  }
  if (values.x3p === undefined) {
    const grid = (['x3p-size', 'x3p-cells'] as const).find((o) => values[o] !== undefined);
    if (grid !== undefined) return `--${grid} needs --x3p <file>: it sets the grid of the file written`;
  } else if (values.x3p.trim() === '') return '--x3p needs the path of the file to write';
  const size = readPair('x3p-size', values['x3p-size'], X3P_DEFAULT_SIZE, X3P_MAX_POINTS);
  if (!size.ok) return size.error;
  const cells = readPair('x3p-cells', values['x3p-cells'], [1, 1], X3P_MAX_CELLS);
  if (!cells.ok) return cells.error;
  // The feed per tooth: --fz, or --feed-rate and --rpm, which give it (the core checks the pair).
  const byRate = values['feed-rate'] !== undefined || values.rpm !== undefined;
  const missing = (['flutes', 'fz'] as const).filter((o) => values[o] === undefined && !(o === 'fz' && byRate));
  if (missing.length > 0) {
    return `--${given[0]} needs ${missing.map((o) => (o === 'flutes' ? '--flutes <N>' : '--fz <mm> (or --feed-rate and --rpm)')).join(' and ')}: the feed marks need the number of teeth and the feed per tooth`;
  }
  if (flags.has('slope-sweep'))
    return `--${given[0]} does not go with --slope-sweep: the sweep answers the step-over only`;
  return null;
}

/** The finish fields' options, in the registry's order. */
const FINISH_OPTIONS: readonly ValueOption[] = FINISH_FIELD_IDS.map((id) => cliFlag(id).slice(2) as ValueOption);

/** Each three-axis field's option (the field registry's). */
const FIELD_OPTION = Object.fromEntries(THREE_AXIS_FIELDS.map((id) => [id, cliFlag(id).slice(2)])) as Record<
  (typeof THREE_AXIS_FIELDS)[number],
  ValueOption
>;

/** The options that give the quantity of a three-axis problem, and the quantity each gives. */
const THREE_AXIS_QUANTITIES: ReadonlyArray<readonly [ValueOption, ThreeAxisQuantity]> = [
  ['h', 'h'],
  ['interval', 'interval'],
  ['horizontal-step', 'horizontalStep'],
  ['step-down', 'stepDown'],
];

/** Options of the five-axis case that a three-axis one (--slope) does not take, and why. */
const NOT_WITH_SLOPE: ReadonlyArray<readonly [string, string]> = [
  ['rho', 'the slope (and the raster angle) set the lead and tilt of the upright tool'],
  ['tilt', 'the slope (and the raster angle) set the lead and tilt of the upright tool'],
  ['pattern', 'the upright tool is the same one-way or zigzag'],
  ['surface-radius', 'a surface of revolution is given by --feed-radius and --cross-radius (waterline)'],
  ['surface-axis', 'a surface of revolution is given by --feed-radius and --cross-radius (waterline)'],
  ['ra', 'three-axis machining takes a scallop height --h or a step'],
  ['half-interval', 'give the step along the surface as --interval <mm>'],
  ['inverse', 'a step (--interval, --horizontal-step or --step-down) asks for the cusp height'],
  ['simulate', 'the simulation of the passes models a tool posture on a plane, not the sloped surface'],
];

/** --slope: three-axis machining; its usage errors are the combinations that do not exist. */
function threeAxisRequest(
  values: Readonly<Partial<Record<ValueOption, string>>>,
  flags: ReadonlySet<string>,
  json: boolean,
): Request {
  for (const [name, why] of NOT_WITH_SLOPE) {
    if (values[name as ValueOption] !== undefined || flags.has(name)) {
      return usage(`--${name} does not go with --slope: ${why}`);
    }
  }
  const passes = values.passes?.trim();
  if (passes === 'waterline') {
    // --raster-angle with waterline: 90 (the contour, what waterline passes follow) is accepted and
    // any other angle refused by the core's validation, as in a batch row (one rule, one message).
    if (values['horizontal-step'] !== undefined) {
      return usage('--horizontal-step is the step of raster passes: give waterline passes their --step-down <mm>');
    }
  } else if (passes === undefined || passes === 'raster') {
    for (const name of ['feed-radius', 'cross-radius'] as const) {
      if (values[name] !== undefined) {
        return usage(`--${name} is for waterline passes on a surface of revolution: add --passes waterline`);
      }
    }
    if (values['step-down'] !== undefined) {
      return usage('--step-down is the step of waterline passes: give raster passes their --horizontal-step <mm>');
    }
  }
  const given = THREE_AXIS_QUANTITIES.filter(([option]) => values[option] !== undefined);
  if (given.length > 1) {
    return usage(
      `${given.map(([o]) => `--${o}`).join(' and ')} do not go together: give --h for the step, or one step for the cusp height it leaves`,
    );
  }
  return { kind: 'threeAxis', json, values, quantity: given[0]?.[1] ?? 'h' };
}

/**
 * --slope-sweep: the three-axis options but the slope (swept from 0 to the largest valid), --h, and
 * optionally the constant programmed step (--horizontal-step for raster, --step-down for waterline).
 */
function slopeSweepRequest(
  values: Readonly<Partial<Record<ValueOption, string>>>,
  flags: ReadonlySet<string>,
  json: boolean,
): Request {
  if (values.slope !== undefined) {
    return usage('--slope does not go with --slope-sweep: the sweep runs over every slope from 0 to the largest valid');
  }
  if (values.interval !== undefined) {
    return usage(
      '--interval does not go with --slope-sweep: give --h, and the constant step as --horizontal-step (raster) or --step-down (waterline)',
    );
  }
  if (values.h === undefined) return usage('--slope-sweep needs the scallop height --h <mm>');
  if (values['horizontal-step'] !== undefined && values['step-down'] !== undefined) {
    return usage('--horizontal-step and --step-down do not go together: give the one constant step the passes program');
  }
  // The rest as --slope takes it (the same combinations do not exist), with the sweep's quantity h.
  const checked = threeAxisRequest(
    { ...values, h: undefined, 'horizontal-step': undefined, 'step-down': undefined, slope: '0' },
    flags,
    json,
  );
  if (checked.kind === 'usage') return usage(checked.error.replace('with --slope:', 'with --slope-sweep:'));
  for (const [name, passes] of [
    ['horizontal-step', 'waterline'],
    ['step-down', 'raster'],
  ] as const) {
    if (values[name] !== undefined && (values.passes?.trim() ?? 'raster') === passes) {
      return usage(
        name === 'step-down'
          ? '--step-down is the step of waterline passes: give raster passes their --horizontal-step <mm>'
          : '--horizontal-step is the step of raster passes: give waterline passes their --step-down <mm>',
      );
    }
  }
  return { kind: 'slopeSweep', json, values };
}
