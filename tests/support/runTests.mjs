#!/usr/bin/env node
// `npm test`: every check, as many at once as two cores take.
// All at once, each as soon as what it needs is there:
//  - preparation: Chromium and MkDocs present (ensure-*.mjs), the compiled command line current
//    (src/cli/bundle.mjs --if-stale: the one CLI build of the run);
//  - the browser tests (`vitest run --project browser`, after the three: two files at a time, the
//    longest step and the one that waits on pages, so at normal priority, its output shown as it comes);
//  - niced (they take the CPU the browser tests leave; none of them measures time): the Node tests
//    (`vitest run --project node`, after the CLI build; files in parallel), Biome, and the type checks
//    (`tsc -b`, src/core checked once). Their output is shown when each ends.
// Each step's time is printed at its end and in a summary; the exit code is 1 if any step failed.
// Arguments after `--` go to both Vitest runs (e.g. `npm test -- --reporter=dot`).
import { spawn } from 'node:child_process';
import { loadavg } from 'node:os';
import { fileURLToPath } from 'node:url';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));
const NICE = 10;
const VERDICT = (code) => (code === 0 ? 'ok     ' : code === null ? 'not run' : 'FAILED ');
// Filters given (`npm test -- tests/cli`) may match files of one project only: the other passes empty.
const vitestArgs = process.argv.length > 2 ? [...process.argv.slice(2), '--passWithNoTests'] : [];

/**
 * Runs one step (a command and its arguments); resolves to its name, exit code and seconds.
 * `live`: its output goes straight through; otherwise it is kept and written whole at the end.
 */
function step(name, command, args, { live = false, niced = false } = {}) {
  const t0 = performance.now();
  const [cmd, argv] =
    niced && process.platform !== 'win32' ? ['nice', ['-n', `${NICE}`, command, ...args]] : [command, args];
  return new Promise((resolve) => {
    const child = spawn(cmd, argv, { cwd: ROOT, stdio: live ? 'inherit' : ['ignore', 'pipe', 'pipe'] });
    const kept = [];
    if (!live) {
      child.stdout.on('data', (d) => kept.push(d));
      child.stderr.on('data', (d) => kept.push(d));
    }
    const end = (code) => {
      const seconds = (performance.now() - t0) / 1000;
      if (!live && kept.length) process.stdout.write(`\n--- ${name} ---\n${Buffer.concat(kept).toString('utf8')}`);
      console.log(`--- ${name}: ${code === 0 ? 'ok' : `FAILED (exit ${code})`}, ${seconds.toFixed(1)} s ---`);
      resolve({ name, code, seconds });
    };
    child.on('error', (e) => {
      kept.push(Buffer.from(`${e.message}\n`));
      end(127);
    });
    child.on('close', (code, signal) => end(code ?? (signal ? 128 : 1)));
  });
}

const node = process.execPath;
const bin = (name) => `${ROOT}node_modules/.bin/${name}`;
const t0 = performance.now();
/** Runs `start` once every one of `needs` has passed; otherwise the step is not run (exit code null). */
const after = async (needs, name, start) =>
  (await Promise.all(needs)).every((r) => r.code === 0) ? start() : { name, code: null, seconds: 0 };
const chromium = step('ensure chromium', node, ['tests/support/ensure-chromium.mjs'], { live: true });
const mkdocs = step('ensure mkdocs', node, ['tests/support/ensure-mkdocs.mjs'], { live: true });
const cli = step('build the command line', node, ['src/cli/bundle.mjs', '--if-stale']);
const x3pReaders = step('ensure x3p readers', node, ['tests/support/ensure-python-x3p.mjs'], { live: true });
const results = await Promise.all([
  chromium,
  mkdocs,
  cli,
  after([chromium, mkdocs, cli], 'browser tests', () =>
    step('browser tests', bin('vitest'), ['run', '--project', 'browser', ...vitestArgs], { live: true }),
  ),
  x3pReaders,
  after([cli, x3pReaders], 'node tests', () =>
    step('node tests', bin('vitest'), ['run', '--project', 'node', ...vitestArgs], { niced: true }),
  ),
  step('lint', bin('biome'), ['check', '.'], { niced: true }),
  step('typecheck', 'npm', ['run', '--silent', 'typecheck'], { niced: true }),
]);
console.log(
  `\nnpm test: ${((performance.now() - t0) / 1000).toFixed(1)} s (load average ${loadavg()
    .map((x) => x.toFixed(2))
    .join(' ')}: other work on the machine slows every step)`,
);
for (const r of results) console.log(`  ${r.name.padEnd(24)}${VERDICT(r.code)}${r.seconds.toFixed(1).padStart(8)} s`);
process.exitCode = results.every((r) => r.code === 0) ? 0 : 1;
