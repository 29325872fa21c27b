/**
 * The words of the three-axis and doubly curved charts, pure (no DOM; tested in Node): the
 * sentence saying where raster and waterline cross, a signed radius in words, and the notes on
 * the radii without an L. Lengths in the user's unit; never NaN, Infinity or -0.
 */
import { formatSignificant, fromMm, unitSymbol } from '../../core/input/units';
import type { RadiusGap, RadiusSweepData, SlopeChartData } from '../../worker/teachProtocol';
import { formatDeg, formatLenUnit } from '../format';
import type { RadiusWords, SlopeWords } from '../i18n/catalogue';
import type { Unit } from '../state';
import { EN_RADIUS } from './radiusWords';
import { EN_SLOPE } from './slopeWords';

/** Degrees in words: 38.2° (three significant digits, never -0). */
export function deg(d: number): string {
  return `${formatDeg(Number(d.toPrecision(3)) + 0)}°`;
}

/** The radius's name and the other's. */
export function radiusNames(which: RadiusSweepData['which']): { self: string; other: string } {
  return which === 'feed' ? { self: 'Rf', other: 'Rc' } : { self: 'Rc', other: 'Rf' };
}

/**
 * One sentence: where raster (at the compared raster angle) and waterline program the same step
 * for the charted scallop h, and which programs the larger above and below; or, plainly, that they
 * do not cross. Lengths in the user's unit; in `words`' language.
 */
export function crossingSentence(d: SlopeChartData, unit: Unit, words: SlopeWords = EN_SLOPE): string {
  const h = formatLenUnit(d.hMm, unit, 'height');
  return words.crossing(
    d.crossingDeg === null ? null : deg(d.crossingDeg),
    deg(d.crossingRasterAngleDeg),
    h,
    d.crossingDeg === null || d.crossingStepMm === null ? null : formatLenUnit(d.crossingStepMm, unit),
    d.onRevolution,
  );
}

/** A signed radius in words: "convex 40 mm", "concave 20 mm", "straight" (in `words`' language). */
export function radiusWords(radiusMm: number, unit: Unit, words: RadiusWords = EN_RADIUS): string {
  if (!Number.isFinite(radiusMm)) return words.radius('straight', '');
  const r = formatSignificant(fromMm(Math.abs(radiusMm), unit), { digits: 6, trimZeros: true });
  return words.radius(radiusMm > 0 ? 'convex' : 'concave', `${r} ${unitSymbol(unit)}`);
}

/** One sentence per gap: which radii of which side have no L, and why (radii in the user's unit; in `words`' language). */
export function radiusGapNotes(s: RadiusSweepData, unit: Unit, words: RadiusWords = EN_RADIUS): string[] {
  const { self, other } = radiusNames(s.which);
  const held = radiusWords(s.heldMm, unit, words);
  const r = (mm: number) =>
    `${formatSignificant(fromMm(mm, unit), { digits: 3, trimZeros: true })} ${unitSymbol(unit)}`;
  return s.gaps.map((g: RadiusGap) =>
    words.gap(
      g.side,
      self,
      r(g.fromMm),
      g.fromMm === g.toMm ? null : r(g.toMm),
      other,
      held,
      g.reason === 'gouging' ? 'gouging' : 'limit',
    ),
  );
}

/** One sentence per run of slopes where the constant step leaves no cusp, and why (in `words`' language). */
export function refusalNotes(d: SlopeChartData, unit: Unit, words: SlopeWords = EN_SLOPE): string[] {
  const step = `${d.passes === 'raster' ? 'Lxy' : 'dz'} = ${formatLenUnit(d.constantStepMm, unit)}`;
  return d.constantStepRefusals.map((r) =>
    words.refusal(step, deg(r.fromDeg), r.fromDeg === r.toDeg ? null : deg(r.toDeg), r.code),
  );
}
