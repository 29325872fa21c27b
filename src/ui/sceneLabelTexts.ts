/**
 * The words of the 3D scene's labels for one answer: the render layer's SceneLabels (a leaf for the
 * page: the catalogue's type and the scene's labels both read it, so neither imports the other).
 */
export type { SceneLabels as SceneLabelTexts } from '../render/drawables/parts';
