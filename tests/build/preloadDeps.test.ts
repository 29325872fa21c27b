/**
 * What a dynamic import preloads (src/build/preloadDeps.ts): the chunks the imported module needs
 * less those its importer loaded already through its static imports (transitively), everything for
 * the page's HTML, and nothing in the solver worker or a chunk it runs. Chunk graphs written out by hand (file -> its
 * static imports), as Rolldown's bundle gives them to the plugin.
 */
import type { OutputBundle } from 'rolldown';
import { describe, expect, it } from 'vitest';
import { preloadDeps } from '../../src/build/preloadDeps';

/** The plugin given a bundle of chunks (file -> static imports), and its resolver. */
function resolverOf(chunks: Record<string, string[]>) {
  const { plugin, resolveDependencies } = preloadDeps();
  const bundle = Object.fromEntries(
    Object.entries(chunks).map(([fileName, imports]) => [fileName, { type: 'chunk', fileName, imports }]),
  ) as unknown as OutputBundle;
  const hook = plugin.generateBundle as { handler: (options: unknown, bundle: OutputBundle) => void };
  hook.handler({}, bundle);
  return resolveDependencies;
}

describe('the chunks a dynamic import preloads', () => {
  const resolve = resolverOf({
    'assets/index.js': ['assets/core.js', 'assets/helper.js'],
    'assets/core.js': ['assets/math.js'],
    'assets/math.js': [],
    'assets/helper.js': [],
    'assets/view.js': ['assets/core.js', 'assets/three.js', 'assets/math.js'],
    'assets/three.js': [],
    'assets/solver.worker.js': ['assets/core.js'],
  });

  it('leaves out what the importer imports statically, directly or through another chunk', () => {
    const deps = ['assets/view.js', 'assets/core.js', 'assets/three.js', 'assets/math.js'];
    expect(resolve('assets/view.js', deps, { hostId: 'assets/index.js', hostType: 'js' })).toEqual([
      'assets/view.js',
      'assets/three.js',
    ]);
    // A chunk that imports none of them preloads them all.
    expect(resolve('assets/view.js', deps, { hostId: 'assets/helper.js', hostType: 'js' })).toEqual(deps);
  });

  it('preloads all for the page, nothing in the worker', () => {
    const deps = ['assets/index.js', 'assets/core.js'];
    expect(resolve('assets/index.js', deps, { hostId: 'index.html', hostType: 'html' })).toEqual(deps);
    expect(
      resolve('assets/view.js', ['assets/view.js'], { hostId: 'assets/solver.worker.js', hostType: 'js' }),
    ).toEqual([]);
  });

  it('nothing from a chunk the worker runs too (the core, shared with the page): its document is missing', () => {
    // The registry's load of the doubly curved model is in the core chunk and runs in the worker.
    const deps = ['assets/view.js', 'assets/three.js'];
    expect(resolve('assets/view.js', deps, { hostId: 'assets/core.js', hostType: 'js' })).toEqual([]);
    expect(resolve('assets/view.js', deps, { hostId: 'assets/math.js', hostType: 'js' })).toEqual([]);
  });
});
