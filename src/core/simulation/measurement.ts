/**
 * The measurement of the simulation (simulation.ts): the cusps between the passes, refined between
 * rows, and the roughness of the trace through the rows over whole periods. Lengths mm.
 */
import type { PassPattern } from '../domain/tool';
import type { Field } from './passes';

/**
 * The cusp between contacts at y = lo and y = hi: the row maximum, refined by intersecting the
 * lines through the two rows on each side of it; also the trace's largest curvature around it.
 */
function refinedCusp(field: Field, lo: number, hi: number): { y: number; z: number; curvature: number } {
  const { rowMin, y0, dy } = field;
  let jm = -1;
  for (let j = 0; j < field.rows; j++) {
    const y = y0 + j * dy;
    if (y > lo && y < hi && (jm < 0 || (rowMin[j] as number) > (rowMin[jm] as number))) jm = j;
  }
  if (jm < 2 || jm > field.rows - 3) return { y: y0 + jm * dy, z: rowMin[jm] as number, curvature: 0 };
  const z = (j: number) => rowMin[j] as number;
  const line = (j: number) => ({ slope: (z(j + 1) - z(j)) / dy, y: y0 + j * dy, z: z(j) });
  const meet = (l1: ReturnType<typeof line>, l2: ReturnType<typeof line>) => {
    const y = l1.y + (l2.z - l1.z + l1.slope * (l1.y - l1.y) - l2.slope * (l2.y - l1.y)) / (l1.slope - l2.slope);
    return { y, z: l1.z + l1.slope * (y - l1.y) };
  };
  // The cusp lies between jm-1 and jm+1: on the rising side of jm or on the falling side.
  const candidates = [
    { left: line(jm - 1), right: line(jm + 1), from: jm, to: jm + 1 },
    { left: line(jm - 2), right: line(jm), from: jm - 1, to: jm },
  ];
  let best = { y: y0 + jm * dy, z: z(jm) };
  for (const c of candidates) {
    if (!(c.left.slope > 0 && c.right.slope < 0)) continue;
    const m = meet(c.left, c.right);
    if (m.y >= y0 + c.from * dy - 1e-12 && m.y <= y0 + c.to * dy + 1e-12 && m.z >= best.z) best = m;
  }
  const second = (j: number) => Math.abs(z(j + 1) - 2 * z(j) + z(j - 1)) / (dy * dy);
  const curvature = Math.max(second(Math.max(1, jm - 2)), second(Math.min(field.rows - 2, jm + 2)));
  return { ...best, curvature };
}

/** Measures cusps and roughness on the trace through the rows and the refined cusps. */
export function measure(
  field: Field,
  input: { readonly intervalMm: number; readonly pattern: PassPattern },
  passes: number,
) {
  const { rowMin, y0, dy } = field;
  const L = input.intervalMm;
  const cusps = [];
  for (let k = 0; k + 1 < passes; k++) cusps.push(refinedCusp(field, k * L, (k + 1) * L));
  // Whole periods from the first contact: one-way L, zigzag 2L.
  const period = input.pattern === 'zigzag' ? 2 * L : L;
  const periods = Math.max(1, Math.floor(((passes - 1) * L) / period + 1e-9));
  const end = periods * period;
  // The trace: rows inside [0, end], the refined cusps, and the ends interpolated.
  const pts: Array<[number, number]> = [];
  const at = (y: number) => {
    const f = (y - y0) / dy;
    const j = Math.min(field.rows - 2, Math.max(0, Math.floor(f)));
    const u = f - j;
    return (rowMin[j] as number) * (1 - u) + (rowMin[j + 1] as number) * u;
  };
  pts.push([0, at(0)]);
  for (let j = 0; j < field.rows; j++) {
    const y = y0 + j * dy;
    if (y > 0 && y < end) pts.push([y, rowMin[j] as number]);
  }
  for (const c of cusps) if (c.y > 0 && c.y < end) pts.push([c.y, c.z]);
  pts.push([end, at(end)]);
  pts.sort((p1, p2) => p1[0] - p2[0]);
  let area = 0;
  for (let i = 1; i < pts.length; i++) {
    const [ya, za] = pts[i - 1] as [number, number];
    const [yb, zb] = pts[i] as [number, number];
    area += 0.5 * (za + zb) * (yb - ya);
  }
  const mean = area / end;
  let abs = 0;
  let sq = 0;
  let lo = Number.POSITIVE_INFINITY;
  let hi = Number.NEGATIVE_INFINITY;
  for (let i = 1; i < pts.length; i++) {
    const [ya, za] = pts[i - 1] as [number, number];
    const [yb, zb] = pts[i] as [number, number];
    const w = yb - ya;
    const da = za - mean;
    const db = zb - mean;
    // Exact for a straight piece: |z - m| split where it crosses the mean line.
    if (da * db >= 0) abs += 0.5 * Math.abs(da + db) * w;
    else abs += (0.5 * (da * da + db * db) * w) / (Math.abs(da) + Math.abs(db));
    sq += ((da * da + da * db + db * db) / 3) * w;
    lo = Math.min(lo, za, zb);
    hi = Math.max(hi, za, zb);
  }
  let slope = 0;
  for (let j = 1; j < field.rows; j++) {
    const y = y0 + j * dy;
    if (y > 0 && y < end) slope = Math.max(slope, Math.abs((rowMin[j] as number) - (rowMin[j - 1] as number)) / dy);
  }
  return {
    cusps,
    roughness: { rzMm: hi - lo, raMm: abs / end, rqMm: Math.sqrt(sq / end), meanMm: mean },
    slope,
  };
}
