#!/usr/bin/env node
// Part of `npm test`: makes sure a Chromium for the browser tests is on this machine.
// Uses $CHROMIUM_PATH or Debian's /usr/bin/chromium; installs Debian's `chromium`
// package with apt-get when neither exists (as root, as on CI). Never downloads a browser build.
import { execFileSync } from 'node:child_process';
import { existsSync } from 'node:fs';

const candidates = [process.env.CHROMIUM_PATH, '/usr/bin/chromium', '/usr/bin/chromium-browser'].filter(Boolean);
if (candidates.some((p) => existsSync(p))) process.exit(0);

const isRoot = typeof process.getuid === 'function' && process.getuid() === 0;
const apt = ['apt-get', 'update'];
const install = ['apt-get', 'install', '-y', '--no-install-recommends', 'chromium'];
const run = (cmd) =>
  execFileSync(isRoot ? cmd[0] : 'sudo', isRoot ? cmd.slice(1) : cmd, {
    stdio: 'inherit',
    env: { ...process.env, DEBIAN_FRONTEND: 'noninteractive' },
  });
try {
  console.log("Chromium not found: installing Debian's chromium package for the browser tests...");
  run(apt);
  run(install);
} catch (error) {
  console.error(`Could not install chromium (${error.message}). Install it with: apt-get install -y chromium`);
  process.exit(1);
}
if (!existsSync('/usr/bin/chromium')) {
  console.error('chromium was installed but /usr/bin/chromium is missing');
  process.exit(1);
}
