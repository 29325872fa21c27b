/** Headless Debian Chromium for the browser tests and the web benchmark (never a downloaded build). */
import { existsSync } from 'node:fs';
import { type Browser, chromium } from 'playwright-core';

export function chromiumPath(): string {
  const found = [process.env.CHROMIUM_PATH, '/usr/bin/chromium', '/usr/bin/chromium-browser'].find(
    (p): p is string => typeof p === 'string' && existsSync(p),
  );
  if (!found) throw new Error('No Chromium found: run `node tests/support/ensure-chromium.mjs` (npm test does it).');
  return found;
}

/**
 * Launches headless Chromium with WebGL on SwiftShader.
 *
 * `gpuCompositing` (default false): the page's layers composited on the GPU process (SwiftShader)
 * as a browser with a GPU does. The tests composite in software instead: the same pixels for the
 * page and its WebGL canvas (read back once per frame), and about half the GPU process's CPU (the
 * scene-heavy test files measured 66.7 -> 30.4 s of it, 77 -> 62 s of wall time, on this 2-core
 * machine). The web benchmark keeps GPU compositing, so that its figures stay those of a browser
 * with a GPU path.
 */
export function launchChromium({ gpuCompositing = false }: { gpuCompositing?: boolean } = {}): Promise<Browser> {
  return chromium.launch({
    executablePath: chromiumPath(),
    headless: true,
    args: [
      '--no-sandbox',
      '--disable-background-networking',
      '--disable-component-update',
      '--no-first-run',
      '--disable-quic',
      '--disable-sync',
      '--enable-unsafe-swiftshader',
      '--use-angle=swiftshader',
      ...(gpuCompositing ? [] : ['--disable-gpu-compositing']),
    ],
  });
}

/**
 * A note Chromium's GL driver logs on the page's console under software compositing ("GL Driver
 * Message (OpenGL, Performance, ...): GPU stall due to ReadPixels", when the compositor reads a
 * WebGL canvas back): the test set-up's, not the page's; tests that keep every warning skip it.
 */
export function isGlDriverNote(consoleText: string): boolean {
  return /^\[\.WebGL-[0-9a-fx]+\]GL Driver Message \(OpenGL, Performance,/.test(consoleText);
}
