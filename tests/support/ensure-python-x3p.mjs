#!/usr/bin/env node
// Part of `npm test`: makes sure two x3p readers no one here wrote, the Python packages x3pio and
// surfalize (pinned), are installed for tests/core/output/x3p*.test.ts, which reads the calculator's
// x3p files with them (tests/support/x3p_read.py). Installs them with pip into a virtual environment
// in the cache outside the clone that ensure-mkdocs.mjs uses (one per machine and package set, shared
// by every clone and reused by the next run), falling back to `pip install --target` when
// `python3 -m venv` is unavailable and installing Debian's Python first when it is missing and we run
// as root (as on CI). Prints nothing when it is already there.
// The lightest set that reads the files and computes surfalize's height parameters, every package
// pinned and installed with `--no-deps`: the two readers, and only what reading needs (surfalize's
// declared dependencies would add matplotlib, scipy, pandas and more: 465 MB against 130 MB, and
// 2 s more to import). x3p_read.py stubs the rest of surfalize's imports with modules that raise
// when used.
//   node tests/support/ensure-python-x3p.mjs          install if missing
//   node tests/support/ensure-python-x3p.mjs --json   also print how to run Python with the readers
//                                                     ({python, env}) as the last line (for the tests)
import { execFileSync } from 'node:child_process';
import { createHash } from 'node:crypto';
import { existsSync, readFileSync, renameSync, rmSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { aptInstallPython, cacheDir, hasPython } from './ensure-mkdocs.mjs';

/**
 * The readers and exactly what reading a file and computing its height parameters needs (numpy and
 * defusedxml for x3pio; python-dateutil with tzdata, chardet and pillow, which surfalize's file
 * readers import), all pinned and installed with `--no-deps`.
 */
export const X3P_PACKAGES = [
  'x3pio==2.0.0',
  'surfalize==0.19.2',
  'numpy==2.4.6',
  'defusedxml==0.7.1',
  'python-dateutil==4.0.0',
  'tzdata==2026.6',
  'chardet==7.7.0',
  'pillow==13.0.0',
];
const spec = X3P_PACKAGES.join(' ');
const name = `python-x3p-${createHash('sha256').update(spec).digest('hex').slice(0, 12)}`;
const venv = join(cacheDir, `${name}-venv`);
const target = join(cacheDir, `${name}-target`);
/** Written last into a finished installation (which is renamed into place whole): its package set. */
const READY = 'x3p-readers-ready.txt';

/** The helper script that reads x3p files with both readers. */
export const X3P_READ_SCRIPT = fileURLToPath(new URL('./x3p_read.py', import.meta.url));

/** How to run Python with the readers: the interpreter and the environment it needs, or null when not installed. */
export function pythonX3pCommand() {
  const ready = (dir) => existsSync(join(dir, READY)) && readFileSync(join(dir, READY), 'utf8') === spec;
  if (ready(venv)) return { python: join(venv, 'bin', 'python'), env: {} };
  if (ready(target)) return { python: 'python3', env: { PYTHONPATH: target } };
  return null;
}

/** Installs the readers when missing (pip downloads some 20 MB); returns how to run them. */
export function ensurePythonX3p() {
  const existing = pythonX3pCommand();
  if (existing) return existing;
  const run = (cmd, args) => execFileSync(cmd, args, { stdio: 'inherit' });
  if (!hasPython()) aptInstallPython('the x3p readers');
  console.log(`The x3p readers (${X3P_PACKAGES.slice(0, 2).join(', ')}) not found: installing them with pip...`);
  const t0 = performance.now();
  // No bytecode compiled at install (Python compiles what it imports, once); pins only, no resolver.
  const pipInstall = [
    'install',
    '--disable-pip-version-check',
    '--root-user-action=ignore',
    '-q',
    '--no-compile',
    '--no-deps',
  ];
  // Built beside its final place and renamed into it whole, so a run that stops half-way leaves nothing that looks ready.
  const building = `${venv}.building-${process.pid}`;
  const venvPython = join(building, 'bin', 'python');
  // The first way that works: a venv without its own pip, filled by Python's pip (fast: creating a venv
  // with pip takes most of the time); a venv with its own pip (where Python has no pip, as Debian's
  // python3-venv without python3-pip); `pip --target` (where venv is missing).
  const ways = [
    {
      dir: venv,
      create: () => run('python3', ['-m', 'venv', '--without-pip', building]),
      pip: ['python3', '-m', 'pip', '--python', venvPython, ...pipInstall],
    },
    {
      dir: venv,
      create: () => run('python3', ['-m', 'venv', building]),
      pip: [venvPython, '-m', 'pip', ...pipInstall],
    },
    { dir: target, create: () => {}, pip: ['python3', '-m', 'pip', ...pipInstall, '--target', building] },
  ];
  let installed = null;
  for (const way of ways) {
    rmSync(building, { recursive: true, force: true });
    try {
      way.create();
      run(way.pip[0], [...way.pip.slice(1), ...X3P_PACKAGES]);
      installed = way.dir;
      break;
    } catch (error) {
      console.log(`(that way failed: ${error.message.split('\n')[0]}; trying the next)`);
    }
  }
  if (!installed) throw new Error('pip could not install them in a venv nor with --target');
  writeFileSync(join(building, READY), spec);
  rmSync(installed, { recursive: true, force: true });
  renameSync(building, installed);
  const command = pythonX3pCommand();
  if (!command) throw new Error('the x3p readers were installed but are not found');
  execFileSync(command.python, ['-c', 'import x3pio, numpy, defusedxml, dateutil, chardet, PIL'], {
    env: { ...process.env, ...command.env },
  });
  console.log(`The x3p readers installed in ${((performance.now() - t0) / 1000).toFixed(1)} s (${installed}).`);
  return command;
}

if (process.argv[1] && fileURLToPath(import.meta.url) === process.argv[1]) {
  try {
    const command = ensurePythonX3p();
    if (process.argv[2] === '--json') console.log(JSON.stringify(command));
  } catch (error) {
    console.error(
      `Could not install the x3p readers (${error.message}). Install Python 3 with pip and venv (apt-get install -y python3-venv).`,
    );
    process.exit(1);
  }
}
