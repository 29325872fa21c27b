/**
 * The 3D scene, loaded after the first result: three.js (about 150 kB gzip) and the creation of a
 * WebGL context (hundreds of milliseconds on a software rasteriser) would otherwise stand between
 * opening the page and reading the step-over. Until the scene exists, the page's calls are kept,
 * the latest of each kind, and replayed in order once it is built; so the scene always shows the
 * latest state it was given, whenever it arrives. Pure (no DOM): the page passes the loader.
 */

/** What a slot needs of its scene. */
export interface SlotScene {
  readonly frames: number;
  readonly softwareRendering: boolean;
  onFrame: (() => void) | null;
}

/** What the page asks of the scene (`update`, `stale`, `camera`, `trace`); each key keeps only its latest call. */
export type SceneCall = string;

export class SceneSlot<S extends SlotScene> {
  private scene: S | null = null;
  private loading = false;
  private readonly calls = new Map<SceneCall, (scene: S) => void>();
  private frameListener: (() => void) | null = null;

  /** `build` loads the scene's code and creates it (called once, by `load`). */
  constructor(private readonly build: () => Promise<S>) {}

  /** Runs `action` on the scene now, or when it is built (replacing an earlier call of that key). */
  run(key: SceneCall, action: (scene: S) => void): void {
    if (this.scene !== null) {
      action(this.scene);
      return;
    }
    this.calls.delete(key); // re-inserted last: calls replay in the order of their latest use
    this.calls.set(key, action);
  }

  /** Builds the scene (once), then replays the kept calls. */
  load(): void {
    if (this.loading) return;
    this.loading = true;
    void this.build().then((scene) => {
      scene.onFrame = this.frameListener;
      this.scene = scene;
      for (const action of this.calls.values()) action(scene);
      this.calls.clear();
    });
  }

  /** Called after each frame the scene renders. */
  set onFrame(listener: (() => void) | null) {
    this.frameListener = listener;
    if (this.scene !== null) this.scene.onFrame = listener;
  }

  /** Frames rendered so far (0 before the scene exists). */
  get frames(): number {
    return this.scene?.frames ?? 0;
  }

  /** Whether WebGL runs on a software rasteriser (false before the scene exists). */
  get softwareRendering(): boolean {
    return this.scene?.softwareRendering ?? false;
  }

  /** The scene once built, else null (read by the tests' probe). */
  peek(): S | null {
    return this.scene;
  }

  /** True once the scene is built. */
  get ready(): boolean {
    return this.scene !== null;
  }
}
