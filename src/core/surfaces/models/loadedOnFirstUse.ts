/**
 * The site's loadedAtOnce.ts (vite.config.ts SITE_SOURCES puts it there): no model beyond the plane's
 * and the cylinders' at import; the doubly curved point's loads on first use (registry.ts
 * loadSurfaceModel), so that it is not part of the first result.
 */
import type { SurfaceDescriptorBase } from '../../domain/surface';
import type { SurfaceModel } from '../surface';

/** The models registered at import besides the plane's and the cylinders': none in the site. */
export const LOADED_AT_ONCE: readonly SurfaceModel<SurfaceDescriptorBase>[] = [];
