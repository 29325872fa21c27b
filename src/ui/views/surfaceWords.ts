/**
 * The Machined surface view's words in English (issue 30): the view as written, typed by the
 * catalogues' SurfaceWords so Japanese and German (i18n/jaSurface.ts, deSurface.ts) give every one.
 * Loaded with the teaching views.
 */
import type { SurfaceWords } from '../i18n/catalogue';

export const EN_SURFACE: SurfaceWords = {
  invalid: 'Out of date: the inputs are invalid, so there is nothing to simulate.',
  failed: 'No simulation: its solver gave up; change any input to try again.',
  pending: (percent) => `Simulating the passes${percent === null ? '' : `: ${percent} %`}...`,
  reasons: {
    'planes-only':
      'The simulation covers planes only: on a cylinder the exact values above still hold, but there is no simulated surface to compare them with.',
    'no-scallop':
      'No scallop: the flat bottom lying on the plane leaves a flat surface, so there is nothing to simulate.',
    none: 'No simulation.',
  },
  // As the worker writes it (worker/simulate.ts), read back by surfaceView.ts.
  exception: (detail) => `No simulation: ${detail}`,
  exaggeration: (k, unit) =>
    `${k === null ? 'Heights at true scale' : `Heights exaggerated x${k} (vertical exaggeration)`}; colour: height above the lowest point (${unit}).`,
  comparison: (simulated, exact, diff, within, bound, cells, passes) =>
    `Simulated cusp ${simulated} against exact ${exact}: they differ by ${diff}, ${within ? 'within' : 'beyond'} the stated resolution bound ${bound} (${cells} cells, ${passes} passes).`,
  traceLabel: 'Profilometer trace across the passes with Rz, Ra and Rq marked',
  traceCaption: (passes, rz, ra, rq) => `Simulated trace, ${passes} passes. Exact: Rz ${rz}, Ra ${ra}, Rq ${rq}`,
  meanLine: 'mean line',
  sceneLabel: '3D view of the simulated machined surface, coloured by height',
};

/**
 * The worker's reason for no simulation in `w`'s language: an exception's (worker/simulate.ts's
 * "No simulation: ...", read back with the English words) worded as a sentence of the language, its
 * own text left out (exceptionDetail gives it, for a hover title); else as it is.
 */
export function exceptionIn(reason: string, w: SurfaceWords): string {
  const prefix = EN_SURFACE.exception('');
  return w !== EN_SURFACE && reason.startsWith(prefix) ? w.exception(reason.slice(prefix.length)) : reason;
}

/** The exception's own text a reason worded in `w`'s language leaves out, for a hover title ('' in English, or none). */
export function exceptionDetail(reason: string, w: SurfaceWords): string {
  const prefix = EN_SURFACE.exception('');
  return w !== EN_SURFACE && reason.startsWith(prefix) ? reason.slice(prefix.length) : '';
}
