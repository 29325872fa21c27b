/**
 * The surface models loaded with the registry besides the plane's and the cylinders': the doubly
 * curved point's, so that in Node (the command line, the library, the tests) every model is there
 * at import and a synchronous lookup needs no load. The site's build puts loadedOnFirstUse.ts in
 * this module's place (vite.config.ts SITE_SOURCES): there these models load on first use
 * (registry.ts loadSurfaceModel), outside the first result.
 */
import type { SurfaceDescriptorBase } from '../../domain/surface';
import type { SurfaceModel } from '../surface';
import { doublyCurvedModel } from './doublyCurved';

/** The models registered at import besides the plane's and the cylinders'. */
export const LOADED_AT_ONCE: readonly SurfaceModel<SurfaceDescriptorBase>[] = [
  doublyCurvedModel as unknown as SurfaceModel<SurfaceDescriptorBase>,
];
