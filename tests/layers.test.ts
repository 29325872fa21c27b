/**
 * The import graph's layers, read from the source: pure math (`core`) at the bottom, then the
 * worker boundary, the three.js rendering and the UI, with no edge going back down-up. The command
 * line sits on the core; the build plugins and benchmarks are tools that nothing imports.
 */
import { readdirSync, readFileSync } from 'node:fs';
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

/** Every module specifier of a file: static imports and re-exports, and dynamic `import()` (not in comments). */
function specifiers(source: string): string[] {
  const out: string[] = [];
  const code = source.replace(/\/\*[\s\S]*?\*\//g, '').replace(/^\s*\/\/.*$/gm, '');
  const re = /(?:\bfrom\s*|\bimport\s*\(\s*|^\s*import\s+)['"]([^'"]+)['"]/gm;
  for (let m = re.exec(code); m !== null; m = re.exec(code)) out.push(m[1] as string);
  return out;
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
    const bad = all.filter((e) => e.from === 'core' && e.to.startsWith('pkg:'));
    expect(bad.map((e) => `${e.file} imports ${e.to}`)).toEqual([]);
  });
});
