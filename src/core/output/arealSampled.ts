/**
 * The ISO 25178-2 height parameters of a sampled height map, as a metrology program computes them
 * from an x3p file: every sample weighs the same, the reference is the samples' own mean (no
 * levelling, no form removal, no S- or L-filter). On the notes' grid over whole cells (sample `i`
 * at `(i + 1/2) dx`) these are the midpoint-rule estimates of the integral definitions in
 * `surface-finish.md`. Pure; heights and results in mm (Ssk and Sku have no unit).
 */

/** The height parameters of a set of samples. */
export interface ArealSampled {
  /** Number of samples. */
  count: number;
  /** The samples' mean height `m` (mm), the reference of the others. */
  meanMm: number;
  /** Mean of `|s - m|` (mm). */
  saMm: number;
  /** Root mean square of `s - m` (mm). */
  sqMm: number;
  /** Highest sample minus `m` (mm). */
  spMm: number;
  /** `m` minus the lowest sample (mm). */
  svMm: number;
  /** `Sp + Sv`: highest minus lowest sample (mm). */
  szMm: number;
  /** Mean of `(s - m)^3` over `Sq^3`; undefined when `Sq = 0` (a flat surface has no skewness). */
  ssk: number | undefined;
  /** Mean of `(s - m)^4` over `Sq^4`; undefined when `Sq = 0`. */
  sku: number | undefined;
}

/**
 * Sa, Sq, Sp, Sv, Sz, Ssk, Sku of the samples `heightsMm` (any order: the grid does not matter).
 * The mean is a compensated sum corrected by a second pass, so the reference is the samples' mean
 * to about one rounding; the sums of powers are compensated too.
 *
 * @param heightsMm the heights (mm), at least one, all finite.
 * @returns the parameters; a one-line RangeError for an empty set or a non-finite height.
 */
export function arealSampled(heightsMm: ArrayLike<number>): ArealSampled {
  const count = heightsMm.length;
  if (count < 1) throw new RangeError('areal parameters: need at least one height sample (got 0)');
  const first = new CompensatedSum();
  let minMm = Number.POSITIVE_INFINITY;
  let maxMm = Number.NEGATIVE_INFINITY;
  for (let k = 0; k < count; k++) {
    const h = heightsMm[k] as number;
    if (!Number.isFinite(h)) throw new RangeError(`areal parameters: every height must be finite (index ${k} is ${h})`);
    first.add(h);
    if (h < minMm) minMm = h;
    if (h > maxMm) maxMm = h;
  }
  const roughMean = first.value() / count;
  const residual = new CompensatedSum();
  for (let k = 0; k < count; k++) residual.add((heightsMm[k] as number) - roughMean);
  const meanMm = roughMean + residual.value() / count;
  const abs = new CompensatedSum();
  const square = new CompensatedSum();
  const cube = new CompensatedSum();
  const fourth = new CompensatedSum();
  for (let k = 0; k < count; k++) {
    const d = (heightsMm[k] as number) - meanMm;
    const d2 = d * d;
    abs.add(Math.abs(d));
    square.add(d2);
    cube.add(d2 * d);
    fourth.add(d2 * d2);
  }
  const sqMm = Math.sqrt(square.value() / count);
  const spMm = maxMm - meanMm;
  const svMm = meanMm - minMm;
  return {
    count,
    meanMm,
    saMm: abs.value() / count,
    sqMm,
    spMm,
    svMm,
    szMm: maxMm - minMm,
    ssk: sqMm > 0 ? cube.value() / count / sqMm ** 3 : undefined,
    sku: sqMm > 0 ? fourth.value() / count / sqMm ** 4 : undefined,
  };
}

/** Neumaier's compensated summation. */
class CompensatedSum {
  private sum = 0;
  private compensation = 0;

  add(x: number): void {
    const t = this.sum + x;
    this.compensation += Math.abs(this.sum) >= Math.abs(x) ? this.sum - t + x : x - t + this.sum;
    this.sum = t;
  }

  value(): number {
    return this.sum + this.compensation;
  }
}
