/**
 * The cross-feed profile's words in English (issue 30): the view as written, typed by the
 * catalogues' ProfileWords so Japanese and German (i18n/jaProfile.ts, deProfile.ts) give every one.
 * Loaded with the teaching views.
 */
import type { ProfileWords } from '../i18n/catalogue';
import { catalogue } from '../i18n/words';

export const EN_PROFILE: ProfileWords = {
  plotPlane: 'Cross-feed profile of three adjacent passes',
  plotCylinder: (side, axis) =>
    `Cross-feed profile of three adjacent passes on a ${side} cylinder, axis ${axis === 'feed' ? 'along' : 'across'} the feed`,
  plotCurved: (rf, rc) => `Cross-feed profile of three adjacent passes at a doubly curved point (Rf ${rf}, Rc ${rc})`,
  noteCylinder: (side, radius, axis) =>
    axis === 'feed'
      ? `On a ${side} cylinder of radius ${radius}, axis along the feed: each pass leaves the plane profile, the next one turned about the cylinder's axis by L/|Rs|; L is measured along the arc. Heights radially, from the surface.`
      : `On a ${side} cylinder of radius ${radius}, axis across the feed: this section through the cylinder's axis shows the surface straight; each pass is the tool revolved about the axis (its profile is not the plane's), the next one stepped L along the axis. Heights radially, from the surface.`,
  noteCurved: (rf, rc) =>
    `At a doubly curved point (Rf ${rf} along the feed, Rc ${rc} across it): the section across the feed is the circle of radius |Rc|; each pass leaves the section its two flanks make seen from the main axis, the next one turned about it by L/|Rc|; L is measured along the arc. The marks show where the plane's answer, each cylinder's and the corrected procedures put the next pass. Heights radially, from the surface.`,
  heightsPlane: 'vertical scale',
  heightsSurface: 'heights above the surface',
  curvatureTrue: "; the surface's curvature at true scale",
  scale: (k, heights, auto, capped, curvature) => {
    const a = auto ? ' (auto)' : '';
    const c = capped === null ? '' : ` (x${capped} would fold the trough over)`;
    return k === 1 ? `true scale${a}${c}` : `${heights} exaggerated x${k}${a}${c}${curvature}`;
  },
  exaggeration: 'Vertical scale',
  auto: 'vertical: auto',
  trueScale: 'true scale',
  vertical: (k) => `vertical x${k}`,
  zoomIn: 'Zoom in',
  zoomOut: 'Zoom out',
  reset: 'Reset view',
  cusp: 'Zoom to cusp',
  approximations:
    "The approximations' profiles are drawn at the exact step-over L (at each pass the exact answer puts), to compare their shapes with the exact profile; the step-over each of them gives is in the results table.",
  ring: 'ring ellipse (a = Rb, b)',
  nextPass: ': next pass',
  cylinderAlong: 'Cylinder along the feed (Rf ignored)',
  cylinderAcross: 'Cylinder across the feed (Rc ignored)',
  arc: ' (arc)',
  high: (length, k) => `${length} high (drawn x${k})`,
};

/** The profile's words in the language in force (English: the view as written). */
export function profileWords(): ProfileWords {
  return catalogue()?.profile ?? EN_PROFILE;
}
