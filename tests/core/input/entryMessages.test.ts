/**
 * How a message quotes what was typed (core/input/entryMessages.ts quotedEntry): cut at 24
 * characters, and every character a message would not show written as its escape, so that a
 * control character after a digit (the tester's `3` + U+0007) never reads as a valid number.
 */
import { describe, expect, it } from 'vitest';
import { entryFaultMessage, quotedEntry } from '../../../src/core/input/entryMessages';

describe('quotedEntry', () => {
  it('shows control, invisible and direction characters as escapes', () => {
    const cases: Array<[typed: string, quoted: string]> = [
      ['3\u0007', '3\\x07'],
      ['2\u001b[31m', '2\\x1b[31m'],
      ['\u202e5.0', '\\u202e5.0'],
      ['1\u200b2', '1\\u200b2'],
      ['1\n2', '1\\n2'],
      ['0,05 µm', '0,05 µm'],
    ];
    for (const [typed, quoted] of cases) expect(quotedEntry(typed)).toBe(quoted);
  });

  it('cuts a long entry at 21 characters and "..."', () => {
    expect(quotedEntry('x'.repeat(25))).toBe(`${'x'.repeat(21)}...`);
    expect(quotedEntry('x'.repeat(24))).toBe('x'.repeat(24));
  });

  it('a message quotes the escape', () => {
    expect(entryFaultMessage('Flutes z', 'not-a-number', '3\u0007', '', '')).toBe(
      'Flutes z must be a number (got "3\\x07").',
    );
  });
});
