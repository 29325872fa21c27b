/**
 * Light or dark: the page follows the system's `prefers-color-scheme` unless the link says
 * `theme=light|dark` (a documentation host matching its own theme). The chosen theme is
 * `data-theme` on the root element; every colour then comes from the stylesheet's custom
 * properties for that theme. Canvas parts (the 3D scenes, the chart) are told on each change.
 */

import { FIELDS } from '../core/input/fields';

export type Theme = 'light' | 'dark';

export interface ThemeChoice {
  /** The theme the link asks for, or null to follow the system. */
  readonly override: Theme | null;
  /** A notice when the link's value is not light or dark (it is then ignored). */
  readonly notice: string | null;
}

/** Reads `theme=` from a query string: `light`, `dark`, absent (follow the system) or invalid (notice). */
export function parseTheme(search: string): ThemeChoice {
  const { url, values } = FIELDS.theme;
  const text = new URLSearchParams(search).get(url);
  if (text === null) return { override: null, notice: null };
  const theme = values.find((v) => v === text);
  if (theme !== undefined) return { override: theme, notice: null };
  return {
    override: null,
    notice: `${url}="${text.slice(0, 20)}" is not ${values.join(' or ')}; following the system's colour scheme.`,
  };
}

const listeners = new Set<(theme: Theme) => void>();

/** The theme on screen now (the root element's `data-theme`, light until one is applied). */
export function currentTheme(): Theme {
  return document.documentElement.dataset.theme === 'dark' ? 'dark' : 'light';
}

/** Calls `listener` on every later change of theme; returns a function that stops it. */
export function onThemeChange(listener: (theme: Theme) => void): () => void {
  listeners.add(listener);
  return () => listeners.delete(listener);
}

/**
 * Applies the choice to the root element and, without an override, follows the system's
 * scheme as it changes (listeners are told after the stylesheet has the new colours).
 */
export function startTheme(choice: ThemeChoice): Theme {
  const root = document.documentElement;
  const media = window.matchMedia('(prefers-color-scheme: dark)');
  const apply = (theme: Theme): void => {
    if (root.dataset.theme === theme) return;
    root.dataset.theme = theme;
    for (const listener of listeners) listener(theme);
  };
  apply(choice.override ?? (media.matches ? 'dark' : 'light'));
  if (choice.override === null) media.addEventListener('change', (e) => apply(e.matches ? 'dark' : 'light'));
  return currentTheme();
}

/** A custom property of the root element in the current theme (e.g. `--scene-bg`), trimmed. */
export function themeColour(name: string): string {
  return getComputedStyle(document.documentElement).getPropertyValue(name).trim();
}
