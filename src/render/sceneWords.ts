/**
 * The words the 3D scene writes itself (issue 30), in English; the page gives another language's
 * with the labels (ui/i18n/sceneText.ts). No DOM and no three.js: the page's types and the tests
 * read it.
 */

/** The words the scene writes itself beside its symbols (P_hp, CC, P_base and the axes' letters kept). */
export interface SceneWordTexts {
  readonly designPlane: string;
  readonly designSurface: string;
  readonly hPlane: string;
  readonly hSurface: string;
  /** A cusp point on a curved surface, right and left (R, L). */
  readonly cusp: string;
  /** The step-through's point: converged, the best candidate, a single contact. */
  readonly converged: string;
  readonly best: string;
  readonly single: string;
  /** The X axis: along the feed. */
  readonly xAxis: string;
  /** After a dimension measured along an arc, with its separator. */
  readonly arc: string;
  /** The heights' scale badge and its hover title: true scale (null) or heights drawn `k` times taller. */
  readonly scale: (k: number | null) => string;
  readonly scaleTitle: (k: number | null) => string;
}

/** The scene's words in English (the page gives another language's with the labels). */
export const SCENE_WORDS: SceneWordTexts = {
  designPlane: 'design plane',
  designSurface: 'design surface',
  hPlane: 'h pseudo plane',
  hSurface: 'h pseudo surface',
  cusp: 'cusp',
  converged: 'P_hp (converged)',
  best: 'best P_hp[i]',
  single: 'single contact',
  xAxis: 'X (feed)',
  arc: ' (arc)',
  scale: (k) => (k === null ? 'heights at true scale' : `heights drawn x${k} (up to 2h above the plane)`),
  scaleTitle: (k) =>
    k === null
      ? 'Every length and height is drawn at true scale.'
      : `So that the scallop can be seen, heights from the plane up to twice the scallop height are drawn ${k} times taller, the tool above them at true scale. Only the drawing: every number is the solver's.`,
};
