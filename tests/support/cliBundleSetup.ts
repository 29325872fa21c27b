/**
 * Global set-up of the Node tests: the compiled command line current before any test starts it as
 * a process (built here once when stale, not by each of the processes started at the same time).
 */
import { buildCliBundle, cliBundleIsCurrent } from '../../src/cli/bundle.mjs';

export default async function setup(): Promise<void> {
  if (!cliBundleIsCurrent()) await buildCliBundle();
}
