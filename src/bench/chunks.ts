/**
 * The import graph of a built site's scripts (Vite's output in dist/assets): which chunks a
 * script loads at once. Used by the web benchmark (the JavaScript a first result needs) and by
 * the build tests (the core shipped once). Pure: the caller reads the files.
 */

const STATIC_IMPORT = /(?:^|[;}\s])(?:import|export)[^"'`();]*?(?:from)?\s*["']\.\/([^"']+\.js)["']/g;

/**
 * The sibling chunks a minified ES module imports statically (`import{a}from"./x.js"`,
 * `import"./x.js"`, `export{b}from"./x.js"`), in order; dynamic `import("./x.js")` is not one.
 */
export function staticImports(code: string): string[] {
  return [...code.matchAll(STATIC_IMPORT)].map((m) => m[1] as string);
}

/** The scripts reached from `roots` through static imports, roots included (names in `known` only). */
export function importClosure(
  roots: readonly string[],
  known: readonly string[],
  read: (name: string) => string,
): Set<string> {
  const reached = new Set<string>();
  const visit = (name: string) => {
    if (reached.has(name) || !known.includes(name)) return;
    reached.add(name);
    for (const next of staticImports(read(name))) visit(next);
  };
  for (const root of roots) visit(root);
  return reached;
}
