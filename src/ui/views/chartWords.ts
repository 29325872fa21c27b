/**
 * The five-axis comparison charts' words in English (issue 30): the charts as written, typed by the
 * catalogues' ChartWords so Japanese and German (i18n/jaChart.ts, deChart.ts) give every one.
 * Loaded with the teaching views, not with the first result.
 */
import { EXACT_NO_ANSWER } from '../../core/procedures/sweepGaps';
import type { ChartWords } from '../i18n/catalogue';

export const EN_CHART: ChartWords = {
  leadTitle: (u, rho) => `L [${u}] against lead rho [deg] (R, Rcr, beta, h fixed; dashed: current rho = ${rho})`,
  errorTitle: (u) => `Signed error of each approximation against exact, along the lead [${u}]`,
  tiltTitle: (u, beta) => `L [${u}] against tilt beta [deg] (R, Rcr, rho, h fixed; dashed: current beta = ${beta})`,
  leadAxis: 'lead angle rho [deg]',
  tiltAxis: 'tilt angle beta [deg]',
  errorAxis: (u) => `error [${u}]`,
  description: (title) => `${title}. The values at the current angle are listed beside the chart.`,
  legendHead: (angle, deg) => `at ${angle} = ${deg} deg:`,
  leadOnly: ' (lead only)',
  seeBelow: 'n/a (see below)',
  none: 'n/a',
  errorIn: { pct: 'error in %', length: 'error in length', name: 'Error unit' },
  rhoScale: { log: 'rho axis: log', linear: 'rho axis: linear', name: 'Lead angle axis' },
  summary: (rho, beta, values) => `At rho = ${rho} deg, beta = ${beta} deg, L: ${values}.`,
  noSummary: 'The current posture is outside the charted range.',
  cylinder: (concave, axis) =>
    ` On this ${concave ? 'concave' : 'convex'} cylinder (axis ${axis === 'feed' ? 'along' : 'across'} the feed) the exact curve is the cylinder's (none where the posture would gouge the surface or h is beyond its flanks); the approximations are as on a plane, as in the table.`,
  gap: (names, angle, from, to) =>
    `No answer from ${names} ${to === null ? `at about ${angle} = ${from} deg` : `for ${angle} from about ${from} to ${to} deg`}: `,
  // The core's sentences (sweepGaps.ts, approximations.ts), as gapReasons.ts reads them back.
  reasons: {
    exact: EXACT_NO_ANSWER,
    sekineRhoZero:
      'at rho = 0 the projected ellipse degenerates to a line (its long radius Rshort/sin(rho) is infinite)',
    sekineShort: "the ellipse's short radius is 0",
    redonnetRhoZero: 'at rho = 0 the effective radius Rb/sin(rho) + Rcr is infinite',
    bediRhoZero: 'at rho = 0 its ellipse (semi-axes Rlong, Rlong sin(rho)) is flat and Eq. 11 divides by 0',
    overflow: 'its effective radius overflows (rho is too close to 0 for its 1/sin(rho)); the model has no answer here',
    flatBottom:
      'the flat bottom lies on the plane (rho = 0 without tilt, or lead and tilt too small to count), so the radius of curvature at the contact is infinite',
    sharpEdge: 'the contact is a sharp edge (Rcr = 0), a circle of radius 0',
    flatEnd: 'a flat end (Rcr = 0) has no corner ball',
  },
  widest: (shape, symbol) =>
    `h is above the widest point of its ${shape} (its ${shape === 'circle' ? 'radius' : 'height'} ${symbol} is below h)`,
};
