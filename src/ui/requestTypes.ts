/**
 * What building a page request yields, a leaf: request.ts (the plane's and cylinder's, and the
 * dispatch), each mode's and surface's own builder and questionRequest.ts return it, so none imports
 * another for it.
 */
import type { InputError } from '../core/input/validate';
import type { PageRequest } from '../worker/pageProtocol';
import type { FieldKey } from './stateTypes';

/** A message the page words itself (a doubly curved point's, an upright tool's), on its field. */
export interface PageFieldError {
  readonly key: FieldKey;
  readonly message: string;
}

/** A built request (the page's, PageRequest; or another kind R: questionRequest.ts's) or its errors. */
export type BuiltRequest<R = PageRequest> =
  | { readonly ok: true; readonly request: R }
  | { readonly ok: false; readonly errors: readonly (InputError | PageFieldError)[] };
