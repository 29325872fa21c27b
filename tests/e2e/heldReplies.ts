/**
 * Holding a worker's replies from a browser test (no fixed wait): the worker keeps what it posts
 * (answers and progress) to itself until released, so that a test can look at the page while an
 * answer is on its way, then let it land.
 */
import type { Worker } from 'playwright-core';

type Held = { __held: unknown[][]; __release(): void };

/** The worker keeps its replies (and progress) to itself until {@link release}. */
export async function holdReplies(worker: Worker): Promise<void> {
  await worker.evaluate(() => {
    const g = self as unknown as Held & { postMessage(m: unknown, t?: unknown): void };
    const post = g.postMessage.bind(g);
    const held: unknown[][] = [];
    let holding = true;
    g.__held = held;
    g.postMessage = (m: unknown, t?: unknown) => {
      if (holding) held.push([m, t]);
      else post(m, t);
    };
    g.__release = () => {
      holding = false;
      for (const [m, t] of held.splice(0)) post(m, t);
    };
  });
}

/** Answers (replies carrying a request) the worker holds. */
export const heldAnswers = (worker: Worker): Promise<number> =>
  worker.evaluate(
    () =>
      (self as unknown as Held).__held.filter(([m]) => {
        const r = m as { rpc?: string; value?: unknown };
        return r?.rpc === 'ok' && typeof r.value === 'object' && r.value !== null && 'request' in r.value;
      }).length,
  );

/** Lets the held replies go, and the next ones straight through. */
export const release = (worker: Worker): Promise<void> => worker.evaluate(() => (self as unknown as Held).__release());
