/**
 * What the first result loads (issue 27 points 2 and 4), read from the sources' static imports
 * (src/build/staticGraph.ts, from which vite.config.ts also groups the chunks): the page validates
 * the fields and loads no surface model (gouging and the limits are the worker's), the worker's
 * first script answers a plane or a cylinder only; the doubly curved and three-axis solvers, the
 * teaching views, the shop sheet, the tool shelf and the lookup table load on first use (dynamic
 * imports).
 */
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { chainTo, staticClosure, staticSpecifiers } from '../../src/build/staticGraph';

const SRC = fileURLToPath(new URL('../../src/', import.meta.url));
const page = staticClosure(`${SRC}main.ts`, SRC);
const worker = staticClosure(`${SRC}worker/solver.worker.ts`, SRC);

/** The three-axis solvers. */
const THREE_AXIS_SOLVERS = [
  'core/threeAxis/solve.ts',
  'core/threeAxis/slopedPlane.ts',
  'core/threeAxis/slopeSweep.ts',
  'core/threeAxis/waterlineRevolution.ts',
  'core/threeAxis/waterlineSolve.ts',
  'core/threeAxis/revolutionGouging.ts',
  'core/threeAxis/meridianCusp.ts',
];
/** Three-axis machining's page builder and the core's validation it calls: loaded with the first three-axis question (app.ts loadThreeAxis). */
const THREE_AXIS_BUILDER = ['ui/threeAxisRequest.ts', 'core/threeAxis/validate.ts'];
/** The doubly curved point's job and checks beyond its solver (gouging by radius, the comparison, roughness). */
const CURVED_JOB = [
  'worker/jobs/curved.ts',
  'worker/data/curvedCheck.ts',
  'worker/data/curvedScene.ts',
  'core/roughness/doublyCurved.ts',
];

/** The files of `closure` that `files` name, each with the chain of imports that loads it. */
function loaded(closure: ReadonlyMap<string, string | null>, files: readonly string[]): string[] {
  return files.filter((f) => closure.has(f)).map((f) => chainTo(closure, f));
}

describe('the static import graph of the first result', () => {
  it('reads static imports and re-exports, not type imports or dynamic imports', () => {
    const source = [
      "import { a } from './a';",
      "import type { B } from './b';",
      "import { type C, type D } from './c';",
      "import { type E, f } from './e';",
      "export { g } from './g';",
      "export * from './h';",
      "import './side';",
      "const later = () => import('./lazy');",
      'export async function load() {',
      "  loaded ??= await import('./later');",
      '}',
      "// import { x } from './comment';",
    ].join('\n');
    expect(staticSpecifiers(source)).toEqual(['./a', './e', './g', './h', './side']);
  });

  it('the page loads no three-axis builder or solving, no doubly curved solving, no teaching view, shop sheet, tool shelf or table grid', () => {
    expect(page.has('ui/app.ts')).toBe(true);
    expect(loaded(page, [...THREE_AXIS_SOLVERS, ...THREE_AXIS_BUILDER, ...CURVED_JOB])).toEqual([]);
    expect(
      loaded(page, [
        'ui/shopSheet.ts',
        'core/output/shopSheet.ts',
        'ui/toolShelf.ts',
        'core/input/toolLibrary.ts',
        'ui/tableRequest.ts',
        'core/output/lookupTable.ts',
        'ui/views/panel.ts',
        'render/scene.ts',
      ]),
    ).toEqual([]);
    // Nothing of the worker's jobs runs on the page.
    expect([...page.keys()].filter((f) => /^worker\/(jobs|data)\//.test(f))).toEqual([]);
  });

  it("the page validates without a surface model: gouging and the limits are the worker's (issue 27 point 4)", () => {
    expect(page.has('core/input/passFields.ts')).toBe(true);
    expect([...page.keys()].filter((f) => /^core\/surfaces\//.test(f)).map((f) => chainTo(page, f))).toEqual([]);
  });

  it("the worker's first script answers a plane or a cylinder; the other jobs load when first asked", () => {
    expect(worker.has('worker/jobs/solve.ts')).toBe(true);
    expect(loaded(worker, [...THREE_AXIS_SOLVERS, ...CURVED_JOB])).toEqual([]);
    expect(
      loaded(worker, [
        'worker/jobs/page.ts',
        'worker/jobs/threeAxis.ts',
        'worker/jobs/teachPage.ts',
        'worker/jobs/teach.ts',
        'worker/jobs/table.ts',
        'worker/simulate.ts',
        'core/simulation/simulation.ts',
      ]),
    ).toEqual([]);
  });
});
