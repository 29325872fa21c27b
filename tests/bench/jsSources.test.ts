import { describe, expect, it } from 'vitest';
import { chunkSources, decodeMappings, textBySource } from '../../src/bench/jsSources';

// Segments worked out by hand from the Base64 VLQ of the Source Map v3 spec: A = 0, C = +1,
// D = -1, E = +2, gB = 32 + 1 * 32 = +16 (continuation bit 32, sign in the lowest bit).
const MAPPINGS = 'AAAA,gBCAA;EDAA';

describe('bench:js-sources attribution', () => {
  it('decodes the VLQ segments: columns per line, source indices summed across lines', () => {
    expect(decodeMappings(MAPPINGS)).toEqual([
      [
        { column: 0, source: 0 },
        { column: 16, source: 1 },
      ],
      [{ column: 2, source: 0 }],
    ]);
  });

  it("gives each segment's text, up to the next segment, to its source; text before any to (unmapped)", () => {
    const parts = textBySource('0123456789abcdefXYZ\nab cd', { mappings: MAPPINGS, sources: ['a.ts', 'b.ts'] });
    expect(Object.fromEntries(parts)).toEqual({ 'a.ts': '0123456789abcdef cd\n', 'b.ts': 'XYZ\n', '(unmapped)': 'ab' });
  });

  it('counts a chunk without a source map whole, as "(no source map)" (it crashed on one)', () => {
    expect(Object.fromEntries(chunkSources('self.a=1;\nb()', null))).toEqual({ '(no source map)': 'self.a=1;\nb()' });
    const mapped = chunkSources('0123456789abcdefXYZ\nab cd', { mappings: MAPPINGS, sources: ['a.ts', 'b.ts'] });
    expect(mapped.get('b.ts')).toBe('XYZ\n');
  });
});
