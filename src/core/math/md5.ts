/**
 * MD5 (RFC 1321) of a byte array, as lower-case hexadecimal: the checksum an x3p file
 * (ISO 25178-72) stores for its main.xml and its binary data. Not for security. Pure: works in
 * the browser and in Node alike (no Web Crypto, which has no MD5, and no node:crypto).
 */

/** The per-step left rotations of the four rounds (RFC 1321, 3.4). */
const SHIFTS = [7, 12, 17, 22, 5, 9, 14, 20, 4, 11, 16, 23, 6, 10, 15, 21];

/** The sine table: K[i] = floor(2^32 |sin(i + 1)|) (RFC 1321, 3.4), written out rather than computed with Math.sin. */
const K = new Uint32Array([
  0xd76aa478, 0xe8c7b756, 0x242070db, 0xc1bdceee, 0xf57c0faf, 0x4787c62a, 0xa8304613, 0xfd469501, 0x698098d8,
  0x8b44f7af, 0xffff5bb1, 0x895cd7be, 0x6b901122, 0xfd987193, 0xa679438e, 0x49b40821, 0xf61e2562, 0xc040b340,
  0x265e5a51, 0xe9b6c7aa, 0xd62f105d, 0x02441453, 0xd8a1e681, 0xe7d3fbc8, 0x21e1cde6, 0xc33707d6, 0xf4d50d87,
  0x455a14ed, 0xa9e3e905, 0xfcefa3f8, 0x676f02d9, 0x8d2a4c8a, 0xfffa3942, 0x8771f681, 0x6d9d6122, 0xfde5380c,
  0xa4beea44, 0x4bdecfa9, 0xf6bb4b60, 0xbebfbc70, 0x289b7ec6, 0xeaa127fa, 0xd4ef3085, 0x04881d05, 0xd9d4d039,
  0xe6db99e5, 0x1fa27cf8, 0xc4ac5665, 0xf4292244, 0x432aff97, 0xab9423a7, 0xfc93a039, 0x655b59c3, 0x8f0ccc92,
  0xffeff47d, 0x85845dd1, 0x6fa87e4f, 0xfe2ce6e0, 0xa3014314, 0x4e0811a1, 0xf7537e82, 0xbd3af235, 0x2ad7d2bb,
  0xeb86d391,
]);

/**
 * The MD5 digest of `bytes`.
 *
 * @param bytes the message (any length, 0 included).
 * @returns the 16-byte digest as 32 lower-case hexadecimal digits.
 */
export function md5Hex(bytes: Uint8Array): string {
  const length = bytes.length;
  // The message, a 0x80 byte, zeros up to 56 mod 64, then the bit length (64 bits, little-endian).
  const paddedLength = (((length + 8) >>> 6) + 1) << 6;
  const tail = new Uint8Array(paddedLength - (length & ~63));
  tail.set(bytes.subarray(length & ~63));
  tail[length & 63] = 0x80;
  const tailView = new DataView(tail.buffer);
  tailView.setUint32(tail.length - 8, (length * 8) >>> 0, true);
  tailView.setUint32(tail.length - 4, Math.floor(length / 2 ** 29), true);

  const state = new Uint32Array([0x67452301, 0xefcdab89, 0x98badcfe, 0x10325476]);
  const words = new Uint32Array(16);
  const fullBlocks = length >>> 6;
  const bytesView = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  for (let block = 0; block < fullBlocks; block++) {
    for (let w = 0; w < 16; w++) words[w] = bytesView.getUint32(block * 64 + w * 4, true);
    compress(state, words);
  }
  for (let offset = 0; offset < tail.length; offset += 64) {
    for (let w = 0; w < 16; w++) words[w] = tailView.getUint32(offset + w * 4, true);
    compress(state, words);
  }
  let hex = '';
  for (const word of state)
    for (let byte = 0; byte < 4; byte++) hex += ((word >>> (8 * byte)) & 0xff).toString(16).padStart(2, '0');
  return hex;
}

/** One 64-byte block into the state (RFC 1321, 3.4), in place. */
function compress(state: Uint32Array, words: Uint32Array): void {
  let a = state[0] as number;
  let b = state[1] as number;
  let c = state[2] as number;
  let d = state[3] as number;
  for (let i = 0; i < 64; i++) {
    const round = i >>> 4;
    let f: number;
    let g: number;
    if (round === 0) {
      f = (b & c) | (~b & d);
      g = i;
    } else if (round === 1) {
      f = (d & b) | (~d & c);
      g = (5 * i + 1) & 15;
    } else if (round === 2) {
      f = b ^ c ^ d;
      g = (3 * i + 5) & 15;
    } else {
      f = c ^ (b | ~d);
      g = (7 * i) & 15;
    }
    const sum = (a + f + (K[i] as number) + (words[g] as number)) | 0;
    const shift = SHIFTS[(round << 2) | (i & 3)] as number;
    a = d;
    d = c;
    c = b;
    b = (b + ((sum << shift) | (sum >>> (32 - shift)))) | 0;
  }
  state[0] = ((state[0] as number) + a) | 0;
  state[1] = ((state[1] as number) + b) | 0;
  state[2] = ((state[2] as number) + c) | 0;
  state[3] = ((state[3] as number) + d) | 0;
}
