/**
 * Where the 3D scene's camera looks from: the three presets (isometric, along the feed, from above)
 * framed for a tool of radius R, and the refit when R changes that keeps the viewing direction the
 * user chose.
 */
import type { PerspectiveCamera } from 'three';
import type { OrbitController } from './orbit';

export type CameraPreset = 'iso' | 'feed' | 'top';

/**
 * Puts the camera at a preset for a tool of radius `toolRadiusMm`: looking at 0.3 R above the
 * contact from 4.2 R away (isometric), from 5.5 R back against the feed (so that Y runs to the right
 * as in the profile view), or from 5.5 R above with X up the screen.
 */
export function presetCamera(
  camera: PerspectiveCamera,
  controls: OrbitController,
  preset: CameraPreset,
  toolRadiusMm: number,
): void {
  const R = toolRadiusMm;
  const target = controls.target.set(0, 0, 0.3 * R);
  const d = 4.2 * R;
  if (preset === 'iso') camera.position.set(target.x + d * 0.75, target.y - d * 0.85, target.z + d * 0.6);
  else if (preset === 'feed') {
    target.z = 0.45 * R;
    camera.position.set(target.x + d * 1.3, target.y, target.z + 1e-3);
  } else camera.position.set(target.x, target.y, target.z + d * 1.3);
  camera.up.set(preset === 'top' ? 1 : 0, 0, preset === 'top' ? 0 : 1);
  controls.update();
}

/**
 * Scales the camera's target and its distance from it by `factor` about the contact (the origin):
 * the same view of a tool `factor` times larger.
 */
export function rescaleCamera(camera: PerspectiveCamera, controls: OrbitController, factor: number): void {
  const offset = camera.position.clone().sub(controls.target).multiplyScalar(factor);
  controls.target.multiplyScalar(factor);
  camera.position.copy(controls.target).add(offset);
  controls.update();
}
