/**
 * Moves the 3D scene's camera to a new place and target: at once, or in a short eased glide (the
 * step-through's moves from one step's focus to the next) unless the system asks for reduced
 * motion. Frames are asked only while the camera glides (render on demand); a new move, or the
 * user taking the camera, stops the glide where it is.
 */
import type { PerspectiveCamera } from 'three';
import type { Vec3 } from './cameraFit';
import type { OrbitController } from './orbit';

/** How long a glide lasts (ms). */
export const GLIDE_MS = 200;

export class CameraMotion {
  private frame: number | null = null;
  private readonly from = { position: [0, 0, 0] as number[], target: [0, 0, 0] as number[] };
  private readonly to = { position: [0, 0, 0] as number[], target: [0, 0, 0] as number[] };
  private startMs = 0;

  constructor(
    private readonly camera: PerspectiveCamera,
    private readonly controls: OrbitController,
    private readonly redraw: () => void,
  ) {}

  /** Whether a glide is under way. */
  get moving(): boolean {
    return this.frame !== null;
  }

  /**
   * Puts the camera at `position` looking at `target` with `up`: in a glide when `glide` is true
   * and the system allows motion, otherwise at once (drawn on the next frame).
   */
  moveTo(position: Vec3, target: Vec3, up: Vec3, glide: boolean): void {
    this.stop();
    this.camera.up.set(...up);
    const reduced = typeof matchMedia === 'function' && matchMedia('(prefers-reduced-motion: reduce)').matches;
    if (!glide || reduced) {
      this.place(position, target);
      return;
    }
    this.from.position = this.camera.position.toArray();
    this.from.target = this.controls.target.toArray();
    this.to.position = [...position];
    this.to.target = [...target];
    this.startMs = performance.now();
    const step = (nowMs: number) => {
      const t = Math.min(1, Math.max(0, (nowMs - this.startMs) / GLIDE_MS));
      const e = t * t * (3 - 2 * t); // smoothstep: eased at both ends
      const mix = (a: number[], b: number[]): Vec3 => [
        (a[0] as number) + e * ((b[0] as number) - (a[0] as number)),
        (a[1] as number) + e * ((b[1] as number) - (a[1] as number)),
        (a[2] as number) + e * ((b[2] as number) - (a[2] as number)),
      ];
      this.place(mix(this.from.position, this.to.position), mix(this.from.target, this.to.target));
      this.frame = t < 1 ? requestAnimationFrame(step) : null;
    };
    this.frame = requestAnimationFrame(step);
  }

  /** Stops a glide where it is. */
  stop(): void {
    if (this.frame !== null) cancelAnimationFrame(this.frame);
    this.frame = null;
  }

  private place(position: Vec3, target: Vec3): void {
    this.camera.position.set(...position);
    this.controls.target.set(...target);
    this.controls.update();
    this.redraw();
  }
}
