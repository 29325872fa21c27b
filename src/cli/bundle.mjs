/**
 * The command line, compiled: src/cli/main.ts and everything it imports, bundled by esbuild into
 * one ES module, dist-cli/cli.mjs, which src/cli/bin.mjs runs (no TypeScript compiled at start-up).
 * Built by `npm ci` / `npm install` (the `prepare` script) and by `npm test`; plain JavaScript so
 * that it runs before anything else is installed or built.
 *
 * The bundle's first line records when its build started and the source files it read, so the
 * launcher can tell, in a checkout whose sources changed since, that it is stale.
 *
 *   node src/cli/bundle.mjs              build
 *   node src/cli/bundle.mjs --if-stale   build only when missing or older than a source
 */
import { closeSync, mkdirSync, openSync, readSync, renameSync, statSync, writeFileSync } from 'node:fs';
import { dirname } from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));
const ENTRY = 'src/cli/main.ts';
/** The compiled command line (git-ignored). */
export const CLI_BUNDLE = `${ROOT}dist-cli/cli.mjs`;
/** Start of the bundle's first line; the JSON after it: { startedMs, inputs } (inputs relative to the root). */
export const CLI_BUILD_MARK = '// path-interval cli build ';
/** The first line is read in one piece of at most this many bytes (the inputs' paths). */
const HEAD_BYTES = 1 << 16;

/** The build record on the bundle's first line, or null when there is no bundle (or no record). */
function buildRecord(bundle) {
  let fd;
  try {
    fd = openSync(bundle, 'r');
  } catch {
    return null;
  }
  try {
    const head = Buffer.alloc(HEAD_BYTES);
    const n = readSync(fd, head, 0, HEAD_BYTES, 0);
    const line = head.subarray(0, n).toString('utf8').split('\n', 1)[0] ?? '';
    if (!line.startsWith(CLI_BUILD_MARK)) return null;
    const record = JSON.parse(line.slice(CLI_BUILD_MARK.length));
    return typeof record.startedMs === 'number' && Array.isArray(record.inputs) ? record : null;
  } catch {
    return null;
  } finally {
    closeSync(fd);
  }
}

/**
 * True when the bundle exists and no source it was built from changed (or vanished) since its
 * build started. Without the sources (an installed copy that ships only the bundle) it is current.
 * `bundle` and `root` (ending in a slash) are for the tests.
 */
export function cliBundleIsCurrent(bundle = CLI_BUNDLE, root = ROOT) {
  const record = buildRecord(bundle);
  if (record === null) return false;
  if (statSync(`${root}${ENTRY}`, { throwIfNoEntry: false }) === undefined) return true;
  for (const input of record.inputs) {
    const s = statSync(`${root}${input}`, { throwIfNoEntry: false });
    if (s === undefined || s.mtimeMs >= record.startedMs) return false;
  }
  return true;
}

/**
 * Bundles the command line into {@link CLI_BUNDLE}: written to a temporary file and renamed, so a
 * command line starting meanwhile (or building at the same time) reads a whole bundle, old or new.
 * Throws when esbuild is missing or the sources do not compile.
 */
export async function buildCliBundle() {
  const startedMs = Date.now();
  const esbuild = await import('esbuild');
  const result = await esbuild.build({
    entryPoints: [ENTRY],
    absWorkingDir: ROOT,
    bundle: true,
    platform: 'node',
    format: 'esm',
    target: 'node20',
    write: false,
    metafile: true,
    logLevel: 'silent',
    legalComments: 'none',
    // Minified (names kept): about half the bytes for Node to read and parse at every start.
    minify: true,
    keepNames: true,
    outfile: CLI_BUNDLE,
  });
  const code = result.outputFiles?.[0]?.text;
  if (code === undefined) throw new Error('esbuild wrote no bundle');
  const inputs = Object.keys(result.metafile.inputs);
  mkdirSync(dirname(CLI_BUNDLE), { recursive: true });
  const tmp = `${CLI_BUNDLE}.${process.pid}.${Math.random().toString(36).slice(2)}.tmp`;
  writeFileSync(tmp, `${CLI_BUILD_MARK}${JSON.stringify({ startedMs, inputs })}\n${code}`);
  renameSync(tmp, CLI_BUNDLE);
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  if (!(process.argv.includes('--if-stale') && cliBundleIsCurrent())) await buildCliBundle();
}
