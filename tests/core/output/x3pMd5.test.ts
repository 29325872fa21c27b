/**
 * The MD5 the x3p file stores for main.xml and its data (src/core/math/md5.ts), against Node's
 * own (OpenSSL's) MD5: RFC 1321's test suite, every length around the padding boundaries, and
 * seeded random messages of random lengths, including a view into a larger buffer.
 */
import { createHash } from 'node:crypto';
import { describe, expect, it } from 'vitest';
import { md5Hex } from '../../../src/core/math/md5';
import { seededRandom } from '../../../src/core/math/seededRandom';

const nodeMd5 = (bytes: Uint8Array) => createHash('md5').update(bytes).digest('hex');
const ascii = (text: string) => Uint8Array.from(text, (c) => c.charCodeAt(0));

function randomBytes(rand: () => number, length: number): Uint8Array {
  const words = new Uint32Array(Math.ceil(length / 4));
  for (let k = 0; k < words.length; k++) words[k] = rand() * 2 ** 32;
  return new Uint8Array(words.buffer, 0, length);
}

describe('md5Hex', () => {
  it("gives RFC 1321's test suite (A.5)", () => {
    const suite: [string, string][] = [
      ['', 'd41d8cd98f00b204e9800998ecf8427e'],
      ['a', '0cc175b9c0f1b6a831c399e269772661'],
      ['abc', '900150983cd24fb0d6963f7d28e17f72'],
      ['message digest', 'f96b697d7cb7938d525a2f31aaf161d0'],
      ['abcdefghijklmnopqrstuvwxyz', 'c3fcd3d76192e4007dfb496cca67e13b'],
      ['ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789', 'd174ab98d277d9f5a5611c2c9f419d9f'],
      ['1234567890'.repeat(8), '57edf4a22be3c955ac49da2e2107b67a'],
    ];
    for (const [text, digest] of suite) expect(md5Hex(ascii(text)), text).toBe(digest);
  });

  it('seed 29001: agrees with node:crypto at every length 0..200 (one, two and three padded blocks)', () => {
    const rand = seededRandom(29001);
    for (let length = 0; length <= 200; length++) {
      const bytes = randomBytes(rand, length);
      expect(md5Hex(bytes), `length ${length}`).toBe(nodeMd5(bytes));
    }
  });

  it('seed 29002: agrees with node:crypto on 300 random messages of random lengths up to 40 kB, and on views', () => {
    const rand = seededRandom(29002);
    for (let n = 0; n < 300; n++) {
      const length = Math.floor(rand() ** 3 * 40_000);
      const bytes = randomBytes(rand, length);
      expect(md5Hex(bytes), `message ${n}, length ${length}`).toBe(nodeMd5(bytes));
      // The same bytes as a view at an odd offset into a larger buffer (as a subarray of a file).
      const start = 1 + Math.floor(rand() * 13);
      const larger = new Uint8Array(length + start + 7);
      larger.set(bytes, start);
      expect(md5Hex(larger.subarray(start, start + length)), `view of message ${n}`).toBe(nodeMd5(bytes));
    }
  });

  it('seed 29003: agrees with node:crypto on a 8 MB message (a 1024 x 1024 float64 height map)', () => {
    const rand = seededRandom(29003);
    const bytes = randomBytes(rand, 8 << 20);
    expect(md5Hex(bytes)).toBe(nodeMd5(bytes));
  });
});
