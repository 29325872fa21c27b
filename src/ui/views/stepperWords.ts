/**
 * The step-through's words in English (issue 30): the view as written, typed by the catalogues'
 * StepperWords so Japanese and German (i18n/jaStepper.ts, deStepper.ts) give every one. Angles come
 * without their unit (" deg" put here). Loaded with the teaching views.
 */
import type { StepperWords } from '../i18n/teachWords';

export const EN_STEPPER: StepperWords = {
  step: (k, n) => `Step ${k} of ${n}. `,
  side: (flank) => (flank === 'right' ? 'Right flank (+Y)' : 'Left flank (-Y)'),
  merged: (what, from, to, count) =>
    what === 'sections'
      ? ` Sections ${from} to ${to} shown as one (${count} sections that the scene and the gauge show alike).`
      : ` Search passes ${from} to ${to} shown as one (${count} passes: each narrows the range further, by less than the scene can show).`,
  start: (side, gamma, ds, rcr) =>
    `${side}. Fig. 1, box 2 (Eq. 1): start at the section at ring angle gamma = ${gamma} deg, where the ring is h/2 above its lowest point; d_s = ${ds} against Rcr = ${rcr}.`,
  approach: (side, merged, gamma, ds, gap) =>
    `${side}. Fig. 1, boxes 6-11: move along the ring towards d_s = Rcr.${merged} Section at gamma = ${gamma} deg: d_s = ${ds} (Rcr - d_s = ${gap}).`,
  single: (side, gamma) =>
    `${side}. Fig. 1, boxes 12-14: the section at gamma_scp = ${gamma} deg touches the h pseudo plane at a single point (d_s = Rcr). It bounds the search range.`,
  noSingle: (side) =>
    `${side}: every section meets the h pseudo plane (no single contact), so the search runs over the whole half ring.`,
  search: (side, sections, from, to, gamma, out, merged) =>
    `${side}. Fig. 1, boxes 16-25: ${sections} sections from gamma = ${from} deg to ${to} deg; their farthest crossings P_hp[i] with the plane. Best: gamma = ${gamma} deg, ${out === null ? 'no crossing' : `${out} out from the contact`}; the range narrows to its neighbours.${merged}`,
  flankConverged: (side, width, out, gamma) => `${side} converged: ${width} = ${out} at gamma* = ${gamma} deg.`,
  closingUntilted: (half, exact) =>
    `Fig. 1, box 26: converged. L/2 = ${half} on each flank; the exact solver gives ${exact}.`,
  closingTilted: (wR, wL, exactR, exactL) =>
    `Fig. 1, box 26: converged on both flanks. wR = ${wR}, wL = ${wL}; the exact solver gives wR = ${exactR}, wL = ${exactL}.`,
  same: {
    'single-contact':
      'The scene hardly changes: the last approach section already lies on the single-contact one; this step confirms it (d_s = Rcr) and marks its point.',
    search: 'The scene hardly changes: the search starts from the single-contact point.',
    converged:
      'The scene shows the last search pass without its candidates: the search has stopped moving, so its best point is the answer for this flank.',
  },
  counter: (k, n) => `step ${k} of ${n}`,
  gaugeLabel: 'd_s / Rcr, linear from 0:',
  noDs: ' no d_s here (search: sections between the ends of the range)',
  ds: (ratio, ds, rcr) => ` ${ratio}: d_s = ${ds}, Rcr = ${rcr}`,
  play: 'Play',
  playOne: 'Play (one step)',
  pause: 'Pause',
  back: '< Back',
  forward: 'Forward >',
  names: {
    controls: 'Step controls',
    first: 'First step',
    back: 'Step back',
    forward: 'Step forward',
    last: 'Last step',
  },
  intro:
    'The scene shows each section visited (purple), the candidate points P_hp[i] of each search pass, and the point found, first on the right flank (+Y), then on the left. Steps that would look the same are shown as one.',
  motion: 'Reduced motion is on: Play shows the next step on each press instead of animating the steps.',
  cylinder:
    "The paper's 3D procedure (Figure 1) searches the torus sections against the h pseudo plane, so it is shown for a plane only. On this cylinder the exact solver works on the cylinder itself (see the results and the Cross-feed profile); choose a plane to step through the procedure.",
};
