/**
 * Command-line arguments: options to a request, or a usage error worded in one line.
 * Pure (no I/O). Values are kept as typed, so `--rho -5` reaches validation and its message.
 */

/** Options that take a value, and the field of the core each one feeds. */
export const VALUE_OPTIONS = ['R', 'Rcr', 'rho', 'tilt', 'pattern', 'h', 'interval', 'half-interval'] as const;
export type ValueOption = (typeof VALUE_OPTIONS)[number];

const FLAG_OPTIONS = ['json', 'inverse', 'batch', 'help'] as const;
type FlagOption = (typeof FLAG_OPTIONS)[number];

/** What the command line was asked to do. */
export type Request =
  | { readonly kind: 'help' }
  | { readonly kind: 'batch' }
  | {
      readonly kind: 'forward';
      readonly json: boolean;
      readonly values: Readonly<Partial<Record<ValueOption, string>>>;
    }
  | {
      readonly kind: 'inverse';
      readonly json: boolean;
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
  if (flags.has('inverse') || hasInterval || hasHalf) return { kind: 'inverse', json, values, half: hasHalf };
  return { kind: 'forward', json, values };
}
