/**
 * The core as a library: `npm run build:lib` builds the entry of package.json's `exports`, the
 * README's example runs against it in a Node process (importing the package by its name), a
 * TypeScript consumer type-checks against its declarations, and every function it exports has
 * its JSDoc.
 */
import { execFileSync, spawnSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { beforeAll, describe, expect, it } from 'vitest';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));
const read = (path: string) => readFileSync(join(ROOT, path), 'utf8');

/** The README's code block marked `js library-example`. */
function readmeExample(): string {
  const m = /```js library-example\n([\s\S]*?)```/.exec(read('README.md'));
  if (!m) throw new Error('README has no `js library-example` block');
  return m[1] as string;
}

describe('the core as a library (package.json exports)', () => {
  beforeAll(() => {
    execFileSync('npm', ['run', '--silent', 'build:lib'], { cwd: ROOT, stdio: 'pipe' });
  }, 120_000);

  it("runs the README's example in Node, importing the package by its name", () => {
    const r = spawnSync(process.execPath, ['--input-type=module', '-e', readmeExample()], {
      cwd: ROOT,
      encoding: 'utf8',
    });
    expect(r.stderr).toBe('');
    const lines = r.stdout.trim().split('\n');
    // The exact value is the one the CLI prints for the same input (tests/cli); the comments in
    // the README must say what the example really prints.
    expect(lines[0]).toBe('exact L = 1.3658 mm');
    expect(lines[1]).toMatch(/^Sekine L = 0\.9719 mm$/);
    expect(lines[2]).toMatch(/^Corner radius Rcr must not exceed the tool radius R = 3 mm \(got 4\)/);
    expect(lines).toHaveLength(3);
    // Each line printed is quoted in the example's comments, so the README says what it prints.
    for (const line of lines) expect(readmeExample()).toContain(`// ${line}`);
  });

  it('type-checks a TypeScript consumer against the declarations it ships', () => {
    mkdirSync(join(ROOT, 'test-results'), { recursive: true });
    const dir = mkdtempSync(join(ROOT, 'test-results', 'lib-consumer-'));
    writeFileSync(
      join(dir, 'consumer.ts'),
      `import { type ExactForward, exactForward, validateForward } from 'path-interval';
const v = validateForward({ R: 3, Rcr: 1, rho: 5, h: 0.01 });
const e: ExactForward | null = v.ok ? exactForward(v.value) : null;
const mm: number | undefined = e?.intervalMm;
// @ts-expect-error the result has no such member
e?.notAMember;
export { mm };
`,
    );
    // A consumer project of its own: strict, bundler resolution, and no ambient @types (`types: []`).
    // The shipped declarations need none, and without the limit tsc also read every @types package
    // of this repository (three.js's 500 files, Node's): 10 s of CPU instead of 2.5.
    writeFileSync(
      join(dir, 'tsconfig.json'),
      JSON.stringify({
        compilerOptions: {
          noEmit: true,
          strict: true,
          module: 'esnext',
          moduleResolution: 'bundler',
          target: 'es2022',
          types: [],
        },
        files: ['consumer.ts'],
      }),
    );
    const tsc = join(ROOT, 'node_modules', 'typescript', 'bin', 'tsc');
    const r = spawnSync(process.execPath, [tsc, '-p', dir], { cwd: ROOT, encoding: 'utf8' });
    expect(r.stdout + r.stderr).toBe('');
    expect(r.status).toBe(0);
  });

  it('documents every function it exports (JSDoc where the function is declared)', () => {
    const entry = read('src/core/library.ts');
    const undocumented: string[] = [];
    for (const m of entry.matchAll(/^export \{([^}]*)\} from '\.\/(\w+)';/gm)) {
      const source = read(`src/core/${m[2]}.ts`);
      for (const name of (m[1] as string)
        .split(',')
        .map((s) => s.trim())
        .filter(Boolean)) {
        const decl = new RegExp(`(\\*/\\s*)?export (?:function|const) ${name}\\b`).exec(source);
        if (!decl) undocumented.push(`${name} (not declared in ${m[2]}.ts)`);
        else if (!decl[1]) undocumented.push(`${name} (${m[2]}.ts)`);
      }
    }
    expect(undocumented).toEqual([]);
  });
});
