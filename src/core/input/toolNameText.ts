/**
 * A tool's name as the program keeps it, wherever it comes from (a library, the browser's saved
 * tools, a link): plain text, never markup, cut to a length. Pure, and small: the page reads a
 * link's tool name with the first result, without the library reader (toolLibrary.ts).
 */

/** A tool name's longest kept form (longer names are cut, with an ellipsis). */
export const TOOL_NAME_MAX_CHARS = 80;

/**
 * Characters a name never keeps: control characters (C0, DEL, C1) and the invisible ones that
 * reorder or hide text (bidirectional overrides and isolates, zero-width spaces and joiners, the
 * byte order mark), which could make a name read as another.
 */
function hidden(c: string): boolean {
  const code = c.codePointAt(0) ?? 0;
  return (
    code < 0x20 ||
    (code >= 0x7f && code <= 0x9f) ||
    (code >= 0x200b && code <= 0x200f) ||
    (code >= 0x202a && code <= 0x202e) ||
    (code >= 0x2060 && code <= 0x2069) ||
    code === 0xfeff
  );
}

/**
 * A name as kept (a library's, a saved tool's, a link's): plain text, hidden and control
 * characters made spaces, spaces collapsed, cut at {@link TOOL_NAME_MAX_CHARS} (with an ellipsis).
 */
export function cleanToolName(name: string): string {
  // Only the start is read: a name of megabytes is cut long before its end.
  const start = Array.from(name.slice(0, 4 * TOOL_NAME_MAX_CHARS), (c) => (hidden(c) ? ' ' : c));
  const t = start.join('').replace(/\s+/g, ' ').trim();
  return t.length > TOOL_NAME_MAX_CHARS ? `${t.slice(0, TOOL_NAME_MAX_CHARS - 1)}\u2026` : t;
}
