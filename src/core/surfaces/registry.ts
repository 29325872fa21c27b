/**
 * The surface registry: each kind of surface descriptor (domain/surface.ts) mapped to its model
 * (surface.ts's SurfaceModel, one module under models/). Adding a surface is one new module and one
 * line in PRODUCT (or, for a surface that is not the product's, registerSurfaceModel); the solvers'
 * entry (solve.ts) and the validation find it here by the descriptor's `kind`, so no caller switches
 * on it. Machine modes, which supply the posture over these models, have their own registry beside
 * this one (modes.ts): a sloped plane is the plane under the upright tool's mode, not a surface.
 *
 * The plane's and the cylinders' models load with the registry; the doubly curved point's is loaded
 * at import in Node (models/loadedAtOnce.ts) but on first use in the site (issue 27 point 2: not in
 * the first result): there a caller that may meet such a descriptor awaits loadSurfaceModel(kind)
 * before the synchronous lookups, which refuse (throw) a product kind not loaded yet.
 */
import type { ForwardInput } from '../domain/pass';
import type { CylinderSurface, PlaneSurface, SurfaceDescriptorBase } from '../domain/surface';
import { cylinderModel } from './models/cylinder';
import type { doublyCurvedModel } from './models/doublyCurved';
import { LOADED_AT_ONCE } from './models/loadedAtOnce';
import { planeModel } from './models/plane';
import type { SurfaceModel } from './surface';

type AnyModel = SurfaceModel<SurfaceDescriptorBase>;

/** The product's models in registration order: each loaded with the registry, or by its loader on first use. */
const PRODUCT = [
  { kind: 'plane', model: planeModel as AnyModel },
  { kind: 'cylinder', model: cylinderModel as AnyModel },
  {
    kind: 'doublyCurved',
    load: () => import('./models/doublyCurved').then((m) => m.doublyCurvedModel as unknown as AnyModel),
  },
] as const;

type DescriptorOf<M> = M extends SurfaceModel<infer S> ? S : never;

/** Every surface descriptor a product model answers (the union of their descriptor types). */
export type SurfaceDescriptor = DescriptorOf<typeof planeModel | typeof cylinderModel | typeof doublyCurvedModel>;

/** The registered kinds, in registration order (loaded or not). */
export const SURFACE_KINDS: readonly SurfaceDescriptor['kind'][] = PRODUCT.map((p) => p.kind);

/**
 * The loaded models as an array of one type (a short scan by kind beats a keyed lookup on the
 * solvers' fast paths): the product's (in PRODUCT's order), then any registerSurfaceModel added.
 */
const LIST: AnyModel[] = [...PRODUCT.flatMap((p) => ('model' in p ? [p.model] : [])), ...LOADED_AT_ONCE];

/** A loaded model of `kind`, or undefined. */
function loaded(kind: string): AnyModel | undefined {
  for (let i = 0; i < LIST.length; i++) if (LIST[i]?.kind === kind) return LIST[i];
  return undefined;
}

/** The refusal of a synchronous lookup of a product kind whose model is not loaded yet (a programming error). */
function notLoaded(kind: string): Error {
  return new Error(`the surface model of kind "${kind}" loads on first use: await loadSurfaceModel("${kind}") first`);
}

/** The registered kinds now (the product's and any registered since). */
export function surfaceKinds(): readonly string[] {
  return [
    ...SURFACE_KINDS,
    ...LIST.map((m) => m.kind).filter((k) => !(SURFACE_KINDS as readonly string[]).includes(k)),
  ];
}

/**
 * The model of a descriptor kind, or null when none is registered (validation's question). Throws
 * for a product kind not loaded yet (see loadSurfaceModel).
 */
export function findSurfaceModel(kind: string): AnyModel | null {
  const model = loaded(kind);
  if (model !== undefined) return model;
  if ((SURFACE_KINDS as readonly string[]).includes(kind)) throw notLoaded(kind);
  return null;
}

/**
 * The model of a registered kind, loaded now if it loads on first use (once: the module cache keeps
 * it), after which the synchronous lookups answer it; null for a kind not registered.
 */
export async function loadSurfaceModel(kind: string): Promise<AnyModel | null> {
  const model = loaded(kind);
  if (model !== undefined) return model;
  const entry = PRODUCT.find((p) => p.kind === kind);
  if (entry === undefined || !('load' in entry)) return null;
  const fresh = await entry.load();
  // Another caller's load may have registered it first.
  const again = loaded(kind);
  if (again !== undefined) return again;
  LIST.push(fresh);
  return fresh;
}

/**
 * Registers a further surface model (one not in PRODUCT: a plug-in's, a test's); returns the
 * function that removes it again. A kind already registered is refused (throws: a programming error).
 */
export function registerSurfaceModel<S extends SurfaceDescriptorBase>(model: SurfaceModel<S>): () => void {
  if (surfaceKinds().includes(model.kind))
    throw new Error(`a surface model of kind "${model.kind}" is registered already`);
  const entry = model as unknown as AnyModel;
  LIST.push(entry);
  return () => {
    const i = LIST.indexOf(entry);
    if (i >= 0) LIST.splice(i, 1);
  };
}

/**
 * The model of a surface descriptor. Throws on an unregistered kind: descriptors come from
 * validation (or a caller's own code), never from raw input, so that is a programming error; and on
 * a product kind not loaded yet (see loadSurfaceModel).
 */
export function surfaceModel<S extends SurfaceDescriptor>(surface: S): SurfaceModel<S> {
  const kind = surface.kind;
  for (let i = 0; i < LIST.length; i++) {
    const model = LIST[i] as AnyModel;
    if (model.kind === kind) return model as unknown as SurfaceModel<S>;
  }
  if ((SURFACE_KINDS as readonly string[]).includes(kind)) throw notLoaded(kind);
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
