/**
 * Stratified cases for the brute-force checks of the doubly curved point's exact answer (issue 19;
 * the registry's model, surfaces/doublyCurvedPoint.ts, which answers a straight radius by the
 * cylinder's or the plane's model): every family
 * of sign combinations (dome ++, bowl --, saddles +- and -+, convex and concave spheres, the two
 * cylinders both ways, the plane), ball, flat and bull-nose ends, with and without tilt, both
 * patterns, from a seed. Concave radii are drawn wide enough not to gouge (doublyCurvedGouges).
 */

import type { PassPattern, ToolInput } from '../../../../src/core/input/validate';
import { doublyCurvedGouges } from '../../../../src/core/surfaces/doublyCurved/gouging';
import { curvedForward, curvedLimits, curvedPoint } from '../../../../src/core/surfaces/doublyCurvedPoint';
import { seededRandom } from '../../../support/bruteForce';
import { bruteForceDoublyCurved } from '../../../support/reference/doublyCurvedBruteForce';
import { polishDoublyCurvedCusp } from '../../../support/reference/doublyCurvedPolished';

export const FAMILIES = [
  'dome',
  'bowl',
  'saddle+-',
  'saddle-+',
  'sphere+',
  'sphere-',
  'cylinder-along',
  'cylinder-across',
  'plane',
] as const;
export type Family = (typeof FAMILIES)[number];
export const TOOLS = ['ball', 'flat', 'bull-nose'] as const;

export interface BruteCase {
  readonly name: string;
  readonly family: Family;
  readonly tool: ToolInput;
  readonly pattern: PassPattern;
  readonly rf: number;
  readonly rc: number;
  readonly h: number;
}

const I = Number.POSITIVE_INFINITY;

function radii(family: Family, R: number, rand: () => number): [number, number] {
  const m = () => R * (6 + 30 * rand());
  switch (family) {
    case 'dome':
      return [m(), m()];
    case 'bowl':
      return [-m(), -m()];
    case 'saddle+-':
      return [m(), -m()];
    case 'saddle-+':
      return [-m(), m()];
    case 'sphere+': {
      const r = m();
      return [r, r];
    }
    case 'sphere-': {
      const r = m();
      return [-r, -r];
    }
    case 'cylinder-along':
      return [I, (rand() < 0.5 ? 1 : -1) * m()];
    case 'cylinder-across':
      return [(rand() < 0.5 ? 1 : -1) * m(), I];
    case 'plane':
      return [I, I];
  }
}

/** The stratum of case i: family, tool, tilt, pattern. */
interface Stratum {
  readonly family: Family;
  readonly kind: (typeof TOOLS)[number];
  readonly tilted: boolean;
  readonly pattern: PassPattern;
  /** No lead: a flat bottom then meets a convex feed circle inside its chords (the foot of l). */
  readonly leadless: boolean;
}

/** `count` cases from a seed, cycling the families, tools, tilt and patterns so that each stratum appears. */
export function bruteCases(seed: number, count: number, offset = 0): BruteCase[] {
  return casesOf(seed, count, offset, (i) => ({
    family: FAMILIES[i % FAMILIES.length] as Family,
    kind: TOOLS[i % TOOLS.length] as (typeof TOOLS)[number],
    tilted: Math.floor(i / 3) % 2 === 1,
    pattern: Math.floor(i / 2) % 2 === 0 ? 'one-way' : 'zigzag',
    // Cases 2, 8, 14, ... (bull-nose on a saddle +-, the plane, a convex sphere).
    leadless: i % 6 === 2,
  }));
}

/**
 * `count` cases from a seed crossing every family with every tool (case i: family i mod 9, tool
 * floor(i / 9) mod 3), tilt alternating and the pattern every second case; no lead for the ball on
 * the saddle +- and the ball and the bull-nose on the plane (the other leadless tools there gouge or
 * leave no scallop, and the case would be skipped).
 */
export function crossCases(seed: number, count: number, offset = 0): BruteCase[] {
  return casesOf(seed, count, offset, (i) => ({
    family: FAMILIES[i % FAMILIES.length] as Family,
    kind: TOOLS[Math.floor(i / FAMILIES.length) % TOOLS.length] as (typeof TOOLS)[number],
    tilted: i % 2 === 1,
    pattern: Math.floor(i / 2) % 2 === 0 ? 'one-way' : 'zigzag',
    leadless: (i % 9 === 2 && i < 9) || (i % 9 === 8 && i < 27 && Math.floor(i / 9) !== 1),
  }));
}

