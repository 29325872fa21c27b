/**
 * Build step: the solver worker is a chunk of the page's own build instead of a separate bundle,
 * so the core (validation, solvers, units) that both the page and the worker use is shipped once,
 * in chunks they share (a module worker imports them; the page has them cached already).
 * `virtual:solver-worker-url` default-exports the worker script's URL: in a build, the emitted
 * chunk's; under the dev server, the source module's (which the server transforms).
 */
import { fileURLToPath } from 'node:url';
import type { Plugin } from 'vite';

export const SOLVER_WORKER_URL_ID = 'virtual:solver-worker-url';
const RESOLVED_ID = `\0${SOLVER_WORKER_URL_ID}`;
const WORKER_SOURCE = fileURLToPath(new URL('../worker/solver.worker.ts', import.meta.url));

export function sharedWorkerPlugin(): Plugin {
  let build = false;
  let reference: string | null = null;
  return {
    name: 'shared-solver-worker',
    configResolved(config) {
      build = config.command === 'build';
    },
    buildStart() {
      if (build) reference = this.emitFile({ type: 'chunk', id: WORKER_SOURCE, name: 'solver.worker' });
    },
    resolveId(id) {
      return id === SOLVER_WORKER_URL_ID ? RESOLVED_ID : null;
    },
    load(id) {
      if (id !== RESOLVED_ID) return null;
      if (build && reference !== null) return `export default import.meta.ROLLUP_FILE_URL_${reference};`;
      return `export default new URL('/src/worker/solver.worker.ts', import.meta.url).href;`;
    },
  };
}
