/**
 * The surface registry: each kind of surface descriptor (domain/surface.ts) mapped to its model
 * (surface.ts's SurfaceModel, one module under models/). Adding a surface is one new module and one
 * line in MODELS; the solvers' entry (solve.ts) and the validation find it here by the descriptor's
 * `kind`, so no caller switches on it.
 */
import type { SurfaceDescriptorBase } from '../domain/surface';
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

const BY_KIND: Readonly<Record<string, SurfaceModel<SurfaceDescriptorBase>>> = Object.fromEntries(
  MODELS.map((m) => [m.kind, m as SurfaceModel<SurfaceDescriptorBase>]),
);

/**
 * The model of a surface descriptor. Throws on an unregistered kind: descriptors come from
 * validation (or a caller's own code), never from raw input, so that is a programming error.
 */
export function surfaceModel<S extends SurfaceDescriptor>(surface: S): SurfaceModel<S> {
  const model = BY_KIND[surface.kind];
  if (model === undefined) throw new Error(`no surface model registered for kind "${surface.kind}"`);
  return model as SurfaceModel<S>;
}
