/**
 * The modules a source file loads at once: its static value imports and re-exports, followed
 * through relative specifiers (`import type`, imports of types only and dynamic `import()` are not
 * edges: the build erases the first two and loads the third when it runs). Read from the source, so
 * a test can say what the page's or the worker's first script holds without building the site.
 */
import { existsSync, readFileSync } from 'node:fs';
import { dirname, join, relative, resolve } from 'node:path';

/** The relative specifiers `source` loads at once (see the module comment). */
export function staticSpecifiers(source: string): string[] {
  const code = source.replace(/\/\*[\s\S]*?\*\//g, '').replace(/^\s*\/\/.*$/gm, '');
  const out: string[] = [];
  // import x from '...'; import { a, type B } from '...'; import '...'; export { a } from '...'; export * from '...'
  // (A clause holds no parenthesis: an exported function's body may reach a dynamic import().)
  const re = /^\s*(import|export)\s+(type\s+)?([^'";(]*?)\s*(?:from\s*)?['"]([^'"]+)['"]/gm;
  for (let m = re.exec(code); m !== null; m = re.exec(code)) {
    const [, , typeOnly, clause = '', spec = ''] = m;
    if (typeOnly) continue;
    const named = /^\{([\s\S]*)\}$/.exec(clause.trim());
    const names = named
      ? (named[1] as string)
          .split(',')
          .map((n) => n.trim())
          .filter((n) => n !== '')
      : null;
    // `import { type A, type B } from` loads nothing at run time.
    if (names !== null && names.length > 0 && names.every((n) => n.startsWith('type '))) continue;
    out.push(spec);
  }
  return out;
}

/** The file a relative specifier names (`x.ts`, `x/index.ts`, or as written), or null. */
function resolveFile(from: string, spec: string): string | null {
  const base = resolve(dirname(from), spec);
  for (const candidate of [`${base}.ts`, join(base, 'index.ts'), base])
    if (/\.(ts|mjs|js)$/.test(candidate) && existsSync(candidate)) return candidate;
  return null;
}

/**
 * Every file `entry` loads at once, transitively, by path relative to `root`, each with the first
 * file found that imports it (the chain to it can be walked back for a message). `replaced` maps a
 * file (absolute) to the one the build takes in its place (siteSources.ts: the site's build).
 */
export function staticClosure(
  entry: string,
  root: string,
  replaced: ReadonlyMap<string, string> = new Map(),
): Map<string, string | null> {
  const reached = new Map<string, string | null>([[relative(root, entry), null]]);
  const queue = [entry];
  for (let file = queue.shift(); file !== undefined; file = queue.shift()) {
    for (const spec of staticSpecifiers(readFileSync(file, 'utf8'))) {
      if (!spec.startsWith('.')) continue;
      const found = resolveFile(file, spec);
      const target = found === null ? null : (replaced.get(found) ?? found);
      if (target === null || !target.startsWith(root)) continue;
      const key = relative(root, target);
      if (reached.has(key)) continue;
      reached.set(key, relative(root, file));
      queue.push(target);
    }
  }
  return reached;
}

/** The chain of imports from the entry to `file` in a closure, as `a -> b -> file`. */
export function chainTo(closure: ReadonlyMap<string, string | null>, file: string): string {
  const chain = [file];
  for (let from = closure.get(file); from !== undefined && from !== null; from = closure.get(from)) chain.unshift(from);
  return chain.join(' -> ');
}
