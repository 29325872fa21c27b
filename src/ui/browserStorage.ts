/** The browser's Web Storage as the page's remembered things use it (saved tools, preferences). */
import type { ToolStorage } from './savedTools';

/** The browser's localStorage, or null where reading it throws (disabled storage, a sandboxed frame). */
export function browserStorage(): ToolStorage | null {
  try {
    return window.localStorage;
  } catch {
    return null;
  }
}
