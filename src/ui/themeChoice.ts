/**
 * The theme a link or a host asks for, read from text (no DOM, so the link's readers can be
 * checked in Node): `theme=light|dark` overrides the system's colour scheme, `auto` (or no
 * `theme=`) follows it. The words are the field registry's (FIELDS.theme.values).
 */
import { FIELDS } from '../core/input/fields';

export type Theme = 'light' | 'dark';

export interface ThemeChoice {
  /** The theme the link asks for, or null to follow the system. */
  readonly override: Theme | null;
  /** A notice when the link's value is not light or dark (it is then ignored). */
  readonly notice: string | null;
}

/** A word of `theme=` (the field registry's): light, dark or auto. */
export type ThemeWord = (typeof FIELDS.theme.values)[number];

/** The override a word of `theme=` asks for: light or dark, or null (auto: follow the system); undefined for any other text. */
export function overrideOfWord(text: unknown): Theme | null | undefined {
  const word = FIELDS.theme.values.find((v) => v === text);
  if (word === undefined) return undefined;
  return word === 'auto' ? null : word;
}

/** Reads `theme=` from a query string: `light`, `dark`, `auto` or absent (follow the system), or invalid (notice). */
export function parseTheme(search: string): ThemeChoice {
  const { url, values } = FIELDS.theme;
  const text = new URLSearchParams(search).get(url);
  if (text === null) return { override: null, notice: null };
  const override = overrideOfWord(text);
  if (override !== undefined) return { override, notice: null };
  return {
    override: null,
    notice: `${url}="${text.slice(0, 20)}" is not ${values.slice(0, -1).join(', ')} or ${values.at(-1)}; following the system's colour scheme.`,
  };
}
