/**
 * The finish box's own sentences in English (issue 30), typed by the catalogues' FinishWords so
 * Japanese and German (i18n/jaFinish.ts, deFinish.ts) give every one; the worker's refusals stay
 * its own English sentences here (i18n/finishText.ts words their data in another language).
 * Loaded with the finish box.
 */
import type { FinishWords } from './i18n/catalogue';

export const EN_FINISH: Omit<FinishWords, 'errors' | 'failure' | 'scope' | 'targetSa'> = {
  worker: (gaveUp, reason) =>
    gaveUp
      ? `No finish: its worker gave up (${reason}).`
      : `The finish's worker was restarted (${reason}); computing again...`,
  areal: {
    Sq: 'root mean square height',
    Sz: 'highest peak to deepest valley',
    Sp: 'highest peak',
    Sv: 'deepest valley',
    Ssk: 'skewness',
    Sku: 'kurtosis',
  },
  mapLabel: 'Heights of one period cell, coloured from the lowest (blue) to the highest (orange)',
  mapScale: (period, across, sz) =>
    `One period cell, ${period} along the feed (right) by ${across} across (down); blue the lowest, orange the highest: Sz = ${sz} apart. Drawn square, not to scale.`,
  x3pComputing: 'Computing the surface in the worker...',
  x3pNone: (reason) => (reason === null ? 'No x3p.' : `No x3p: ${reason}`),
  x3pGaveUp: (reason) => `No x3p: its worker gave up (${reason}).`,
  x3pSaved: (fileName, size) => `Saved ${fileName}: ${size} x ${size} heights over one period cell.`,
};
