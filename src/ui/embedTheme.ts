/**
 * The embedded page's theme, changed by its host without a reload: the host (public/embed.js,
 * when its `theme` attribute changes or, with `theme="auto"`, when the host page's colour scheme
 * does) posts `{ type: 'path-interval:theme', theme: 'light' | 'dark' | 'auto' }` to the frame.
 * The message is hostile until checked: it is taken only from the window that embeds this page
 * (`event.source === window.parent`), from that window's origin where the browser tells it
 * (`location.ancestorOrigins`, else the referrer's origin), and only with a theme word of the
 * field registry; anything else is ignored, silently (it may be another script's message).
 */
import { overrideOfWord, type Theme } from './themeChoice';

/** The message type the embedded page takes from its host. */
export const THEME_MESSAGE = 'path-interval:theme';

/**
 * The theme a message's data asks for: light or dark, or null for auto (follow the system);
 * undefined when the data is not a theme message with one of the registry's words. `data` is
 * anything a window posted: only own, plain string properties are read.
 */
export function themeOfMessage(data: unknown): Theme | null | undefined {
  if (typeof data !== 'object' || data === null || Array.isArray(data)) return undefined;
  const record = data as Record<string, unknown>;
  if (!Object.hasOwn(record, 'type') || record.type !== THEME_MESSAGE) return undefined;
  if (!Object.hasOwn(record, 'theme') || typeof record.theme !== 'string') return undefined;
  return overrideOfWord(record.theme);
}

/** The origin of the window that embeds this page, when the browser tells it; null when it does not. */
export function embedderOrigin(): string | null {
  const ancestors = window.location.ancestorOrigins;
  if (ancestors !== undefined && ancestors.length > 0) return ancestors[0] ?? null;
  try {
    return document.referrer === '' ? null : new URL(document.referrer).origin;
  } catch {
    return null;
  }
}

/**
 * Listens for the host's theme messages (see the module's comment for the checks) and calls
 * `onTheme` with each theme asked (null: follow the system). Does nothing when the page is not in
 * a frame. Returns a function that stops listening.
 */
export function listenForHostTheme(onTheme: (theme: Theme | null) => void): () => void {
  if (window.parent === window) return () => undefined;
  const origin = embedderOrigin();
  const listener = (event: MessageEvent): void => {
    if (event.source !== window.parent) return;
    if (origin !== null && event.origin !== origin) return;
    const theme = themeOfMessage(event.data);
    if (theme !== undefined) onTheme(theme);
  };
  window.addEventListener('message', listener);
  return () => window.removeEventListener('message', listener);
}
