/**
 * Number entry as people type: a field's text that is not yet a valid question (`0`, `0.`, `-`,
 * empty) is held back while the user types, so no error flashes and no old number shows: the page
 * shows the pending state (dashes, "Typing") until the text commits, after a pause of
 * TYPING_PAUSE_MS with no keystroke, or on Enter or when the field loses focus. A text that makes a
 * valid question commits at once (the results follow the typing live). Pure timing, no DOM.
 */

/** The pause after the last keystroke before a held-back text is validated and shown (ms). */
export const TYPING_PAUSE_MS = 400;

export class TypingGate {
  private timer: ReturnType<typeof setTimeout> | null = null;

  /** `commit` runs when a held-back text has waited TYPING_PAUSE_MS with no further keystroke. */
  constructor(
    private readonly commit: () => void,
    private readonly pauseMs: number = TYPING_PAUSE_MS,
  ) {}

  /** True while a typed text is held back. */
  get holding(): boolean {
    return this.timer !== null;
  }

  /** Holds the text just typed back, until a pause (restarted by every keystroke). */
  hold(): void {
    if (this.timer !== null) clearTimeout(this.timer);
    this.timer = setTimeout(() => {
      this.timer = null;
      this.commit();
    }, this.pauseMs);
  }

  /** Stops holding; true when a text was held back (the caller then commits it). */
  release(): boolean {
    const was = this.timer !== null;
    if (this.timer !== null) clearTimeout(this.timer);
    this.timer = null;
    return was;
  }
}
