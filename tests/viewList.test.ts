/**
 * One list of views (issue 28 leftovers): the field registry's `view` words (src/core/input/fields.ts)
 * are the ones the page takes in its URL, the ones the embed element sizes (VIEW_SIZES in
 * public/embed.js, '' being the whole calculator) and the ones the README names, `result` (the
 * embed's compact card) among them.
 */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { EMBED_SCRIPT } from '../src/build/embedAttributes';
import { FIELDS } from '../src/core/input/fields';
import { parseUrl } from '../src/ui/state';

/** The embed's compact card (src/ui/embedCard.ts RESULT_VIEW; that module needs a DOM). */
const RESULT_VIEW = 'result';

/** The keys of embed.js's VIEW_SIZES, as the script holds them. */
function embedViewSizes(): string[] {
  const literal = /const VIEW_SIZES = (\{[\s\S]*?\n {2}\});/.exec(readFileSync(EMBED_SCRIPT, 'utf8'))?.[1];
  if (literal === undefined) throw new Error('embed.js has no VIEW_SIZES');
  return Object.keys(new Function(`return ${literal};`)() as Record<string, unknown>);
}

describe('the views: one list', () => {
  const views: readonly string[] = FIELDS.view.values;

  it("the registry's view words include the embed's result card, and the URL takes each", () => {
    expect(views).toContain(RESULT_VIEW);
    for (const view of views) {
      const parsed = parseUrl(`?view=${view}&embed=1`);
      expect(parsed.view, view).toBe(view);
      expect(parsed.notices, view).toEqual([]);
    }
  });

  it('the embed element sizes exactly these views (and the whole calculator)', () => {
    expect(new Set(embedViewSizes())).toEqual(new Set(['', ...views]));
  });

  it('the README names each of them', () => {
    const readme = readFileSync(new URL('../README.md', import.meta.url), 'utf8');
    const listed = /`\?view=((?:[a-z]+\|)+[a-z]+)`/.exec(readme)?.[1]?.split('|') ?? [];
    expect(new Set([...listed, ...(readme.includes(`view="${RESULT_VIEW}"`) ? [RESULT_VIEW] : [])])).toEqual(
      new Set(views),
    );
  });
});
