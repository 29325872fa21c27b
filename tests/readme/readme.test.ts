/**
 * The README opens with what a newcomer needs, in this order: the title, one sentence of what the
 * calculator answers, a screenshot of the page (a committed PNG that exists), the two commands, a
 * short walk-through and a glossary with its sketch; the reference follows, opened by a contents list
 * that matches its headings. Every local file and anchor the README links to exists. The README
 * refers to no issue (a heading or line says what is, not which issue asked for it) and states no
 * long sentence twice (a fact has one place; others link to it).
 */
import { existsSync, readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));
const read = (path: string): string => readFileSync(`${ROOT}${path}`, 'utf8');
const README = read('README.md');

/** The README's blocks (paragraphs, headings, lists, fenced code) in order, each with its offset. */
function blocks(text: string): Array<{ readonly at: number; readonly text: string }> {
  const out: Array<{ at: number; text: string }> = [];
  const re = /```[\s\S]*?```|[^\n](?:[\s\S]*?)(?=\n\s*\n|$)/g;
  for (let m = re.exec(text); m !== null; m = re.exec(text)) out.push({ at: m.index, text: m[0] });
  return out;
}

/** Offset of the `## title` heading (exact line), or -1. */
const heading = (title: string): number => README.search(new RegExp(`^## ${title}$`, 'm'));

/** The section under a `## title` heading, up to the next `## `. */
function section(title: string): string {
  const start = heading(title);
  if (start < 0) throw new Error(`README has no "## ${title}"`);
  const next = README.indexOf('\n## ', start + 3);
  return README.slice(start, next < 0 ? undefined : next);
}

/** Width and height of a PNG, from its IHDR chunk. */
function pngSize(path: string): { width: number; height: number } {
  const b = readFileSync(`${ROOT}${path}`);
  expect(b.subarray(0, 8).toString('hex')).toBe('89504e470d0a1a0a');
  return { width: b.readUInt32BE(16), height: b.readUInt32BE(20) };
}

/** The GitHub anchor of a heading. */
const slug = (title: string): string =>
  title
    .toLowerCase()
    .replace(/[^\w\- ]/g, '')
    .replace(/ /g, '-');

describe('README opening', () => {
  const parts = blocks(README);

  it('is the title, one sentence of what it answers, then the screenshot', () => {
    expect(parts[0]?.text).toMatch(/^# \S/);
    const sentence = (parts[1]?.text ?? '').replace(/`[^`]*`/g, 'x').replace(/\s+/g, ' ');
    expect(sentence).toMatch(/^It answers .*\.$/);
    expect(sentence.slice(0, -1)).not.toMatch(/[.?!](\s|$)/); // one sentence
    const image = /^!\[([^\]]+)\]\(([^)]+)\)$/.exec(parts[2]?.text ?? '');
    expect(image?.[2]).toBe('tests/readme/screenshot.png');
    expect((image?.[1] ?? '').length).toBeGreaterThan(20); // says what the image shows
    expect(pngSize('tests/readme/screenshot.png')).toEqual({ width: 1280, height: 800 });
  });

  it('gives the two commands next, the ones CI runs', () => {
    expect(parts[3]?.text).toBe('## Two commands');
    const code = /^```sh\n([\s\S]*?)```$/.exec(parts[4]?.text ?? '');
    const commands = (code?.[1] ?? '')
      .split('\n')
      .map((l) => l.replace(/#.*/, '').trim())
      .filter((l) => l !== '');
    expect(commands).toEqual(['npm ci && npm start', 'npm test']);
    const scripts = JSON.parse(read('package.json')).scripts;
    expect(Object.keys(scripts)).toEqual(expect.arrayContaining(['start', 'test']));
    expect(read('.ci/run')).toMatch(/^npm ci\b/m);
    expect(read('.ci/run')).toMatch(/^npm test$/m);
  });

  it('walks through the page in a few steps (30 seconds of reading)', () => {
    const walk = section('In 30 seconds');
    const steps = walk.match(/^\d+\. /gm) ?? [];
    expect(steps.length).toBeGreaterThanOrEqual(3);
    expect(steps.length).toBeLessThanOrEqual(7);
    expect(walk.split(/\s+/).length).toBeLessThan(300);
    expect(walk).toContain('npm ci && npm start');
  });

  it('has a glossary with its sketch, defining each term the page and the paper use', () => {
    const glossary = section('Glossary');
    expect(glossary).toMatch(/^!\[[^\]]{20,}\]\(tests\/readme\/glossary\.svg\)$/m);
    expect(read('tests/readme/glossary.svg')).toMatch(/^<svg [^>]*xmlns="http:\/\/www\.w3\.org\/2000\/svg"/);
    const terms = [...glossary.matchAll(/^- \*\*(.+?)\*\*/gm)].map((m) => m[1]).join(' | ');
    for (const term of ['Lead `rho`', 'Tilt `beta`', 'CC path', 'Step-over `L`', '`L/2`', 'Scallop height `h`'])
      expect(terms).toContain(term);
    expect(terms).toContain('h pseudo plane');
    expect(terms).toContain('`P_hp`');
  });

  it('labels in the sketch what the glossary defines', () => {
    const labels = [...read('tests/readme/glossary.svg').matchAll(/<text[^>]*>([^<]+)<\/text>/g)].map((m) => m[1]);
    for (const label of ['P_hp', 'h pseudo plane', 'L/2', 'CC', 'Rcr', 'rho', 'beta', 'O', 'h', 'design plane'])
      expect(labels).toContain(label);
    expect(labels.some((l) => l?.startsWith('L, the step-over'))).toBe(true);
  });

  it('puts the parts in that order, the reference after them', () => {
    const order = [
      README.indexOf('\nIt answers '),
      README.indexOf('](tests/readme/screenshot.png)'),
      heading('Two commands'),
      heading('In 30 seconds'),
      heading('Glossary'),
      heading('Reference'),
      heading('What it computes'),
      heading('The calculator \\(browser\\)'),
      heading('Command line'),
      heading('The solver core as a library'),
      heading('Layout'),
      heading('Decisions'),
    ];
    expect(order.every((at) => at > 0)).toBe(true);
    expect([...order].sort((a, b) => a - b)).toEqual(order);
  });

  it('says how the screenshot is kept current and taken again', () => {
    expect(README).toContain(
      'UPDATE_README_SHOT=1 npx vitest run --project browser tests/e2e/readmeScreenshot.test.ts',
    );
    expect(existsSync(`${ROOT}tests/e2e/readmeScreenshot.test.ts`)).toBe(true);
  });

  it('says that the screenshots for a person to look at are kept only by npm run shots, as the script does', () => {
    const shots = blocks(README).find((b) => b.text.startsWith('**Screenshots.**'))?.text ?? '';
    const script: string = JSON.parse(read('package.json')).scripts.shots;
    expect(shots).toContain('`npm run shots`');
    expect(shots).toContain(`\`${script}\``);
    expect(shots).toContain('test-results/screenshots/');
    expect(script).toMatch(/^E2E_SHOTS=1 /);
    expect(read('tests/e2e/harness.ts')).toMatch(/KEEP_SHOTS = Boolean\(process\.env\.E2E_SHOTS\)/);
  });
});

