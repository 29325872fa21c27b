/**
 * The import graph's layers, read from the source: pure math (`core`) at the bottom, then the
 * worker boundary, the three.js rendering and the UI, with no edge going back down-up. The command
 * line sits on the core; the build plugins and benchmarks are tools that nothing imports.
 *
 * Inside the core, its folders in this order (CORE_ORDER); a core file imports its own folder and
 * earlier ones only:
 *
 *   math < domain < input < tool < threeAxis < surfaces < roughness < procedures < simulation < output
 *
 * - math: the root finder and vectors; domain: the data types (tool, pass, surface descriptors);
 * - input: units, the field registry, limits, error wording, the strict reading of a number;
 * - tool: the tool in its posture (flanks, placement, profile, the step-over rule);
 * - threeAxis: the posture a slope gives and the three-axis solvers, which need the tool only;
 * - surfaces: the surface models, their registry (which wraps the sloped plane of threeAxis) and
 *   the rules that ask them (surfaces/validate.ts);
 * - roughness: Ra, Rz, Rq of the solved scallops, and the questions given an Ra;
 * - procedures: the paper's approximations and their comparison with the exact answer;
 * - simulation: the brute-force measurement of a pass pattern;
 * - output: what the page, the CLI and the shop sheet show (tables, CSV, geometry).
 * The core's root files (index.ts, library.ts: barrels) stand above every folder; none imports them.
 *
 * The page validates and the worker solves (issue 27 point 4, one pass per keystroke): no file of
 * src/ui imports a value of a solver module (SOLVER_MODULES: the validations that ask a surface
 * model, the surface models and their solvers, the posture solvers, roughness, three-axis solving,
 * the procedures' comparison, the simulation, the worker's jobs and their data); type imports cost
 * nothing at run time and stay allowed. The page checks the fields (core input/passFields.ts).
 *
 * No import circle anywhere in src/: among static imports and re-exports, type imports included
 * (a circle of types alone still ties the files together). A dynamic `import()` loads later, on
 * first use, so it is left out of the circle check (a lazily loaded module may import back what
 * loads it); it counts for the layers and the core's order like any other import.
 */
