/** `present=` from the link (src/ui/present.ts): the registry's word turns it on; another is named in a notice. */
import { describe, expect, it } from 'vitest';
import { FIELDS } from '../../src/core/input/fields';
import { parsePresent } from '../../src/ui/present';
import { parseUrl } from '../../src/ui/state';

describe('parsePresent', () => {
  it('present=1 is on, absent is off, another word is off with a notice naming the parameter and its value', () => {
    expect(parsePresent(parseUrl('?R=3&present=1').present)).toEqual({ on: true, notice: null });
    expect(parsePresent(parseUrl('?R=3').present)).toEqual({ on: false, notice: null });
    const other = parsePresent(parseUrl('?present=yes').present);
    expect(other.on).toBe(false);
    expect(other.notice).toBe(`${FIELDS.present.url}="yes" is not 1; presentation mode is off.`);
    expect(parsePresent('x'.repeat(500)).notice?.length).toBeLessThan(80);
  });
});
