#!/usr/bin/env node
// Part of `npm test`: makes sure MkDocs (pinned) is available for the example documentation site
// (tests/docs-site/). Installs it with pip into a virtual environment in a cache outside the clone
// ($PATH_INTERVAL_CACHE, else $XDG_CACHE_HOME/path-interval, else ~/.cache/path-interval), so the
// next CI run on the same machine reuses it and a new machine installs it again, when missing (falls back to `pip install --target` when
// `python3 -m venv` is unavailable; installs Debian's python3 and python3-venv with apt-get when
// Python itself is missing and we run as root, as on CI). Prints nothing when it is already there.
//   node tests/support/ensure-mkdocs.mjs                          install if missing
//   node tests/support/ensure-mkdocs.mjs build <mkdocs.yml> <dir> also build a site into <dir>
import { execFileSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { homedir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';

export const MKDOCS_VERSION = '1.6.1';
/** The cache folder outside the clone: one MkDocs per machine and version, shared by every clone. */
export const cacheDir =
  process.env.PATH_INTERVAL_CACHE || join(process.env.XDG_CACHE_HOME || join(homedir(), '.cache'), 'path-interval');
const venv = join(cacheDir, `mkdocs-${MKDOCS_VERSION}-venv`);
const target = join(cacheDir, `mkdocs-${MKDOCS_VERSION}-target`);

/** How to run mkdocs here: the command and the environment it needs, or null when not installed. */
export function mkdocsCommand() {
  const venvPython = join(venv, 'bin', 'python');
  if (existsSync(join(venv, 'bin', 'mkdocs'))) return { python: venvPython, env: {} };
  if (existsSync(join(target, 'mkdocs'))) return { python: 'python3', env: { PYTHONPATH: target } };
  return null;
}

function installedVersion(cmd) {
  try {
    const out = execFileSync(cmd.python, ['-m', 'mkdocs', '--version'], {
      env: { ...process.env, ...cmd.env },
      encoding: 'utf8',
    });
    return /version (\S+)/.exec(out)?.[1] ?? null;
  } catch {
    return null;
  }
}

/** Whether python3 with venv and ensurepip runs here. */
export function hasPython() {
  try {
    execFileSync('python3', ['--version'], { stdio: 'ignore' });
    execFileSync('python3', ['-c', 'import venv, ensurepip'], { stdio: 'ignore' });
    return true;
  } catch {
    return false;
  }
}

/** Installs Debian's python3, python3-venv and pip when running as root (as on CI); `purpose` names what needs it. */
export function aptInstallPython(purpose = 'MkDocs') {
  const isRoot = typeof process.getuid === 'function' && process.getuid() === 0;
  if (!isRoot) return;
  const env = { ...process.env, DEBIAN_FRONTEND: 'noninteractive' };
  console.log(`Python 3 with venv not found: installing Debian's python3 and python3-venv for ${purpose}...`);
  execFileSync('apt-get', ['update'], { stdio: 'inherit', env });
  execFileSync('apt-get', ['install', '-y', '--no-install-recommends', 'python3', 'python3-venv', 'python3-pip'], {
    stdio: 'inherit',
    env,
  });
}

export function ensureMkdocs() {
  const existing = mkdocsCommand();
  if (existing && installedVersion(existing) === MKDOCS_VERSION) return existing;
  const run = (cmd, args) => execFileSync(cmd, args, { stdio: 'inherit' });
  if (!hasPython()) aptInstallPython();
  console.log(`MkDocs ${MKDOCS_VERSION} not found: installing it with pip for the example documentation site...`);
  let venvOk = true;
  try {
    run('python3', ['-m', 'venv', venv]);
  } catch {
    venvOk = false;
  }
  if (venvOk && existsSync(join(venv, 'bin', 'pip'))) {
    run(join(venv, 'bin', 'pip'), ['install', '--disable-pip-version-check', '-q', `mkdocs==${MKDOCS_VERSION}`]);
  } else {
    run('python3', [
      '-m',
      'pip',
      'install',
      '--disable-pip-version-check',
      '-q',
      '--target',
      target,
      `mkdocs==${MKDOCS_VERSION}`,
    ]);
  }
  const installed = mkdocsCommand();
  if (!installed || installedVersion(installed) !== MKDOCS_VERSION)
    throw new Error('MkDocs was installed but does not run');
  return installed;
}

if (process.argv[1] && fileURLToPath(import.meta.url) === process.argv[1]) {
  try {
    const mkdocs = ensureMkdocs();
    if (process.argv[2] === 'build') {
      const [config, out] = process.argv.slice(3);
      execFileSync(mkdocs.python, ['-m', 'mkdocs', 'build', '--quiet', '--strict', '-f', config, '-d', out], {
        stdio: 'inherit',
        env: { ...process.env, ...mkdocs.env },
      });
    }
  } catch (error) {
    console.error(
      `Could not install MkDocs (${error.message}). Install Python 3 with pip and venv (apt-get install -y python3-venv).`,
    );
    process.exit(1);
  }
}
