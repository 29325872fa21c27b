/**
 * The surface registry: each kind of surface descriptor (domain/surface.ts) mapped to its model
 * (surface.ts's SurfaceModel, one module under models/). Adding a surface is one new module and one
 * line in MODELS (or, for a surface that is not the product's, registerSurfaceModel); the solvers'
 * entry (solve.ts) and the validation find it here by the descriptor's `kind`, so no caller switches
 * on it. Machine modes, which supply the posture over these models, have their own registry beside
 * this one (modes.ts): a sloped plane is the plane under the upright tool's mode, not a surface.
 */
import type { ForwardInput } from '../domain/pass';
import type { CylinderSurface, PlaneSurface, SurfaceDescriptorBase } from '../domain/surface';
import { cylinderModel } from './models/cylinder';
import { doublyCurvedModel } from './models/doublyCurved';
import { planeModel } from './models/plane';
import type { SurfaceModel } from './surface';

/** Every registered surface model. */
const MODELS = [planeModel, cylinderModel, doublyCurvedModel] as const;

type DescriptorOf<M> = M extends SurfaceModel<infer S> ? S : never;

/** Every surface descriptor a registered model answers (the union of their descriptor types). */
export type SurfaceDescriptor = DescriptorOf<(typeof MODELS)[number]>;

/** The registered kinds, in registration order. */
export const SURFACE_KINDS: readonly SurfaceDescriptor['kind'][] = MODELS.map((m) => m.kind);

/**
 * The models as an array of one type (a short scan by kind beats a keyed lookup on the solvers' fast
 * paths): the product's, then any registerSurfaceModel added.
 */
const LIST: SurfaceModel<SurfaceDescriptorBase>[] = [...MODELS];

/** The registered kinds now (the product's and any registered since). */
export function surfaceKinds(): readonly string[] {
  return LIST.map((m) => m.kind);
}

/** The model of a descriptor kind, or null when none is registered (validation's question). */
export function findSurfaceModel(kind: string): SurfaceModel<SurfaceDescriptorBase> | null {
  for (let i = 0; i < LIST.length; i++)
    if (LIST[i]?.kind === kind) return LIST[i] as SurfaceModel<SurfaceDescriptorBase>;
  return null;
}

/**
 * Registers a further surface model (one not in MODELS: a plug-in's, a test's); returns the
 * function that removes it again. A kind already registered is refused (throws: a programming error).
 */
export function registerSurfaceModel<S extends SurfaceDescriptorBase>(model: SurfaceModel<S>): () => void {
  if (findSurfaceModel(model.kind) !== null)
    throw new Error(`a surface model of kind "${model.kind}" is registered already`);
  const entry = model as unknown as SurfaceModel<SurfaceDescriptorBase>;
  LIST.push(entry);
  return () => {
    const i = LIST.indexOf(entry);
    if (i >= 0) LIST.splice(i, 1);
  };
}

/**
 * The model of a surface descriptor. Throws on an unregistered kind: descriptors come from
 * validation (or a caller's own code), never from raw input, so that is a programming error.
 */
export function surfaceModel<S extends SurfaceDescriptor>(surface: S): SurfaceModel<S> {
  const kind = surface.kind;
  for (let i = 0; i < LIST.length; i++) {
    const model = LIST[i] as SurfaceModel<SurfaceDescriptorBase>;
    if (model.kind === kind) return model as SurfaceModel<S>;
  }
  throw new Error(`no surface model registered for kind "${kind}"`);
}

/**
 * The exact step-over (mm) of a validated forward input on its surface's model: the solvers' hot
 * path (sweeps, batches, the benchmarks). The plane and the cylinders each have a call site of
 * their own, so that V8 sees one target there and inlines it (one shared `model.intervalMm` call
 * that sees every model was measured at +4 % of the plane's exact solve); any other kind goes
 * through {@link surfaceModel}, so a new model needs no line here.
 */
export function modelIntervalMm(input: ForwardInput<SurfaceDescriptor>): number {
  const surface = input.surface;
  switch (surface.kind) {
    case 'plane':
      return planeModel.intervalMm(input as ForwardInput<PlaneSurface>);
    case 'cylinder':
      return cylinderModel.intervalMm(input as ForwardInput<CylinderSurface>);
    default:
      return surfaceModel<SurfaceDescriptor>(surface).intervalMm(input);
  }
}
