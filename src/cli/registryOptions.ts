/**
 * The command line's `--machine <mode>` and `--surface <kind>` (issue 27 point 3): a machine mode
 * named from the mode registry (core surfaces/modes.ts: `5-axis`, `3-axis` and any mode registered
 * since, by its name or kind) and a surface kind from the surface registry (surfaces/registry.ts: `plane`, `cylinder`,
 * `doublyCurved`, ...). Both are optional and every older option keeps its meaning: the product's
 * modes and surfaces only name what the other options give (three-axis is `--slope`, a cylinder
 * `--surface-radius`, a doubly curved point both principal radii), and a mismatch is a usage error
 * in one line; a registered mode or surface the product's own paths do not answer is asked as the
 * one question over the registries (cli/question.ts answerRegistryQuestion). Pure.
 */
import type { MachineMode, ModeDescriptorBase } from '../core/surfaces/mode';
import { findMode, modeKinds, productModeKinds } from '../core/surfaces/modes';
import { findSurfaceModel, SURFACE_KINDS, surfaceKinds } from '../core/surfaces/registry';

/** The mode and surface a question over the registries is asked of. */
export interface RegistryKinds {
  /** The mode's kind (the registry's key) and the name it was given by. */
  readonly mode: string;
  readonly modeName: string;
  readonly surface: string;
}

type Values = Readonly<Partial<Record<string, string>>>;

/** The words the product's modes are named by (mode.ts `name` for any other, else its kind). */
const PRODUCT_MODE_NAMES: Readonly<Record<string, string>> = { fiveAxis: '5-axis', threeAxis: '3-axis' };

/** The word a user names a mode of this kind by. */
export function modeName(kind: string): string {
  return PRODUCT_MODE_NAMES[kind] ?? findMode(kind)?.name ?? kind;
}

/** The registered modes' names, in registration order (what `--machine` takes). */
export function modeNames(): readonly string[] {
  return modeKinds().map(modeName);
}

/** The mode a user names (by its name, or its kind), or null when none is registered. */
function findModeByName(name: string): MachineMode<ModeDescriptorBase> | null {
  const kind = modeKinds().find((k) => modeName(k) === name) ?? name;
  return findMode(kind);
}

/** A name as a usage error quotes it (a kind is short: longer text is cut). */
function quoted(text: string): string {
  return `"${text.length > 40 ? `${text.slice(0, 40)}...` : text}"`;
}

/** The surface kind the product's own options give (a cylinder by one principal radius alone too). */
function impliedSurface(values: Values, threeAxis: boolean): string {
  const rf = values['feed-radius'] !== undefined;
  const rc = values['cross-radius'] !== undefined;
  if (threeAxis) return rf || rc ? 'doublyCurved' : 'plane';
  if (rf && rc) return 'doublyCurved';
  const radius = values['surface-radius']?.trim();
  if (rf || rc || (radius !== undefined && radius !== '' && radius !== 'plane')) return 'cylinder';
  return 'plane';
}

/** How each product surface is given by the other options. */
const GIVEN_BY: Readonly<Record<string, string>> = {
  plane: 'leave out --surface-radius, --feed-radius and --cross-radius',
  cylinder: 'give its radius with --surface-radius <mm>',
  doublyCurved: 'give --feed-radius <mm> and --cross-radius <mm> (three-axis: waterline on a surface of revolution)',
};

/**
 * The kinds `--machine` and `--surface` name: null when neither is given or both name what the
 * product's own options answer (then those options decide, as before); the kinds of a question
 * over the registries; or a usage error (an unknown name, listed from the registries, or a product
 * mode or surface the other options contradict).
 */
export function registryKinds(values: Values, flags: ReadonlySet<string>): RegistryKinds | string | null {
  const machine = values.machine?.trim();
  const surface = values.surface?.trim();
  if (machine === undefined && surface === undefined) return null;
  const mode = machine === undefined ? null : findModeByName(machine);
  if (machine !== undefined && mode === null)
    return `--machine must be one of ${modeNames().join(', ')} (got ${quoted(machine)})`;
  if (surface !== undefined && findSurfaceModel(surface) === null)
    return `--surface must be one of ${surfaceKinds().join(', ')} (got ${quoted(surface)})`;
  const productMode = mode === null || (productModeKinds() as readonly string[]).includes(mode.kind);
  const productSurface = surface === undefined || (SURFACE_KINDS as readonly string[]).includes(surface);
  if (!productMode || !productSurface)
    return {
      mode: mode?.kind ?? 'fiveAxis',
      modeName: modeName(mode?.kind ?? 'fiveAxis'),
      surface: surface ?? 'plane',
    };
  const threeAxis = values.slope !== undefined || flags.has('slope-sweep');
  if (mode !== null && (mode.kind === 'threeAxis') !== threeAxis)
    return threeAxis
      ? `--machine ${machine} does not go with --slope: the slope is three-axis machining's (give --machine 3-axis, or leave --machine out)`
      : `--machine ${machine} needs the surface's slope: give --slope <deg> (or --slope-sweep)`;
  const implied = impliedSurface(values, threeAxis);
  if (surface !== undefined && surface !== implied)
    return `--surface ${surface} does not match the other options, which give ${implied === 'doublyCurved' ? 'a doubly curved surface' : `a ${implied}`}: ${GIVEN_BY[surface] ?? 'leave out --surface'}`;
  return null;
}
