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
};
