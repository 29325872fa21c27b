/**
 * The check the catalogue tests make of a sentence read back from the page's English and worded in
 * a language: worded at all, no English word of `english` left, and in Japanese no Latin word but
 * those `kept` (the paper's symbols, authors, units).
 */
import { expect } from 'vitest';
import type { Catalogue } from '../../../src/ui/i18n/catalogue';

/** `text`, the wording in `c`'s language of the page's sentence `source`, checked; returned as a string. */
export function expectWorded(
  text: string | null,
  source: string,
  c: Pick<Catalogue, 'lang'>,
  english: RegExp,
  kept: ReadonlySet<string>,
): string {
  expect(text, source).not.toBeNull();
  const t = text ?? '';
  expect([...new Set(t.match(english) ?? [])], t).toEqual([]);
  if (c.lang === 'ja') expect(t.match(/[A-Za-zµ][A-Za-z0-9]*/g)?.filter((w) => !kept.has(w)) ?? [], t).toEqual([]);
  return t;
}
