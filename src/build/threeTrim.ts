/**
 * Build step: three.js without what this page cannot reach. The site builds three.js from its
 * sources through src/render/threeParts.ts (the classes the page uses); the renderer still imports
 * every material's shaders (ShaderChunk holds them all, looked up by name at run time), WebXR, the
 * shadow maps and the environment maps' PMREM generator, and its shaders carry the code of every
 * feature behind preprocessor switches. Each removal here holds only while a check of the page's
 * sources proves its feature unreachable (src/build/threeFeatures.ts); a feature the sources may
 * use is kept whole, and the build says which.
 *
 *  - Shaders: only the chunks that the materials threeParts.ts exports (through WebGLPrograms'
 *    table of shader ids and ShaderLib) and the renderer itself include, transitively; and in
 *    them, the blocks that only a dead switch opens (src/build/glslDeadBlocks.ts).
 *  - WebGLBackground without its texture backgrounds (a colour or none is drawn as before).
 *  - Modules replaced by small stand-ins: WebXRManager (never enabled), WebGLShadowMap (never
 *    enabled: nothing casts a shadow), WebGLEnvironments (no texture exists, so no environment map
 *    and no PMREM), WebGLMorphtargets (no geometry has morph attributes). A stand-in reached after
 *    all throws, naming itself.
 *  - Parts cut inside modules, each while its feature is proven unreachable (threeFeatures.ts
 *    REWRITES: the renderer's render targets and API beyond the page's calls, serialisation,
 *    raycasting, other materials' refreshes, dead switches' prefix lines in WebGLProgram).
 *  - Class methods that nothing names (unnamedMethods): their name appears nowhere else in three's
 *    sources, nor in the page's, so no code can call them; dropped, to a fixpoint.
 */
import { readdirSync, readFileSync, statSync } from 'node:fs';
import { join } from 'node:path';
import type { Plugin } from 'vite';
import { dropDeadBlocks } from './glslDeadBlocks.ts';
import { compactGlsl, glslTemplates, stripGlslComments } from './shaderWhitespace.ts';
import { FEATURES, REWRITES, SOURCE_SEPARATOR, STAND_INS } from './threeFeatures.ts';

/** Materials' shader ids (WebGLPrograms.js `shaderIDs`: material type -> ShaderLib entry). */
export function shaderIds(webGLPrograms: string): Map<string, string> {
  const table = /const shaderIDs = \{([^}]*)\}/.exec(webGLPrograms)?.[1];
  if (table === undefined) throw new Error('threeTrim: no shaderIDs table in WebGLPrograms.js');
  return new Map([...table.matchAll(/(\w+): '(\w+)'/g)].map((m) => [m[1] as string, m[2] as string]));
}