describe('README links', () => {
  it('points only at files that exist and headings that exist', () => {
    const anchors = new Set([...README.matchAll(/^#+ (.+)$/gm)].map((m) => slug(m[1] as string)));
    const targets = [...README.matchAll(/\]\(([^)\s]+)\)/g)].map((m) => m[1] as string);
    expect(targets.length).toBeGreaterThan(2);
    for (const target of targets) {
      if (/^https?:/.test(target)) continue;
      if (target.startsWith('#')) expect(anchors, target).toContain(target.slice(1));
      else expect(existsSync(`${ROOT}${target}`), target).toBe(true);
    }
  });
});

/** The `##` and `###` headings after `## Reference`, in order, as their titles. */
function referenceHeadings(text: string): string[] {
  const start = text.search(/^## Reference$/m);
  if (start < 0) throw new Error('README has no "## Reference"');
  const body = text.slice(start).replace(/```[\s\S]*?```/g, '');
  return [...body.matchAll(/^#{2,3} (.+)$/gm)].map((m) => m[1] as string).slice(1);
}

/** The contents list under `## Reference`: each `[title](#anchor)` link of its list items, in order. */
function contents(text: string): Array<{ readonly title: string; readonly anchor: string }> {
  const start = text.search(/^## Reference$/m);
  const next = text.indexOf('\n## ', start + 3);
  const list = text
    .slice(start, next < 0 ? undefined : next)
    .split('\n')
    .filter((l) => /^\s*- /.test(l));
  return list.flatMap((l) =>
    [...l.matchAll(/\[([^\]]+)\]\(#([^)]+)\)/g)].map((m) => ({ title: m[1] as string, anchor: m[2] as string })),
  );
}

/** Lines (1-based, with their text) that mention an issue: "issue 21", "(issue-17)", "the issues". */
function issueLines(text: string): string[] {
  return text
    .split('\n')
    .map((line, i) => `${i + 1}: ${line}`)
    .filter((l) => /\bissues?\b/i.test(l));
}

/** Sentences of at least `minWords` words that occur more than once (whitespace and case ignored). */
function repeatedSentences(text: string, minWords = 12): string[] {
  const prose = text.replace(/```[\s\S]*?```/g, ' ').replace(/^\|.*$/gm, ' ');
  const seen = new Map<string, number>();
  for (const raw of prose.split(/(?<=[.;:!?])\s+|\n\s*\n/)) {
    const sentence = raw
      .replace(/^[-\s]+/, '')
      .replace(/\s+/g, ' ')
      .trim()
      .toLowerCase();
    if (sentence.split(' ').length < minWords) continue;
    seen.set(sentence, (seen.get(sentence) ?? 0) + 1);
  }
  return [...seen].filter(([, n]) => n > 1).map(([s]) => s);
}

describe('README reference', () => {
  it('opens with a contents list that names every heading of the reference, in order, and nothing else', () => {
    const headings = referenceHeadings(README);
    expect(headings.length).toBeGreaterThan(10);
    const listed = contents(README);
    expect(listed.map((c) => c.title)).toEqual(headings);
    expect(listed.map((c) => c.anchor)).toEqual(headings.map(slug));
  });

  it('refers to no issue, in a heading or anywhere else', () => {
    expect(issueLines(README)).toEqual([]);
  });

  it('states no long sentence twice (one place for each fact)', () => {
    expect(repeatedSentences(README)).toEqual([]);
  });
});
