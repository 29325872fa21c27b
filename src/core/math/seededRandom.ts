/** A small seeded pseudo-random generator, so that random cases (tests, benches, the reference set) replay from their seed. */

/**
 * mulberry32: numbers in [0, 1), the same sequence for the same seed.
 *
 * @param seed any integer (taken as an unsigned 32-bit one).
 * @returns the generator; each call gives the next number.
 */
export function seededRandom(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}