import { existsSync, readdirSync, readFileSync } from 'node:fs';
import { dirname, join, relative, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';

const SRC = fileURLToPath(new URL('../src', import.meta.url));

/** Rank of each layer: a file may import its own layer and those of lower rank only. */
const RANK: Record<string, number> = { core: 0, worker: 1, cli: 1, render: 2, ui: 3, 'main.ts': 4 };
/** Tools: may import any layer; no layer may import them. */
const TOOLS = new Set(['build', 'bench']);

function sourceFiles(dir: string): string[] {
  return readdirSync(dir, { withFileTypes: true }).flatMap((e) => {
    const p = join(dir, e.name);
    if (e.isDirectory()) return sourceFiles(p);
    return /\.(ts|mjs)$/.test(e.name) && !e.name.endsWith('.d.ts') ? [p] : [];
  });
}

interface Import {
  readonly spec: string;
  /** True for a dynamic `import()`, loaded on first use. */
  readonly dynamic: boolean;
}

/** Every import of a file: static imports and re-exports, and dynamic `import()` (not in comments). */
function imports(source: string): Import[] {
  const out: Import[] = [];
  const code = source.replace(/\/\*[\s\S]*?\*\//g, '').replace(/^\s*\/\/.*$/gm, '');
  const re = /(\bfrom\s*|\bimport\s*\(\s*|^\s*import\s+)['"]([^'"]+)['"]/gm;
  for (let m = re.exec(code); m !== null; m = re.exec(code))
    out.push({ spec: m[2] as string, dynamic: (m[1] as string).includes('(') });
  return out;
}

/** Every module specifier of a file (see imports). */
function specifiers(source: string): string[] {
  return imports(source).map((i) => i.spec);
}

function layerOf(file: string): string {
  return relative(SRC, file).split(/[\\/]/)[0] as string;
}

interface Edge {
  readonly from: string;
  readonly to: string;
  readonly file: string;
}

function edges(): Edge[] {
  const list: Edge[] = [];
  for (const file of sourceFiles(SRC)) {
    for (const spec of specifiers(readFileSync(file, 'utf8'))) {
      if (!spec.startsWith('.')) {
        list.push({ from: layerOf(file), to: `pkg:${spec.split('/')[0]}`, file: relative(SRC, file) });
        continue;
      }
      const target = resolve(dirname(file), spec);
      if (!target.startsWith(SRC)) continue;
      list.push({ from: layerOf(file), to: layerOf(target), file: relative(SRC, file) });
    }
  }
  return list;
}

/** The file a relative specifier names: `x.ts`, `x.mjs` or `x/index.ts`; null when none exists. */
function resolveFile(from: string, spec: string): string | null {
  const base = resolve(dirname(from), spec);
  for (const candidate of [base, `${base}.ts`, `${base}.mjs`, join(base, 'index.ts')])
    if (/\.(ts|mjs)$/.test(candidate) && existsSync(candidate)) return candidate;
  return null;
}

/**
 * The import graph of the files under `dir` (type imports and re-exports included), by path relative
 * to SRC; dynamic `import()` only when `dynamic` is set.
 */
function fileGraph(dir: string, dynamic: boolean): Map<string, string[]> {
  const graph = new Map<string, string[]>();
  for (const file of sourceFiles(dir)) {
    const targets: string[] = [];
    for (const i of imports(readFileSync(file, 'utf8'))) {
      if (!i.spec.startsWith('.') || (i.dynamic && !dynamic)) continue;
      const target = resolveFile(file, i.spec);
      if (target?.startsWith(dir)) targets.push(relative(SRC, target));
    }
    graph.set(relative(SRC, file), targets);
  }
  return graph;
}

/** The core's folders, lowest first: a core file may import its own folder and earlier ones only. */
const CORE_ORDER = [
  'math',
  'domain',
  'input',
  'tool',
  'threeAxis',
  'surfaces',
  'finish',
  'roughness',
  'procedures',
  'simulation',
  'output',
] as const;

/** Rank of a core file's folder in CORE_ORDER; the root files (index.ts, library.ts) above all; -1 for an unknown folder. */
function coreRank(path: string): number {
  const parts = path.split(/[\\/]/);
  if (parts.length === 2) return CORE_ORDER.length;
  return (CORE_ORDER as readonly string[]).indexOf(parts[1] as string);
}

/**
 * The imports inside the core that climb against CORE_ORDER (or leave or enter a folder it does not
 * name), each as `file -> target`.
 */
function backArrows(graph: ReadonlyMap<string, readonly string[]>): string[] {
  const bad: string[] = [];
  for (const [file, targets] of graph) {
    const from = coreRank(file);
    for (const target of targets) {
      const to = coreRank(target);
      if (from < 0 || to < 0 || to > from) bad.push(`${file} -> ${target}`);
    }
  }
  return bad;
}

/**
 * Every import cycle of a graph, one per strongly connected component with more than one file (or a
 * file importing itself), written `a -> b -> ... -> a` along one of its loops (Tarjan's algorithm).
 */
function cycles(graph: ReadonlyMap<string, readonly string[]>): string[] {
  const index = new Map<string, number>();
  const low = new Map<string, number>();
  const stack: string[] = [];
  const onStack = new Set<string>();
  const found: string[] = [];
  let next = 0;
  const visit = (v: string): void => {
    index.set(v, next);
    low.set(v, next);
    next++;
    stack.push(v);
    onStack.add(v);
    for (const w of graph.get(v) ?? []) {
      if (!index.has(w)) {
        visit(w);
        low.set(v, Math.min(low.get(v) as number, low.get(w) as number));
      } else if (onStack.has(w)) low.set(v, Math.min(low.get(v) as number, index.get(w) as number));
    }
    if (low.get(v) !== index.get(v)) return;
    const component: string[] = [];
    for (let w = stack.pop(); w !== undefined; w = stack.pop()) {
      onStack.delete(w);
      component.push(w);
      if (w === v) break;
    }
    if (component.length > 1 || (graph.get(v) ?? []).includes(v)) found.push(loopThrough(graph, new Set(component), v));
  };
  for (const v of [...graph.keys()].sort()) if (!index.has(v)) visit(v);
  return found;
}

/** One loop from `start` back to it inside a strongly connected component (breadth first). */
function loopThrough(
  graph: ReadonlyMap<string, readonly string[]>,
  within: ReadonlySet<string>,
  start: string,
): string {
  const previous = new Map<string, string>();
  const queue = [start];
  while (queue.length > 0) {
    const v = queue.shift() as string;
    for (const w of graph.get(v) ?? []) {
      if (!within.has(w)) continue;
      if (w === start) {
        const path = [start];
        for (let u: string | undefined = v; u !== undefined && u !== start; u = previous.get(u)) path.splice(1, 0, u);
        return [...path, start].join(' -> ');
      }
      if (!previous.has(w)) {
        previous.set(w, v);
        queue.push(w);
      }
    }
  }
  return start;
}

/**
 * The modules that solve (paths under src/, a folder ending in `/`): the page imports no value of
 * them; it validates the typed fields, and the worker's reply brings what needs a solve (the
 * answer, a refusal, the sliders' limits).
 */
const SOLVER_MODULES = [
  'core/surfaces/validate.ts',
  'core/surfaces/question.ts',
  'core/surfaces/solve.ts',
  'core/surfaces/exact.ts',
  'core/surfaces/congruentPasses.ts',
  'core/surfaces/cylinder.ts',
  'core/surfaces/cylinder/',
  'core/surfaces/doublyCurved/index.ts',
  'core/surfaces/doublyCurved/solve.ts',
  'core/surfaces/doublyCurved/gouging.ts',
  'core/surfaces/models/',
  'core/tool/posture.ts',
  'core/tool/postureShape.ts',
  'core/tool/placement.ts',
  'core/roughness/roughness.ts',
  'core/roughness/raTarget.ts',
  'core/roughness/doublyCurved.ts',
  'core/roughness/slopedPlane.ts',
  'core/threeAxis/index.ts',
  'core/threeAxis/solve.ts',
  'core/threeAxis/slopedPlane.ts',
  'core/threeAxis/slopeSweep.ts',
  'core/threeAxis/waterlineRevolution.ts',
  'core/threeAxis/waterlineSolve.ts',
  'core/threeAxis/revolutionGouging.ts',
  'core/threeAxis/meridianCusp.ts',
  'core/procedures/compare.ts',
  'core/procedures/compareDoublyCurved.ts',
  'core/simulation/',
  'core/output/shopSheet.ts',
  'worker/jobs/',
  'worker/data/',
] as const;

/**
 * The page's solver imports still to move into the worker (`file -> module`): the shop sheet's
 * matrix of answers is worked out on the page while its dialog is open (shopSheet.ts; its text
 * reads the module's marks and passes); the builder of a question over the registries (not wired
 * to the page's switches yet) validates it whole, gouging included. The list only shrinks.
 */
const SOLVING_ON_THE_PAGE_STILL = [
  'ui/registryQuestionRequest.ts -> core/surfaces/question.ts',
  'ui/shopSheet.ts -> core/output/shopSheet.ts',
  'ui/shopSheetText.ts -> core/output/shopSheet.ts',
  // Its marks' constants (W, G, X) for their words in each language; the sheet's own chunk.
  'ui/shopSheetWords.ts -> core/output/shopSheet.ts',
];

/**
 * The specifiers a file imports a value from: static imports and re-exports (not `import type`, not
 * `export type`, not a list of `type` names only) and dynamic `import()` (not in comments).
 */
function valueImports(source: string): string[] {
  const code = source.replace(/\/\*[\s\S]*?\*\//g, '').replace(/^\s*\/\/.*$/gm, '');
  const out: string[] = [];
  const statement = /^\s*(?:import|export)\s+([\s\S]*?)\s*from\s*['"]([^'"]+)['"]/gm;
  for (let m = statement.exec(code); m !== null; m = statement.exec(code)) {
    const clause = (m[1] as string).trim();
    if (/^type\b/.test(clause)) continue;
    const named = /^\{([\s\S]*)\}$/.exec(clause);
    const names =
      named === null
        ? []
        : (named[1] as string)
            .split(',')
            .map((n) => n.trim())
            .filter((n) => n !== '');
    if (named !== null && names.every((n) => n.startsWith('type '))) continue;
    out.push(m[2] as string);
  }
  for (const m of code.matchAll(/\bimport\s*\(\s*['"]([^'"]+)['"]\s*\)/g)) out.push(m[1] as string);
  for (const m of code.matchAll(/^\s*import\s+['"]([^'"]+)['"]/gm)) out.push(m[1] as string);
  return out;
}

/** Each value import of a solver module by a file of src/ui, as `ui/file.ts -> core/module.ts`. */
function pageSolverImports(): string[] {
  const found: string[] = [];
  const uiDir = join(SRC, 'ui');
  for (const file of sourceFiles(uiDir)) {
    for (const spec of valueImports(readFileSync(file, 'utf8'))) {
      if (!spec.startsWith('.')) continue;
      const target = resolveFile(file, spec);
      if (target === null) continue;
      const path = relative(SRC, target).split(/[\\/]/).join('/');
      if (SOLVER_MODULES.some((m) => (m.endsWith('/') ? path.startsWith(m) : path === m)))
        found.push(`${relative(SRC, file).split(/[\\/]/).join('/')} -> ${path}`);
    }
  }
  return found.sort();
}

describe('layers of src/', () => {
  const all = edges();

  it('reads the imports it checks (the parser finds static, re-export and dynamic forms)', () => {
    const comment = "/** `import { x } from 'pkg'` */\n// import y from 'other';\n";
    expect(specifiers(`${comment}import a from './a';\nexport * from './b';\nconst c = await import('./c');`)).toEqual([
      './a',
      './b',
      './c',
    ]);
    expect(all.some((e) => e.from === 'ui' && e.to === 'core')).toBe(true);
  });

  it('has no back-edge: each layer imports only its own and lower layers', () => {
    const bad = all.filter((e) => {
      if (e.to.startsWith('pkg:') || e.from === e.to || TOOLS.has(e.from)) return false;
      if (TOOLS.has(e.to)) return true;
      const from = RANK[e.from];
      const to = RANK[e.to];
      return from === undefined || to === undefined || to >= from;
    });
    expect(bad.map((e) => `${e.file}: ${e.from} -> ${e.to}`)).toEqual([]);
  });

  it('keeps the core pure: no three.js, no DOM or Node modules', () => {
    // fflate (the x3p file's zip, core/output/x3p.ts) is plain JavaScript: no DOM, no Node module.
    const PURE_PACKAGES = new Set(['pkg:fflate']);
    const bad = all.filter((e) => e.from === 'core' && e.to.startsWith('pkg:') && !PURE_PACKAGES.has(e.to));
    expect(bad.map((e) => `${e.file} imports ${e.to}`)).toEqual([]);
  });

  it('finds an import cycle when there is one (the checker itself)', () => {
    const graph = new Map([
      ['a.ts', ['b.ts']],
      ['b.ts', ['c.ts']],
      ['c.ts', ['a.ts', 'd.ts']],
      ['d.ts', []],
    ]);
    expect(cycles(graph)).toEqual(['a.ts -> b.ts -> c.ts -> a.ts']);
    expect(
      cycles(
        new Map([
          ['a.ts', ['b.ts']],
          ['b.ts', []],
        ]),
      ),
    ).toEqual([]);
  });

  it('has no import circle anywhere in src/ (static imports, type imports included)', () => {
    const graph = fileGraph(SRC, false);
    expect(graph.size).toBeGreaterThan(250);
    expect(cycles(graph)).toEqual([]);
  });

  it('finds a back arrow against the core order when there is one (the checker itself)', () => {
    const graph = new Map([
      ['core/input/validate.ts', ['core/domain/tool.ts', 'core/surfaces/registry.ts']],
      ['core/surfaces/registry.ts', ['core/input/validate.ts', 'core/surfaces/surface.ts']],
      ['core/index.ts', ['core/output/csvWrite.ts']],
      ['core/output/csvWrite.ts', ['core/index.ts']],
      ['core/newFolder/x.ts', ['core/math/vec.ts']],
    ]);
    expect(backArrows(graph)).toEqual([
      'core/input/validate.ts -> core/surfaces/registry.ts',
      'core/output/csvWrite.ts -> core/index.ts',
      'core/newFolder/x.ts -> core/math/vec.ts',
    ]);
  });

  it('names every folder of the core in its order, and each folder imports only its own and earlier ones', () => {
    const folders = readdirSync(join(SRC, 'core'), { withFileTypes: true })
      .filter((e) => e.isDirectory())
      .map((e) => e.name);
    expect([...folders].sort()).toEqual([...CORE_ORDER].sort());
    expect(backArrows(fileGraph(join(SRC, 'core'), true))).toEqual([]);
  });

  it('reads value imports apart from type imports (the checker itself)', () => {
    const source = [
      "import { a } from './a';",
      "import type { B } from './b';",
      "import { type C, type D } from './c';",
      "import { type E, f } from './e';",
      'import {',
      '  type G,',
      '  h,',
      "} from './g';",
      "export { i } from './i';",
      "export type { J } from './j';",
      "export * from './k';",
      "import * as l from './l';",
      "import './side';",
      "const later = () => import('./lazy');",
      "// import { x } from './comment';",
    ].join('\n');
    expect(valueImports(source).sort()).toEqual(['./a', './e', './g', './i', './k', './l', './lazy', './side']);
  });

  it('the page imports no solver: src/ui validates, the worker solves (issue 27 point 4)', () => {
    for (const m of SOLVER_MODULES) expect(existsSync(join(SRC, m)), m).toBe(true);
    expect(pageSolverImports()).toEqual(SOLVING_ON_THE_PAGE_STILL);
  });
});
