/**
 * The words of the three-axis and doubly curved charts, pure (no DOM; tested in Node): the
 * sentence saying where raster and waterline cross, a signed radius in words, and the notes on
 * the radii without an L. Lengths in the user's unit; never NaN, Infinity or -0.
 */
import { formatSignificant, fromMm, unitSymbol } from '../../core/input/units';
import type { RadiusGap, RadiusSweepData, SlopeChartData } from '../../worker/teachProtocol';
import { formatDeg, formatLenUnit } from '../format';
import type { Unit } from '../state';

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
 * do not cross. Lengths in the user's unit.
 */
export function crossingSentence(d: SlopeChartData, unit: Unit): string {
  const raster = `raster at psi = ${deg(d.crossingRasterAngleDeg)}`;
  const h = formatLenUnit(d.hMm, unit, 'height');
  const where = d.onRevolution ? ' (on a plane of that slope)' : '';
  if (d.crossingDeg === null)
    return `Waterline and ${raster} do not cross for a scallop of ${h}${where}: ${raster} programs the larger step at every slope where both are valid.`;
  const step =
    d.crossingStepMm === null ? '' : ` (both ${formatLenUnit(d.crossingStepMm, unit)} at ${deg(d.crossingDeg)})`;
  return `Above ${deg(d.crossingDeg)} waterline programs a larger step than ${raster} for the same scallop of ${h}, below it ${raster} does${step}${where}.`;
}

/** A signed radius in words: "convex 40 mm", "concave 20 mm", "straight". */
export function radiusWords(radiusMm: number, unit: Unit): string {
  if (!Number.isFinite(radiusMm)) return 'straight';
  const r = formatSignificant(fromMm(Math.abs(radiusMm), unit), { digits: 6, trimZeros: true });
  return `${radiusMm > 0 ? 'convex' : 'concave'} ${r} ${unitSymbol(unit)}`;
}

/** One sentence per gap: which radii of which side have no L, and why (radii in the user's unit). */
export function radiusGapNotes(s: RadiusSweepData, unit: Unit): string[] {
  const { self, other } = radiusNames(s.which);
  const held = `${other} held ${radiusWords(s.heldMm, unit)}`;
  const r = (mm: number) =>
    `${formatSignificant(fromMm(mm, unit), { digits: 3, trimZeros: true })} ${unitSymbol(unit)}`;
  return s.gaps.map((g: RadiusGap) => {
    const range =
      g.fromMm === g.toMm
        ? `at about |${self}| = ${r(g.fromMm)}`
        : `for |${self}| from about ${r(g.fromMm)} to ${r(g.toMm)}`;
    const why =
      g.reason === 'gouging'
        ? 'the tool gouges the surface at this posture'
        : 'h is at or above the flank or shank limit there';
    return `No ${g.side} L ${range} (${held}): ${why}.`;
  });
}

/** Why a constant step leaves no cusp, by the core's code (core/threeAxis/errors.ts). */
const REFUSAL_WORDS: Readonly<Record<string, string>> = {
  'beyond-step': 'passes that far apart leave a wall, not a scallop',
  'shank-cuts': "the tool's shank, not its corner, would form the cusp",
  'flank-wall': 'the flank rises to a wall before the passes meet',
  'wall-only': 'the side rises straight from the contact: no scallop at any step',
  'past-surface': 'the next pass would lie past the usable surface',
  'needs-slope': 'on a flat floor a step-down means nothing',
  gouging: 'the tool would gouge the surface',
};

/** One sentence per run of slopes where the constant step leaves no cusp, and why. */
export function refusalNotes(d: SlopeChartData, unit: Unit): string[] {
  const step = `${d.passes === 'raster' ? 'Lxy' : 'dz'} = ${formatLenUnit(d.constantStepMm, unit)}`;
  return d.constantStepRefusals.map((r) => {
    const range =
      r.fromDeg === r.toDeg ? `at about ${deg(r.fromDeg)}` : `from about ${deg(r.fromDeg)} to ${deg(r.toDeg)}`;
    return `No scallop for the constant ${step} ${range}: ${REFUSAL_WORDS[r.code] ?? 'the solver refuses it'}.`;
  });
}
