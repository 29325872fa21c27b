/**
 * The words of the 3D scene's labels for one answer: the render layer's SceneLabels, read from its
 * leaf file (no DOM, no three.js), so the catalogue's type and the scene's labels import neither
 * each other nor the scene.
 */
export type { SceneLabels as SceneLabelTexts } from '../render/sceneLabels';
