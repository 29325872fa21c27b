/**
 * The arithmetic of the comparison charts, with no DOM: "nice" 1-2-5 ticks, linear and log
 * scales from data to pixels, tick labels without float noise, and SVG path data that breaks
 * where a value is missing. Pure; tested in Node.
 */

/** A map from data values to pixels, with the ticks to draw along it. */
export interface Scale {
  /** Data range shown (min < max). */
  readonly min: number;
  readonly max: number;
  readonly log: boolean;
  /** Pixel of a data value (linear or log in the value; pixels may run either way). */
  toPixel(value: number): number;
  /** Tick values inside [min, max], ascending. */
  readonly ticks: readonly number[];
  /** The tick step (linear) or the smallest decade (log): decides the decimals of the labels. */
  readonly step: number;
}

/**
 * The 1-2-5 step near `span / count`: 1, 2 or 5 times a power of ten.
 * @param span data span (> 0); @param count wanted number of intervals (>= 1).
 */
export function niceStep(span: number, count: number): number {
  const raw = span / Math.max(1, count);
  const decade = 10 ** Math.floor(Math.log10(raw));
  const f = raw / decade;
  return (f < 1.5 ? 1 : f < 3.5 ? 2 : f < 7.5 ? 5 : 10) * decade;
}

/** Multiples of `step` within [min, max] (a small tolerance keeps the ends), ascending. */
export function ticksWithin(min: number, max: number, step: number): number[] {
  const out: number[] = [];
  const eps = step * 1e-9;
  for (let k = Math.ceil((min - eps) / step); k * step <= max + eps; k++) out.push(roundToStep(k * step, step));
  return out;
}

/** A value on a step's grid without float noise (0.30000000000000004 becomes 0.3). */
function roundToStep(value: number, step: number): number {
  const decimals = Math.max(0, -Math.floor(Math.log10(step)) + 1);
  return Number(value.toFixed(Math.min(20, decimals)));
}

/**
 * A data range widened to whole 1-2-5 steps, so the first tick is at or below `min` and the
 * last at or above `max`. A single value (or none) gets a range around it.
 */
export function coverRange(min: number, max: number, count: number): { min: number; max: number; step: number } {
  let lo = min;
  let hi = max;
  if (!(Number.isFinite(lo) && Number.isFinite(hi))) {
    lo = 0;
    hi = 1;
  }
  if (hi - lo <= Math.abs(hi) * 1e-12) {
    const pad = Math.abs(hi) > 0 ? Math.abs(hi) * 0.1 : 1;
    lo -= pad;
    hi += pad;
  }
  const step = niceStep(hi - lo, count);
  return {
    min: roundToStep(Math.floor(lo / step + 1e-9) * step, step),
    max: roundToStep(Math.ceil(hi / step - 1e-9) * step, step),
    step,
  };
}

/**
 * A linear scale over [min, max] to [pixelAtMin, pixelAtMax] with about `count` tick intervals.
 * @param cover widen the range to whole steps (value axes); otherwise keep it exactly (angle axes).
 */
export function linearScale(
  min: number,
  max: number,
  pixelAtMin: number,
  pixelAtMax: number,
  count: number,
  cover: boolean,
): Scale {
  const r = cover ? coverRange(min, max, count) : { min, max, step: niceStep(max - min, count) };
  const span = r.max - r.min;
  return {
    min: r.min,
    max: r.max,
    log: false,
    step: r.step,
    ticks: ticksWithin(r.min, r.max, r.step),
    toPixel: (v) => pixelAtMin + ((v - r.min) / span) * (pixelAtMax - pixelAtMin),
  };
}

/**
 * A log scale over [min, max] (both > 0), ticks at 1, 2 and 5 times each power of ten inside
 * it (only the powers of ten when the range spans more than 3 decades).
 */
export function logScale(min: number, max: number, pixelAtMin: number, pixelAtMax: number): Scale {
  const lmin = Math.log10(min);
  const span = Math.log10(max) - lmin;
  const mantissas = span > 3 ? [1] : [1, 2, 5];
  const ticks: number[] = [];
  const first = Math.floor(lmin);
  for (let e = first; e <= Math.ceil(Math.log10(max)); e++) {
    for (const m of mantissas) {
      const v = Number((m * 10 ** e).toPrecision(6));
      if (v >= min * (1 - 1e-12) && v <= max * (1 + 1e-12)) ticks.push(v);
    }
  }
  return {
    min,
    max,
    log: true,
    step: 10 ** first,
    ticks,
    toPixel: (v) => pixelAtMin + ((Math.log10(v) - lmin) / span) * (pixelAtMax - pixelAtMin),
  };
}

/** A tick label: the value with the decimals its step needs (log: its own), never "-0". */
export function tickLabel(value: number, scale: Scale): string {
  if (value === 0) return '0';
  const step = scale.log ? value : scale.step;
  const decimals = Math.max(0, Math.min(12, -Math.floor(Math.log10(step) + 1e-9)));
  const text = value.toFixed(decimals);
  return /^-0(\.0*)?$/.test(text) ? '0' : text;
}

/**
 * SVG path data through the points (x[i], y[i]) in pixels: one "M" then "L"s, and a new "M"
 * after each missing value (null or not finite), so a gap in the data is a gap in the line.
 */
export function linePath(
  xs: readonly number[],
  ys: ReadonlyArray<number | null>,
  x: (v: number) => number,
  y: (v: number) => number,
): string {
  let d = '';
  let pen = false;
  for (let i = 0; i < xs.length; i++) {
    const v = ys[i];
    const xv = xs[i];
    if (v === null || v === undefined || xv === undefined || !Number.isFinite(v)) {
      pen = false;
      continue;
    }
    d += `${pen ? 'L' : 'M'}${x(xv).toFixed(1)} ${y(v).toFixed(1)}`;
    pen = true;
  }
  return d;
}

/** Smallest and largest finite value over every series (Infinity, -Infinity when there is none). */
export function extent(series: ReadonlyArray<ReadonlyArray<number | null>>): { min: number; max: number } {
  let min = Number.POSITIVE_INFINITY;
  let max = Number.NEGATIVE_INFINITY;
  for (const s of series) {
    for (const v of s) {
      if (v === null || !Number.isFinite(v)) continue;
      if (v < min) min = v;
      if (v > max) max = v;
    }
  }
  return { min, max };
}
