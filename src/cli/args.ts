/**
 * Command-line arguments: options to a request, or a usage error worded in one line.
 * Pure (no I/O). Values are kept as typed, so `--rho -5` reaches validation and its message.
 */

import { CLI_OPTIONS, type CliOption } from '../core/input/fields';

/** Options that take a value: one per field of the field registry that the command line takes. */
export const VALUE_OPTIONS: readonly CliOption[] = CLI_OPTIONS;
export type ValueOption = CliOption;

/** Options that take no value (not fields: what to do and how to write it). */
export const FLAG_OPTIONS = ['json', 'inverse', 'simulate', 'batch', 'help'] as const;
type FlagOption = (typeof FLAG_OPTIONS)[number];

/** What the command line was asked to do. */
export type Request =
  | { readonly kind: 'help' }
  | { readonly kind: 'batch' }
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
  | { readonly kind: 'usage'; readonly error: string };

function isValueOption(name: string): name is ValueOption {
  return (VALUE_OPTIONS as readonly string[]).includes(name);
}

function isFlagOption(name: string): name is FlagOption {
  return (FLAG_OPTIONS as readonly string[]).includes(name);
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
      error = `unexpected argument "${arg}"`;
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
    } else error = `unknown option --${name}`;
  }
  if (help) return { kind: 'help' };
  if (error !== null) return usage(error);

  if (flags.has('batch')) {
    const other = order.find((name) => name !== 'batch');
    if (other === 'json') return usage('--json does not go with --batch: the batch output is CSV');
    if (other !== undefined) {
      return usage(`--${other} does not go with --batch: every case comes from the CSV on stdin`);
    }
    return { kind: 'batch' };
  }
  const json = flags.has('json');
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
