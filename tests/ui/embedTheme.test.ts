/**
 * The embedded page's theme messages from its host (src/ui/embedTheme.ts): only a message of the
 * right type with one of the registry's theme words is taken; anything else a window may post
 * (other types, other words, non-strings, inherited properties, arrays, null) is ignored.
 */
import { describe, expect, it } from 'vitest';
import { FIELDS } from '../../src/core/input/fields';
import { THEME_MESSAGE, themeOfMessage } from '../../src/ui/embedTheme';

describe('themeOfMessage', () => {
  it("takes each of the registry's theme words: light and dark, auto as null (follow the system)", () => {
    for (const theme of FIELDS.theme.values)
      expect(themeOfMessage({ type: THEME_MESSAGE, theme }), theme).toBe(theme === 'auto' ? null : theme);
  });

  it('ignores any other data: other types and words, non-strings, inherited properties', () => {
    const hostile: unknown[] = [
      null,
      undefined,
      'dark',
      42,
      [THEME_MESSAGE, 'dark'],
      { type: THEME_MESSAGE },
      { type: THEME_MESSAGE, theme: 'purple' },
      { type: THEME_MESSAGE, theme: 'Dark' },
      { type: THEME_MESSAGE, theme: ' dark' },
      { type: THEME_MESSAGE, theme: '<img src=x onerror=alert(1)>' },
      { type: THEME_MESSAGE, theme: ['dark'] },
      { type: THEME_MESSAGE, theme: { toString: () => 'dark' } },
      { type: 'path-interval:resize', theme: 'dark' },
      { type: [THEME_MESSAGE], theme: 'dark' },
      Object.create({ type: THEME_MESSAGE, theme: 'dark' }),
      { type: THEME_MESSAGE, theme: 'x'.repeat(1e6) },
    ];
    for (const data of hostile) expect(themeOfMessage(data), JSON.stringify(data)?.slice(0, 60)).toBeUndefined();
  });
});
