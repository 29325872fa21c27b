/**
 * The words of the 3D scene's labels for one answer (a leaf: the catalogue's type and the scene's
 * labels both read it, so neither imports the other).
 */
import type { SceneWordTexts } from '../render/sceneWords';

/** Texts of the scene's labels (render/drawables/parts.ts SceneLabels), and its accessible name in another language. */
export interface SceneLabelTexts {
  readonly interval: string;
  readonly halfInterval: string;
  readonly contactOffset: string | null;
  readonly programmedStep?: string;
  readonly name?: string;
  readonly words?: SceneWordTexts;
  /** The step-over is measured along an arc (the scene adds its word after L and L/2). */
  readonly arc?: boolean;
}
