import { describe, expect, it } from 'vitest';
import { SceneSlot } from '../../src/ui/sceneSlot';

/** A stand-in for the three.js scene: records the calls it receives, in order. */
const log: string[] = [];
class FakeScene {
  frames = 7;
  softwareRendering = true;
  onFrame: (() => void) | null = null;
  constructor() {
    log.push('built');
  }
  setStale(stale: boolean) {
    log.push(`stale ${stale}`);
  }
  setCamera(preset: string) {
    log.push(`camera ${preset}`);
  }
  update(labels: { interval: string }) {
    log.push(`update ${labels.interval}`);
  }
}
let builds = 0;
const newSlot = () =>
  new SceneSlot(async () => {
    builds++;
    return new FakeScene();
  });

const settle = () => new Promise((r) => setTimeout(r, 0));

describe('SceneSlot: the scene loads after the first result and replays what it missed', () => {
  it('keeps only the latest call of each kind, replays them in the order of their latest use, then runs calls at once', async () => {
    log.length = 0;
    builds = 0;
    const slot = newSlot();
    const frames: number[] = [];
    slot.onFrame = () => frames.push(1);
    const update = (text: string) => slot.run('update', (s) => s.update({ interval: text }));
    slot.run('stale', (s) => s.setStale(false));
    update('L = 1');
    update('L = 2');
    slot.run('stale', (s) => s.setStale(true));
    expect(log).toEqual([]);
    expect(slot.ready).toBe(false);
    expect(slot.frames).toBe(0);
    slot.load();
    slot.load(); // once
    expect(builds).toBe(1);
    await settle();
    await settle();
    expect(log).toEqual(['built', 'update L = 2', 'stale true']);
    expect(slot.ready).toBe(true);
    expect(slot.frames).toBe(7);
    expect(slot.softwareRendering).toBe(true);
    slot.run('camera', (s) => s.setCamera('top'));
    expect(log.at(-1)).toBe('camera top');
  });

  it('hands the frame listener to the scene, set before or after it is built', async () => {
    log.length = 0;
    const slot = newSlot();
    let calls = 0;
    slot.onFrame = () => calls++;
    slot.load();
    await settle();
    await settle();
    slot.run('probe', (s) => s.onFrame?.());
    expect(calls).toBe(1);
    slot.onFrame = () => (calls += 10);
    slot.run('probe', (s) => s.onFrame?.());
    expect(calls).toBe(11);
  });
});