function casesOf(seed: number, count: number, offset: number, stratum: (i: number) => Stratum): BruteCase[] {
  const rand = seededRandom(seed);
  const out: BruteCase[] = [];
  for (let i = offset; out.length < count; i++) {
    const { family, kind, tilted, pattern, leadless } = stratum(i);
    for (let attempt = 0; attempt < 50; attempt++) {
      const R = 1 + 3 * rand();
      const Rcr = kind === 'ball' ? R : kind === 'flat' ? 0 : R * (0.15 + 0.7 * rand());
      const tool: ToolInput = {
        toolRadiusMm: R,
        cornerRadiusMm: Rcr,
        leadAngleDeg: leadless ? 0 : 3 + 30 * rand(),
        tiltAngleDeg: tilted ? (rand() < 0.5 ? 1 : -1) * (5 + 30 * rand()) : 0,
      };
      const [rf, rc] = radii(family, R, rand);
      if (doublyCurvedGouges(tool, { feedRadiusMm: rf, crossRadiusMm: rc })) continue;
      const limit = curvedLimits(curvedPoint(tool, { feedRadiusMm: rf, crossRadiusMm: rc }, pattern)).limitMm;
      if (!(limit > 1e-3)) continue;
      const h = Math.min(0.1 * R, limit * (0.05 + 0.5 * rand()));
      const name = `${family}, ${kind}, ${tilted ? 'tilt' : 'no tilt'}, ${pattern} (seed ${seed} #${i}: R ${R.toFixed(4)} Rcr ${Rcr.toFixed(4)} rho ${tool.leadAngleDeg.toFixed(3)} tilt ${tool.tiltAngleDeg.toFixed(3)} Rf ${rf.toFixed(3)} Rc ${rc.toFixed(3)} h ${h.toFixed(5)})`;
      out.push({ name, family, tool, pattern, rf, rc, h });
      break;
    }
  }
  return out;
}

/** The tool's kind from its radii. */
export function toolKind(c: BruteCase): (typeof TOOLS)[number] {
  if (c.tool.cornerRadiusMm === c.tool.toolRadiusMm) return 'ball';
  return c.tool.cornerRadiusMm === 0 ? 'flat' : 'bull-nose';
}

/** Keeps the largest error (mm) per stratum of the case: family, tool, tilt, pattern. */
export function recordWorst(worst: Map<string, number>, c: BruteCase, errorMm: number): void {
  for (const key of [
    `family ${c.family}`,
    `tool ${toolKind(c)}`,
    c.tool.tiltAngleDeg === 0 ? 'no tilt' : 'tilt',
    `pattern ${c.pattern}`,
  ])
    worst.set(key, Math.max(worst.get(key) ?? 0, errorMm));
}

/** The table of largest errors, one stratum a line, families first. */
export function worstTable(title: string, worst: Map<string, number>): string {
  const rows = [...worst].sort(([a], [b]) => a.localeCompare(b));
  return `${title}\n${rows.map(([k, v]) => `  ${k.padEnd(26)} ${v.toExponential(2)} mm`).join('\n')}`;
}

/**
 * The solver's cusps against the brute force's: between pass 0 and pass 1, and for zigzag also the
 * other cusp (pass 0 and 1 meet with two right flanks; the same passes of the tool mirrored in Y meet
 * with the original's two left flanks). With `polish`, also the polished cusp (doublyCurvedPolished.ts,
 * started from this brute force's winning samples); NaN without.
 */
export function compare(
  c: BruteCase,
  levels: number,
  polish = false,
): Array<{ exactMm: number; bruteMm: number; boundMm: number; polishedMm: number }> {
  const f = curvedForward(curvedPoint(c.tool, { feedRadiusMm: c.rf, crossRadiusMm: c.rc }, c.pattern), c.h);
  const other = f.otherCuspHeightMm as number;
  // Zigzag: the narrower flank's cusp is at h, the wider one's at the other (lower) height.
  const cusps: Array<[number, number]> =
    c.pattern === 'zigzag'
      ? [
          [c.tool.tiltAngleDeg, f.halfWidthRightMm > f.halfWidthLeftMm ? other : c.h],
          [-c.tool.tiltAngleDeg, f.halfWidthLeftMm > f.halfWidthRightMm ? other : c.h],
        ]
      : [[c.tool.tiltAngleDeg, c.h]];
  return cusps.map(([tilt, exactMm]) => {
    const tool = { R: c.tool.toolRadiusMm, Rcr: c.tool.cornerRadiusMm, leadDeg: c.tool.leadAngleDeg, tiltDeg: tilt };
    const b = bruteForceDoublyCurved(tool, c.pattern, c.rf, c.rc, f.intervalMm, {
      spacingMm: c.tool.toolRadiusMm / 60,
      levels,
    });
    const polishedMm = polish
      ? polishDoublyCurvedCusp(tool, c.pattern, c.rf, c.rc, f.intervalMm, b).polishedMm
      : Number.NaN;
    return { exactMm, bruteMm: b.cuspHeightMm, boundMm: b.boundMm, polishedMm };
  });
}
