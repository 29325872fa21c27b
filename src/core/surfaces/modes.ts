/**
 * The registry of machine modes (mode.ts), beside the registry of surfaces (registry.ts): each mode
 * descriptor's kind mapped to its mode (one module under modes/). Adding a mode is one new module
 * and one line in MODES (or, for a mode that is not the product's, registerMode). Validation
 * (question.ts) finds the mode here by the descriptor's `kind`, so no caller switches on it.
 */
import type { SurfaceDescriptorBase } from '../domain/surface';
import type { MachineMode, ModeDescriptorBase, OwnAnswer, Posture } from './mode';
import { fiveAxisMode } from './modes/fiveAxis';
import { threeAxisMode } from './modes/threeAxis';

/** Every mode of the product. */
const MODES = [fiveAxisMode, threeAxisMode] as const;

type DescriptorOf<M> = M extends MachineMode<infer D> ? D : never;

/** Every mode descriptor a product mode answers (the union of their descriptor types). */
export type ModeDescriptor = DescriptorOf<(typeof MODES)[number]>;

/** The registered modes: the product's, then any registerMode added. */
const LIST: MachineMode<ModeDescriptorBase>[] = [...(MODES as unknown as readonly MachineMode<ModeDescriptorBase>[])];

/** The product's own mode kinds (the page's machine switch and the command line's own paths answer them). */
export function productModeKinds(): readonly ModeDescriptor['kind'][] {
  return MODES.map((m) => m.kind);
}

/** The registered kinds, in registration order. */
export function modeKinds(): readonly string[] {
  return LIST.map((m) => m.kind);
}

/** The mode of a descriptor kind, or null when none is registered. */
export function findMode<M extends ModeDescriptorBase>(kind: M['kind']): MachineMode<M> | null {
  for (const m of LIST) if (m.kind === kind) return m as MachineMode<M>;
  return null;
}

/**
 * Registers a further mode (one not in MODES: a plug-in's, a test's); returns the function that
 * removes it again. A kind already registered is refused (throws: a programming error).
 */
export function registerMode<M extends ModeDescriptorBase>(mode: MachineMode<M>): () => void {
  if (findMode(mode.kind) !== null) throw new Error(`a machine mode of kind "${mode.kind}" is registered already`);
  const entry = mode as unknown as MachineMode<ModeDescriptorBase>;
  LIST.push(entry);
  return () => {
    const i = LIST.indexOf(entry);
    if (i >= 0) LIST.splice(i, 1);
  };
}

/** True when the mode supplies a posture on this surface (a surface model answers at it). */
export function postureOn(mode: MachineMode<ModeDescriptorBase>, surface: SurfaceDescriptorBase): boolean {
  return mode.surfaceKinds === null || mode.surfaceKinds.includes(surface.kind);
}

/** The mode's own answer on this surface for this descriptor (passes not congruent), or null. */
export function ownAnswerOn(
  mode: MachineMode<ModeDescriptorBase>,
  descriptor: ModeDescriptorBase,
  surface: SurfaceDescriptorBase,
): OwnAnswer<ModeDescriptorBase> | null {
  return mode.ownAnswers?.find((a) => a.surfaceKind === surface.kind && a.applies(descriptor)) ?? null;
}

export type { MachineMode, ModeDescriptorBase, OwnAnswer, Posture };
