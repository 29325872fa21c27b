/**
 * The Copy buttons. Every value copies in one format: the plain number in the unit of the unit
 * switch (mm or inch, never the µm or thou a small value may be shown in), at the resolution the
 * page shows (formatLen: 0.1 µm in mm, 10 µin in inch, at least four significant digits), with no
 * unit symbol, so it pastes straight into a CAM field in that unit. A button is disabled while its
 * value is missing (invalid or pending input, typing); a copy is confirmed by "Copied" on the
 * button for COPIED_MS and by a polite live region that names the value and its unit.
 */
import { type LengthUnit, unitSymbol } from '../core/input/units';
import { localize } from './i18n/words';

/** How long the button says "Copied" (ms). */
export const COPIED_MS = 1500;

/** The text a Copy button of `output` copies, or null when there is none (the button is then disabled). */
export function setCopyValue(output: Element, text: string | null, unit: LengthUnit): void {
  const button = output.parentElement?.querySelector<HTMLButtonElement>('button.copy') ?? null;
  if (text === null || !/\d/.test(text)) {
    delete (output as HTMLElement).dataset.copy;
    if (button) button.disabled = true;
    return;
  }
  (output as HTMLElement).dataset.copy = text;
  (output as HTMLElement).dataset.copyUnit = unitSymbol(unit);
  if (button) button.disabled = false;
}

/**
 * Wires every `button.copy` under `root` to the `data-copy` of the output beside it. `question`
 * gives the question the copied answer answers in words (questionWords.ts), named in the
 * confirmation ("Copied 1.9236 (mm): 5-axis, lead 5°, tilt 0°, one-way, plane.").
 */
export function wireCopyButtons(root: ParentNode, live: HTMLElement, question: () => string | null = () => null): void {
  for (const button of root.querySelectorAll<HTMLButtonElement>('button.copy')) {
    // The button's words in the language on screen (i18n/language.ts sets them), English by default.
    const label = () => button.dataset.label ?? 'Copy';
    button.disabled = true;
    let timer: ReturnType<typeof setTimeout> | null = null;
    button.addEventListener('click', () => {
      const output = button.parentElement?.querySelector<HTMLElement>('output');
      const text = output?.dataset.copy;
      if (!text) return;
      const unit = output?.dataset.copyUnit ?? '';
      const asked = question();
      const done = (ok: boolean) => {
        button.textContent = ok ? (button.dataset.copied ?? 'Copied') : (button.dataset.failed ?? 'Copy failed');
        live.textContent = ok
          ? `Copied ${text} (${unit})${asked ? `: ${asked}` : ''}.`
          : `Could not copy: select the value and copy it by hand (${text} ${unit}).`;
        // In the language in force (i18n/language.ts; English: as written).
        localize(live);
        if (timer !== null) clearTimeout(timer);
        timer = setTimeout(() => {
          button.textContent = label();
          live.textContent = '';
        }, COPIED_MS);
      };
      const clipboard = navigator.clipboard;
      if (!clipboard) {
        done(false);
        return;
      }
      clipboard.writeText(text).then(
        () => done(true),
        () => done(false),
      );
    });
  }
}
