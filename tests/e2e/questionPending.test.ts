/**
 * The number on screen keeps the words of the question it answers (issue 28, point 1): while a new
 * answer is on its way (the solver's reply held), the headline and the result bar show the old
 * number with the old question's words, never the words of the inputs not yet answered, and Copy
 * waits; once the reply lands, the new number with the new words, and Copy names them. Desktop, one page.
 */
import { describe, expect, it } from 'vitest';
import { exactForward, forwardInput } from '../../src/core/index';
import { formatLenUnit } from '../../src/ui/format';
import { namedWorker, SOLVER, useSite } from './harness';
import { heldAnswers, holdReplies, release } from './heldReplies';

const site = useSite('docs/question-pending', { scene: false });

/** The headline for a lead angle (deg): the README's tool, h 0.05 mm, one-way on a plane. */
const headline = (leadDeg: number) =>
  formatLenUnit(
    exactForward(
      forwardInput({ toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: leadDeg, tiltAngleDeg: 0 }, 'one-way', 0.05),
    ).intervalMm,
    'mm',
  );
const words = (leadDeg: number) => `5-axis, lead ${leadDeg}°, tilt 0°, one-way, plane`;

describe('the question words go with the number shown', { timeout: 60_000 }, () => {
  it('while the answer to lead 10° is pending, the lead 5° number keeps the lead 5° words (headline, bar; Copy waits)', async () => {
    const { page, errors } = await site.open('?R=3&Rcr=1&rho=5&tilt=0&h=0.05&unit=mm');
    await page
      .context()
      .grantPermissions(['clipboard-read', 'clipboard-write'], { origin: new URL(site.url()).origin });
    const number = () => page.getByTestId('result-exact-interval').textContent();
    const question = () => page.getByTestId('headline-question').textContent();
    const barQuestion = () => page.getByTestId('result-bar-question').textContent();
    await expect.poll(number).toBe(headline(5));
    await expect.poll(question).toBe(words(5));
    site.changed();
    // The instrumented build's solver watchdog (workers.ts), lengthened from 3 s: the held reply
    // is not taken for a stall (a restarted worker would answer).
    await page.evaluate(() => {
      (window as unknown as { __pathIntervalSolverWatchdogMs: number }).__pathIntervalSolverWatchdogMs = 120_000;
    });
    const worker = await namedWorker(page, SOLVER);
    await holdReplies(worker);
    await page.getByTestId('input-rho').fill('10');
    await page.getByTestId('input-rho').press('Enter');
    // The lead 10° answer is computed and held: the page shows the old number, marked out of date.
    await expect.poll(() => heldAnswers(worker), { timeout: 20_000 }).toBe(1);
    await expect.poll(() => page.locator('section.results').getAttribute('aria-busy')).toBe('true');
    expect(await number()).toBe(headline(5));
    expect(await question()).toBe(words(5));
    expect(await barQuestion()).toBe(words(5));
    // Nothing to copy under the wrong words: the headline's Copy waits for the answer.
    const copy = page.locator('.results .big button.copy');
    expect(await copy.isDisabled()).toBe(true);
    await release(worker);
    await expect.poll(number).toBe(headline(10));
    expect(headline(10)).not.toBe(headline(5));
    await expect.poll(question).toBe(words(10));
    await expect.poll(barQuestion).toBe(words(10));
    // Copy copies the number shown and names the question it answers.
    await expect.poll(() => copy.isDisabled()).toBe(false);
    await copy.click();
    await expect.poll(() => page.getByTestId('copy-status').textContent()).toMatch(/^Copied /);
    const status = (await page.getByTestId('copy-status').textContent()) ?? '';
    expect(status).toBe(`Copied ${headline(10).replace(' mm', '')} (mm): ${words(10)}.`);
    expect(errors).toEqual([]);
  });
});
