/**
 * Text that may hold what the user typed, made visible on one line: the command line's errors
 * (cli/output.ts) and every message's quote of an entry (entryMessages.ts quotedEntry) write each
 * control character as its escape. Pure, a leaf.
 */

/** Escapes of the control characters that have a short one. */
const SHORT_ESCAPES: Readonly<Record<string, string>> = { '\n': '\\n', '\r': '\\r', '\t': '\\t' };

/**
 * Control characters: C0 (line breaks, tab, ESC...), DEL and C1, the Unicode line and paragraph
 * separators, the bidirectional controls (which reorder what a terminal shows after them), and
 * the zero-width characters (which hide between digits).
 */
// biome-ignore lint/suspicious/noControlCharactersInRegex: matching control characters is the point
const CONTROL = /[\u0000-\u001f\u007f-\u009f\u061c\u200b-\u200f\u2028\u2029\u202a-\u202e\u2066-\u2069\ufeff]/g;

/**
 * Text that may hold what the user typed, shown on one line: every control character written as
 * an escape (`\n`, `\r`, `\t`, `\x1b`, `\u2028`), so a value holding a line break or a terminal
 * escape sequence can neither split an error in two nor reach the terminal. Other text, a
 * backslash included, is kept as it is.
 */
export function escapeControls(text: string): string {
  return text.replace(CONTROL, (c) => {
    const short = SHORT_ESCAPES[c];
    if (short !== undefined) return short;
    const code = c.charCodeAt(0);
    return code < 0x100 ? `\\x${code.toString(16).padStart(2, '0')}` : `\\u${code.toString(16).padStart(4, '0')}`;
  });
}
