/**
 * Light or dark: the page follows the system's `prefers-color-scheme` unless the link says
 * `theme=light|dark` (a documentation host matching its own theme; `theme=auto` follows the system,
 * as without it). An embedding host may change it later without reloading the page
 * (embedTheme.ts calls {@link setThemeOverride}). The chosen theme is
 * `data-theme` on the root element; every colour then comes from the stylesheet's custom
 * properties for that theme. Canvas parts (the 3D scenes, the chart) are told on each change.
 * Reading the link's word is themeChoice.ts's (no DOM).
 */
import type { Theme, ThemeChoice } from './themeChoice';

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

/** The override in force (null: the system's scheme is followed) and the system's scheme, once started. */
let override: Theme | null = null;
let media: MediaQueryList | null = null;

/** Puts `theme` on the root element and tells the listeners (after the stylesheet has the new colours). */
function apply(theme: Theme): void {
  const root = document.documentElement;
  if (root.dataset.theme === theme) return;
  root.dataset.theme = theme;
  for (const listener of listeners) listener(theme);
}

function systemTheme(): Theme {
  return media?.matches ? 'dark' : 'light';
}

/**
 * Applies the choice to the root element and, without an override, follows the system's
 * scheme as it changes (listeners are told after the stylesheet has the new colours).
 */
export function startTheme(choice: ThemeChoice): Theme {
  override = choice.override;
  if (media === null) {
    media = window.matchMedia('(prefers-color-scheme: dark)');
    media.addEventListener('change', () => {
      if (override === null) apply(systemTheme());
    });
  }
  apply(override ?? systemTheme());
  return currentTheme();
}

/**
 * Changes the override while the page runs (no reload): light or dark, or null to follow the
 * system's scheme from now on. Call after {@link startTheme}.
 */
export function setThemeOverride(next: Theme | null): Theme {
  override = next;
  apply(override ?? systemTheme());
  return currentTheme();
}

/** A custom property of the root element in the current theme (e.g. `--scene-bg`), trimmed. */
export function themeColour(name: string): string {
  return getComputedStyle(document.documentElement).getPropertyValue(name).trim();
}
