/**
 * The doubly curved point's model loads on first use in the site (issue 27 point 2): the site's
 * build takes models/loadedOnFirstUse.ts in place of models/loadedAtOnce.ts (src/build/siteSources.ts),
 * so neither the page's nor the worker's first script reaches the model or its solvers; the registry
 * then refuses a synchronous lookup of that kind until loadSurfaceModel has loaded it, and answers it
 * as Node's registry does afterwards. Node's registry (every model at import) is the one the other
 * tests use; this file mocks loadedAtOnce.ts into the site's form.
 */
import { fileURLToPath } from 'node:url';
import { describe, expect, it, vi } from 'vitest';
import { siteSources } from '../../src/build/siteSources';
import { chainTo, staticClosure } from '../../src/build/staticGraph';
import type { DoublyCurvedSurface } from '../../src/core/domain/surface';

vi.mock(
  '../../src/core/surfaces/models/loadedAtOnce',
  async () => import('../../src/core/surfaces/models/loadedOnFirstUse'),
);

const SRC = fileURLToPath(new URL('../../src/', import.meta.url));
const SITE = siteSources(SRC);
const CURVED = /^core\/surfaces\/(models\/doublyCurved|doublyCurved\/)/;

/** The doubly curved files `entry` loads at once, each with its chain of imports. */
function curvedFiles(entry: string, replaced?: ReadonlyMap<string, string>): string[] {
  const closure = staticClosure(`${SRC}${entry}`, SRC, replaced);
  return [...closure.keys()].filter((f) => CURVED.test(f)).map((f) => chainTo(closure, f));
}

const TOOL = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 10, tiltAngleDeg: 0 };
const SURFACE: DoublyCurvedSurface = { kind: 'doublyCurved', feedRadiusMm: 40, crossRadiusMm: -200 };

describe('the doubly curved model on first use (the site)', () => {
  it("neither the page's nor the worker's first script loads the doubly curved model or its solvers; Node's do", () => {
    expect(curvedFiles('main.ts', SITE)).toEqual([]);
    expect(curvedFiles('worker/solver.worker.ts', SITE)).toEqual([]);
    // Without the site's sources the worker reaches it through the registry: the replacement is what
    // keeps it out. The page reaches no surface model at all (it validates the fields only, issue 27
    // point 4; tests/build/firstResult.test.ts).
    expect(curvedFiles('worker/solver.worker.ts').length).toBeGreaterThan(0);
    expect(curvedFiles('main.ts')).toEqual([]);
  });

  it('refuses a synchronous lookup before the load, answers as the model itself after it, and keeps the kinds', async () => {
    // Fresh modules: the Node project shares modules between files (isolate: false), and another
    // file may have loaded the registry with Node's models already.
    vi.resetModules();
    const { doublyCurvedModel } = await import('../../src/core/surfaces/models/doublyCurved');
    const { findSurfaceModel, loadSurfaceModel, registerSurfaceModel, SURFACE_KINDS, surfaceKinds, surfaceModel } =
      await import('../../src/core/surfaces/registry');
    expect(SURFACE_KINDS).toEqual(['plane', 'cylinder', 'doublyCurved']);
    expect(surfaceKinds()).toEqual(['plane', 'cylinder', 'doublyCurved']);
    expect(() => surfaceModel(SURFACE)).toThrow(/loadSurfaceModel\("doublyCurved"\)/);
    expect(() => findSurfaceModel('doublyCurved')).toThrow(/first use/);
    expect(findSurfaceModel('sphere')).toBeNull();
    expect(() => registerSurfaceModel({ ...doublyCurvedModel })).toThrow(/registered already/);
    // A plug-in registered before the load stays after the product's models.
    const remove = registerSurfaceModel({ ...doublyCurvedModel, kind: 'plugin' } as never);
    expect(await loadSurfaceModel('sphere')).toBeNull();
    expect((await loadSurfaceModel('plane'))?.kind).toBe('plane');
    const [a, b] = await Promise.all([loadSurfaceModel('doublyCurved'), loadSurfaceModel('doublyCurved')]);
    expect(a).toBe(doublyCurvedModel);
    expect(b).toBe(a);
    expect(surfaceModel(SURFACE)).toBe(doublyCurvedModel);
    expect(findSurfaceModel('doublyCurved')).toBe(doublyCurvedModel);
    expect(
      surfaceModel(SURFACE).intervalMm({ ...TOOL, pattern: 'one-way', surface: SURFACE, scallopHeightMm: 0.01 }),
    ).toBe(doublyCurvedModel.intervalMm({ ...TOOL, pattern: 'one-way', surface: SURFACE, scallopHeightMm: 0.01 }));
    expect(surfaceKinds()).toEqual(['plane', 'cylinder', 'doublyCurved', 'plugin']);
    remove();
    expect(surfaceKinds()).toEqual(['plane', 'cylinder', 'doublyCurved']);
  });

  it("the worker's teaching views and lookup table of a doubly curved point, asked first, load the model they ask", async () => {
    // Fresh modules, as above: no other job has loaded the model in this worker.
    vi.resetModules();
    const { workerApi } = await import('../../src/worker/workerApi');
    const input = {
      ...TOOL,
      pattern: 'one-way',
      feedRadiusMm: 40,
      crossRadiusMm: -200,
      scallopHeightMm: 0.01,
    } as const;
    const taught = await workerApi.teach({ mode: 'curved-forward', input });
    expect(taught.ok && 'section' in taught && taught.section.exact.cuspHeightMm).toBeGreaterThan(0);
    vi.resetModules();
    const fresh = await import('../../src/worker/workerApi');
    const grid = { scallopHeightsMm: [0.01], leadAnglesDeg: [10], tiltAnglesDeg: [0] };
    const table = await fresh.workerApi.table({
      tool: { toolRadiusMm: 3, cornerRadiusMm: 1, pattern: 'one-way', surface: { kind: 'plane' } },
      radii: { feedRadiusMm: 40, crossRadiusMm: -200 },
      grid,
    });
    expect(table.ok && table.rows).toBe(1);
  });
});
