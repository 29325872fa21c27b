/**
 * axe-core run on a page or a frame as it is (the instrumented build is served without a CSP, so
 * the injected script runs): one line per violation (rule, count, first targets), for a page or a
 * frame (an embed inside its host page).
 */
import { readFileSync } from 'node:fs';
import type { Frame, Page } from 'playwright-core';
import { ROOT } from './harness';

const AXE = readFileSync(`${ROOT}node_modules/axe-core/axe.min.js`, 'utf8');

interface AxeViolation {
  readonly id: string;
  readonly nodes: ReadonlyArray<{ readonly target: readonly string[] }>;
}

/** axe-core's violations in `target` (a page or one frame), one line each. */
export async function axeViolations(target: Page | Frame): Promise<string[]> {
  // Once per document (axe-core is about 500 kB of script to parse).
  if (!(await target.evaluate(() => 'axe' in window))) await target.addScriptTag({ content: AXE });
  const found = await target.evaluate(async () => {
    const axe = (window as unknown as { axe: { run(): Promise<{ violations: AxeViolation[] }> } }).axe;
    return (await axe.run()).violations;
  });
  return found.map(
    (v) =>
      `${v.id} x${v.nodes.length}: ${v.nodes
        .slice(0, 3)
        .map((n) => n.target.join(' '))
        .join(', ')}`,
  );
}
