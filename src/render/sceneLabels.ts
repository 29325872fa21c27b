/**
 * The texts of the scene's labels (a leaf with no DOM and no three.js: the page's catalogue types
 * its translations with it, and the Node type check reads it).
 */
import type { SceneWordTexts } from './sceneWords';

/** Texts of the scene's labels, in the user's unit (the scene knows no units). */
export interface SceneLabels {
  /** The step-over dimension, e.g. `L = 2.8872 mm`. */
  readonly interval: string;
  /** Its half, e.g. `L/2 = 1.4436 mm`. */
  readonly halfInterval: string;
  /** The contact offset dimension, e.g. `y0 = 0.1234 mm`, or null to hide it (no offset). */
  readonly contactOffset: string | null;
  /** Three-axis: the programmed step's dimension, e.g. `Lxy = 0.91 mm` or `dz = 0.12 mm`. */
  readonly programmedStep?: string;
  /** The view's accessible name in the reader's language; the scene's own English when absent. */
  readonly name?: string;
  /** The scene's own words in the reader's language; sceneWords.ts SCENE_WORDS when absent. */
  readonly words?: SceneWordTexts;
  /** The step-over is measured along an arc (its dimensions say so). */
  readonly arc?: boolean;
}
