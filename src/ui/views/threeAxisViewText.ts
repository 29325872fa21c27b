/**
 * What the teaching views say in three-axis mode (issue 28 point 2), pure (no DOM; tested in
 * Node): the tab names that follow what each view draws, the neutral one-line statements of what a
 * view shows (the plane at the equivalent posture, or why nothing), and the formulas that take the
 * slope and raster angle to that posture (core threeAxis/slopePosture.ts, its numbers substituted).
 */
import type { FIELDS } from '../../core/input/fields';
import { slopePosture } from '../../core/threeAxis/slopePosture';
import type { ThreeAxisTeachReply } from '../../worker/teachProtocol';
import { formatAngle, formatDeg } from '../format';
import type { ViewNoteWords } from '../i18n/catalogue';
import { EN_VIEW_NOTES } from './viewNoteWords';

type ThreeAxisOk = Extract<ThreeAxisTeachReply, { ok: true }>;
/** A view's id (common.ts ViewId; not imported from there: this module is pure, tested without a DOM). */
type ViewId = Exclude<(typeof FIELDS.view.values)[number], 'result'>;
/** The kinds of page question (common.ts PageKind), null for a plane's or a cylinder's. */
type PageKind = 'curved' | 'three-axis';

/** The chart tab's name for what it draws: the five-axis sweeps, the slope sweep, the radius sweeps. */
export function chartTitle(kind: PageKind | null): string {
  return kind === 'three-axis'
    ? 'Step against slope'
    : kind === 'curved'
      ? 'L against each radius'
      : 'L against lead and tilt';
}

/** The raster angle of raster passes, degrees; null for waterline passes (on a plane or a surface of revolution). */
function rasterAngleOf(d: ThreeAxisOk): number | null {
  const i = d.request.input;
  return i.surface === 'plane' && i.case.passes === 'raster' ? i.case.rasterAngleDeg : null;
}

/**
 * The neutral line over a view that draws the sloped plane as the plane at the equivalent posture
 * (the profile, the step-through, the formulas), or over one that draws nothing for this question
 * (waterline on a surface of revolution); null for a view that draws the three-axis question itself
 * (the chart). In `words`' language.
 */
export function threeAxisViewNote(view: ViewId, d: ThreeAxisOk, words: ViewNoteWords = EN_VIEW_NOTES): string | null {
  if (view === 'chart') return null;
  if (view === 'tables') return words.tables;
  const psi = rasterAngleOf(d);
  const question = words.question(formatDeg(d.request.input.case.slopeDeg), psi === null ? null : formatDeg(psi));
  const plane = d.plane;
  if (plane === null) return words.revolution(question);
  // The angles' numbers (formatAngle's, its unit word left to the language).
  const angle = (deg: number) => formatAngle(deg).replace(/ deg$/, '');
  return words.equivalent(
    question,
    angle(plane.forward.leadAngleDeg),
    angle(plane.forward.tiltAngleDeg),
    view === 'surface',
  );
}

/** One line of the posture formulas: what it is, the formula, and its value. */
export interface PostureLine {
  readonly label: string;
  readonly formula: string;
  readonly value: string;
}

/**
 * The formulas that take the slope alpha and raster angle psi (90 for waterline) to the equivalent
 * lead and tilt, and the programmed step from L, with this question's numbers (slopePosture.ts).
 */
export function postureFormulaLines(d: ThreeAxisOk): PostureLine[] {
  const c = d.request.input.case;
  const raster = rasterAngleOf(d);
  const waterline = raster === null;
  const psi = raster ?? 90;
  const p = slopePosture(c.slopeDeg, psi);
  const D = p.horizontalStepPerInterval;
  const lines: PostureLine[] = [
    {
      label: 'Slope and raster angle',
      formula: 'alpha, psi (waterline: psi = 90)',
      value: `alpha = ${formatDeg(c.slopeDeg)}, psi = ${formatDeg(psi)}`,
    },
    { label: 'D', formula: 'D = sqrt(cos^2 psi + cos^2 alpha sin^2 psi)', value: `D = ${D.toFixed(6)}` },
    { label: 'Lead', formula: 'rho = atan2(sin alpha cos psi, cos alpha D)', value: `rho = ${formatAngle(p.leadDeg)}` },
    {
      label: 'Tilt',
      formula: 'beta = atan2(sin alpha cos alpha sin psi, sqrt(cos^2 psi + cos^4 alpha sin^2 psi))',
      value: `beta = ${formatAngle(p.tiltDeg)}`,
    },
  ];
  lines.push(
    waterline
      ? {
          label: 'Programmed step',
          formula: 'dz = L sin alpha',
          value: `dz / L = ${p.verticalStepPerInterval.toFixed(6)}`,
        }
      : { label: 'Programmed step', formula: 'Lxy = L D', value: `Lxy / L = ${D.toFixed(6)}` },
  );
  return lines;
}
