/**
 * A doubly curved point's charts' words in English (issue 30): the charts as written, typed by the
 * catalogues' RadiusWords so Japanese and German (i18n/jaRadius.ts, deRadius.ts) give every one.
 * Loaded with the teaching views.
 */
import type { RadiusWords } from '../i18n/catalogue';

export const EN_RADIUS: RadiusWords = {
  radius: (kind, size) => (kind === 'straight' ? 'straight' : `${kind} ${size}`),
  title: (u, self, other, held, current) =>
    `L [${u}] against |${self}| [${u}], log axis (${other} held ${held}; R, Rcr, posture, h fixed; dashed: current ${self} = ${current})`,
  xLabel: (self, u) => `|${self}| [${u}] (log)`,
  description: (title) => `${title}. The values at the current radius are listed beside the chart.`,
  band: { gouging: 'gouging', limit: 'h at or above the limit' },
  legendHead: (self, current) => `at ${self} ${current}:`,
  branch: (self, kind) => `${self} ${kind}`,
  seeBelow: 'n/a (see below)',
  summary: (rf, rc, L, rfStraight, rcStraight) =>
    `At Rf ${rf}, Rc ${rc}: L = ${L}; with Rf straight ${rfStraight}, with Rc straight ${rcStraight}.`,
  gap: (side, self, from, to, other, held, reason) =>
    `No ${side} L ${to === null ? `at about |${self}| = ${from}` : `for |${self}| from about ${from} to ${to}`} (${other} held ${held}): ${reason === 'gouging' ? 'the tool gouges the surface at this posture' : 'h is at or above the flank or shank limit there'}.`,
};