/** Each ShaderLib entry's shader chunk names (ShaderLib.js `name: { ... vertexShader: ShaderChunk.x ... }`). */
export function shaderLibChunks(shaderLib: string): Map<string, string[]> {
  const out = new Map<string, string[]>();
  const blocks = shaderLib.split(/\n\t(\w+): \{\n|\nShaderLib\.(\w+) = \{\n/);
  for (let i = 1; i < blocks.length; i += 3) {
    const name = (blocks[i] ?? blocks[i + 1]) as string;
    const body = blocks[i + 2] as string;
    out.set(
      name,
      [...body.matchAll(/ShaderChunk\.(\w+)/g)].map((m) => m[1] as string),
    );
  }
  return out;
}

/** The ShaderChunk entries: name -> [module file under shaders/, export ('default', 'vertex', 'fragment')]. */
export function shaderChunkEntries(shaderChunk: string): Map<string, [string, string]> {
  const modules = new Map<string, string>();
  for (const m of shaderChunk.matchAll(/^import (?:\* as )?(\w+) from '\.\/([\w/]+\.glsl\.js)';$/gm))
    modules.set(m[1] as string, m[2] as string);
  const out = new Map<string, [string, string]>();
  for (const m of shaderChunk.matchAll(/^\t(\w+): (\w+)(?:\.(vertex|fragment))?,?$/gm)) {
    const file = modules.get(m[2] as string);
    if (file === undefined) throw new Error(`threeTrim: ShaderChunk.${m[1]} has no import`);
    out.set(m[1] as string, [file, m[3] ?? 'default']);
  }
  return out;
}

/** The chunks reached from `roots` through `#include <name>` (in the given, already trimmed, texts). */
export function includeClosure(roots: Iterable<string>, chunks: ReadonlyMap<string, string>): Set<string> {
  const reached = new Set<string>();
  const visit = (name: string) => {
    if (reached.has(name)) return;
    const glsl = chunks.get(name);
    if (glsl === undefined) throw new Error(`threeTrim: #include <${name}> names no chunk`);
    reached.add(name);
    for (const m of glsl.matchAll(/^[ \t]*#include +<(\w+)>/gm)) visit(m[1] as string);
  };
  for (const r of roots) visit(r);
  return reached;
}

/** ShaderChunk.js with only the `keep` entries and their imports. */
export function trimShaderChunk(source: string, keep: ReadonlySet<string>): string {
  const entries = shaderChunkEntries(source);
  const usedModules = new Set([...keep].map((name) => entries.get(name)?.[0]));
  return source
    .split('\n')
    .filter((line) => {
      const entry = /^\t(\w+): \w+(?:\.\w+)?,?$/.exec(line);
      if (entry !== null) return keep.has(entry[1] as string);
      const imported = /^import (?:\* as )?\w+ from '\.\/([\w/]+\.glsl\.js)';$/.exec(line);
      return imported === null || usedModules.has(imported[1] as string);
    })
    .join('\n');
}

/** The page's TypeScript sources (not the build tools and benchmarks), concatenated (SOURCE_SEPARATOR between files). */
export function pageSources(src: string): string {
  const texts: string[] = [];
  const walk = (dir: string) => {
    for (const name of readdirSync(dir)) {
      const path = join(dir, name);
      if (statSync(path).isDirectory()) {
        if (!/^(build|bench|cli)$/.test(name) || dir !== src) walk(path);
      } else if (path.endsWith('.ts')) texts.push(readFileSync(path, 'utf8'));
    }
  };
  walk(src);
  return texts.join(SOURCE_SEPARATOR);
}

/**
 * A class method of a three.js module: one tab in, `name( args ) {`, lines empty or two tabs in, then
 * the line `\t}` (so that a match never runs past its method's end).
 */
const CLASS_METHOD = /\n\t(\w+)\([^)\n]*\) \{((?:\n(?:\t\t[^\n]*)?)*)\n\t\}\n/g;

/** Every `.js` file under `dir`, recursively. */
function jsFiles(dir: string): string[] {
  return readdirSync(dir).flatMap((name) => {
    const path = join(dir, name);
    return statSync(path).isDirectory() ? jsFiles(path) : path.endsWith('.js') ? [path] : [];
  });
}

/**
 * The class methods of three's modules whose name appears nowhere else: not in any module of three
 * (the build's and every other, comments included) nor in the page's sources; by module path under
 * three/src/. Nothing can call such a method but by a name built at run time, which three does not do.
 */
export function unnamedMethods(three: string, sources: string): Map<string, string[]> {
  const texts = new Map(jsFiles(three).map((file) => [file.slice(three.length), readFileSync(file, 'utf8')]));
  const words = new Map<string, number>();
  const count = (text: string, by: number) => {
    for (const m of text.matchAll(/\w+/g)) words.set(m[0], (words.get(m[0]) ?? 0) + by);
  };
  for (const text of [...texts.values(), sources]) count(text, 1);
  const methods = [...texts].flatMap(([path, text]) =>
    [...text.matchAll(CLASS_METHOD)]
      .filter((m) => m[1] !== 'constructor')
      .map((m) => ({ path, name: m[1] as string, text: m[0] })),
  );
  const out = new Map<string, string[]>();
  // Until no more: a method named only in methods dropped before is dropped in the next round.
  for (let left = methods, found = true; found; ) {
    const dropped = left.filter((m) => words.get(m.name) === 1);
    found = dropped.length > 0;
    for (const m of dropped) {
      count(m.text, -1);
      out.set(m.path, [...(out.get(m.path) ?? []), m.name]);
    }
    left = left.filter((m) => !dropped.includes(m));
  }
  return out;
}

/** `code` without the class methods `names` (each whole, from its line to its closing `\t}`). */
export function dropMethods(code: string, names: readonly string[]): string {
  const drop = new Set(names);
  return code.replace(CLASS_METHOD, (method, name: string) => (drop.has(name) ? '\n' : method));
}

export interface TrimPlan {
  /** Features proven unused (their switches dead, their modules replaced). */
  readonly removed: readonly string[];
  /** Features the sources may use: kept whole. */
  readonly kept: readonly string[];
  readonly dead: ReadonlySet<string>;
  readonly standIns: ReadonlyMap<string, string>;
  /** Modules of which a part is cut. */
  readonly rewrites: ReadonlySet<string>;
  /** The ShaderChunk entries kept. */
  readonly chunks: ReadonlySet<string>;
  /** Class methods dropped (unnamedMethods), by module. */
  readonly unnamed: ReadonlyMap<string, readonly string[]>;
}

/**
 * What to remove, from three's sources (`three`: its src/ folder), the exported class names of
 * threeParts.ts (`parts`: its text) and the page's sources (`sources`).
 */
export function trimPlan(three: string, parts: string, sources: string): TrimPlan {
  const exported = new Set(
    [...parts.matchAll(/export \{ (\w+) \} from 'three\/src\/[\w/]+\.js';/g)].map((m) => m[1] as string),
  );
  if (exported.size === 0) throw new Error('threeTrim: threeParts.ts exports nothing from three/src');
  const removed = FEATURES.filter((f) => f.unused(exported, sources));
  const dead = new Set(removed.flatMap((f) => f.macros));
  const read = (path: string) => readFileSync(join(three, path), 'utf8');
  const entries = shaderChunkEntries(read('renderers/shaders/ShaderChunk.js'));
  const texts = new Map<string, string>();
  const fileTemplates = new Map<string, Record<string, string>>();
  for (const [name, [file, exportName]] of entries) {
    let templates = fileTemplates.get(file);
    if (templates === undefined) {
      const found = glslTemplates(read(`renderers/shaders/${file}`));
      templates =
        found.length === 1 ? { default: found[0] as string } : { vertex: found[0] ?? '', fragment: found[1] ?? '' };
      fileTemplates.set(file, templates);
    }
    texts.set(name, dropDeadBlocks(compactGlsl(stripGlslComments(templates[exportName] ?? '')), dead));
  }
  // A dead switch must never be defined by a shader itself (only by the renderer's prefixes).
  for (const [name, glsl] of texts)
    for (const m of glsl.matchAll(/^\s*#\s*define\s+(\w+)/gm))
      if (dead.has(m[1] as string)) throw new Error(`threeTrim: ShaderChunk.${name} defines ${m[1]}`);
  const ids = shaderIds(read('renderers/webgl/WebGLPrograms.js'));
  const lib = shaderLibChunks(read('renderers/shaders/ShaderLib.js'));
  const roots = new Set<string>();
  for (const material of exported) {
    const id = ids.get(material);
    if (id !== undefined) for (const chunk of lib.get(id) ?? []) roots.add(chunk);
  }
  // The renderer's own chunks (WebGLProgram.js: ShaderChunk[ 'name' ]).
  for (const m of read('renderers/webgl/WebGLProgram.js').matchAll(/ShaderChunk\[ '(\w+)' \]/g))
    roots.add(m[1] as string);
  const chunks = includeClosure(roots, texts);
  // The proofs over the GLSL the page can compile (macros of these features are not dead: see Feature).
  const glsl = `${[...chunks].map((name) => texts.get(name)).join('\n')}\n${sources}`;
  const proven = removed.filter((f) => f.unusedInShaders?.(glsl) ?? true);
  const standIns = new Map(proven.flatMap((f) => (f.modules ?? []).map((m) => [m, STAND_INS[m] as string])));
  return {
    removed: proven.map((f) => f.name),
    kept: FEATURES.filter((f) => !proven.includes(f)).map((f) => f.name),
    dead,
    standIns,
    rewrites: new Set(proven.flatMap((f) => f.rewrites ?? [])),
    chunks,
    unnamed: unnamedMethods(three, sources),
  };
}

const THREE_SRC = /\/node_modules\/three\/src\/(.+)$/;

/** A line of WebGLProgram.js's prefixes that defines one switch when its parameter holds: `a ? '#define X' : '',` (or `'#define X ' + a.b`). */
const DEFINE_LINE = /^[ \t]*[^\n]*? \? '#define (\w+) ?'(?: \+ [\w.]+)? : '',[ \t]*\n/gm;

/**
 * WebGLProgram.js without the prefix lines of dead switches (a line yields '' while its switch is
 * dead, and the renderer drops empty lines): `USE_X` itself, and `X_UV`, the texture coordinates'
 * channel of map X, which WebGLPrograms sets only when the material has that map (`mapUv: HAS_MAP
 * && ...`), so only while `USE_X` can be defined.
 */
export function dropDeadDefines(code: string, dead: ReadonlySet<string>): string {
  return code.replace(DEFINE_LINE, (line, name: string) =>
    dead.has(name) || (name.endsWith('_UV') && dead.has(`USE_${name.slice(0, -3)}`)) ? '' : line,
  );
}

/** A three.js module's code (`path` under three/src/) as the plan trims it; null when unchanged. */
export function trimModule(path: string, code: string, plan: TrimPlan): string | null {
  const unnamed = plan.unnamed.get(path);
  const trimmed = trimModuleParts(path, code, plan);
  return unnamed === undefined ? trimmed : dropMethods(trimmed ?? code, unnamed);
}

/** {@link trimModule} but for the unnamed methods. */
function trimModuleParts(path: string, code: string, plan: TrimPlan): string | null {
  if (plan.rewrites.has(path)) return (REWRITES[path] as (code: string) => string)(code);
  if (path === 'renderers/shaders/ShaderChunk.js') return trimShaderChunk(code, plan.chunks);
  if (path === 'renderers/webgl/WebGLProgram.js') return dropDeadDefines(code, plan.dead);
  if (/^renderers\/shaders\/.*\.glsl\.js$/.test(path))
    return code.replace(/`([^`]*)`/g, (_, glsl: string) => `\`${dropDeadBlocks(glsl, plan.dead)}\``);
  return null;
}

/**
 * Vite plugin applying {@link trimPlan} in the build: `three` is three's src/ folder, `parts` the
 * path of threeParts.ts, `src` the page's source folder. Runs after the shader whitespace plugin.
 */
export function threeTrimPlugin(options: { three: string; parts: string; src: string }): Plugin {
  let plan: TrimPlan | null = null;
  return {
    name: 'three-trim',
    apply: 'build',
    buildStart() {
      const sources = pageSources(options.src);
      // Only threeParts.ts may import three's modules (so its exports are every class the page has).
      if (/(from|import\()\s*['"]three\//.test(sources.replace(readFileSync(options.parts, 'utf8'), '')))
        throw new Error('threeTrim: a page source imports three/... directly; import it through threeParts.ts');
      plan = trimPlan(options.three, readFileSync(options.parts, 'utf8'), sources);
      if (plan.kept.length > 0) this.info(`three.js kept whole (the sources may use them): ${plan.kept.join('; ')}`);
    },
    load(id) {
      const path = THREE_SRC.exec(id)?.[1];
      return path === undefined ? null : (plan?.standIns.get(path) ?? null);
    },
    transform(code, id) {
      const path = THREE_SRC.exec(id)?.[1];
      if (path === undefined || plan === null) return null;
      const trimmed = trimModule(path, code, plan);
      return trimmed === null ? null : { code: trimmed, map: null };
    },
  };
}
