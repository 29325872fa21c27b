/**
 * The result bar (issues 21 and 28): on a phone the results panel lies below the inputs, so the
 * answer is off screen while a field has focus and after (Enter, a tap elsewhere). A compact bar
 * fixed at the bottom of a narrow viewport (resultBar.css: shown while a result exists, and while a
 * field of the inputs has focus), kept above the on-screen keyboard (the visual viewport's bottom
 * edge, {@link followVisualViewport}), mirrors the results panel's
 * headline: its label, its text (in the user's unit, a dash when there is no answer) and the value
 * its Copy button copies, with a mark while that value is stale or the field is being typed. It
 * computes nothing: it copies what ResultsPanel.render just drew, so it never shows a number the
 * panel does not show for the inputs on screen.
 */
import { must } from './dom';
import './resultBar.css';

/** What the bar's mark says: typing, stale (the panel's `.stale` or aria-busy) or nothing. */
export type ResultBarMark = 'typing' | 'stale' | '';

export class ResultBar {
  private readonly section: HTMLElement;
  private readonly headlineLabel: HTMLElement;
  private readonly headline: HTMLOutputElement;
  private readonly label: HTMLElement;
  private readonly headlineQuestion: HTMLElement;
  private readonly question: HTMLElement;
  private readonly value: HTMLOutputElement;
  private readonly copyButton: HTMLButtonElement;
  private readonly mark: HTMLElement;

  constructor(
    root: ParentNode,
    private readonly bar: HTMLElement = must(root, '[data-testid="result-bar"]'),
  ) {
    this.section = must(root, '.results');
    this.headlineLabel = must(root, '[data-role="headline-label"]');
    this.headline = must(root, '[data-role="headline"]');
    this.label = must(bar, '[data-role="bar-label"]');
    this.headlineQuestion = must(root, '[data-role="headline-question"]');
    this.question = must(bar, '[data-role="bar-question"]');
    this.value = must(bar, 'output');
    this.copyButton = must(bar, 'button.copy');
    this.mark = must(bar, '[data-role="bar-mark"]');
    // A press on the bar keeps the focus in the field (the bar stays, and so does a phone's keyboard).
    bar.addEventListener('mousedown', (event) => event.preventDefault());
    followVisualViewport(document.documentElement);
  }

  /**
   * Mirrors the headline the results panel has just drawn (call right after ResultsPanel.render);
   * `typing` is true while a typed text is held back (typing.ts).
   */
  render(typing: boolean): void {
    const setText = (e: HTMLElement, text: string) => {
      if (e.textContent !== text) e.textContent = text;
    };
    setText(this.label, this.headlineLabel.textContent ?? '');
    setText(this.value, this.headline.textContent ?? '');
    // The question the answer answers, under its label (hidden as the headline's is).
    setText(this.question, this.headlineQuestion.hidden ? '' : (this.headlineQuestion.textContent ?? ''));
    this.question.hidden = this.headlineQuestion.hidden;
    const copy = this.headline.dataset.copy;
    if (copy === undefined) {
      delete this.value.dataset.copy;
      delete this.value.dataset.copyUnit;
    } else {
      this.value.dataset.copy = copy;
      this.value.dataset.copyUnit = this.headline.dataset.copyUnit ?? '';
    }
    this.copyButton.disabled = copy === undefined;
    this.bar.toggleAttribute('data-has-result', copy !== undefined);
    // Its name starts with its visible word, in the language on screen ("Copy", "Kopieren").
    this.copyButton.setAttribute(
      'aria-label',
      `${this.copyButton.dataset.label ?? 'Copy'} ${this.headlineLabel.textContent ?? 'the headline value'}`,
    );
    const stale = this.section.classList.contains('stale') || this.section.getAttribute('aria-busy') === 'true';
    const mark: ResultBarMark = typing ? 'typing' : stale ? 'stale' : '';
    this.bar.dataset.mark = mark;
    setText(this.mark, mark === 'typing' ? 'typing' : mark === 'stale' ? 'out of date' : '');
    this.mark.hidden = mark === '';
  }
}

/**
 * Keeps the result bar (fixed to the layout viewport's bottom) on the visual viewport's bottom edge:
 * the top of a phone's on-screen keyboard, which shrinks the visual viewport and not the layout
 * one. Sets `--keyboard-inset` on `target` (the root element: the bar and the page's scroll padding
 * read it; CSS px, 0 when the two bottoms meet) on each resize and scroll of the visual viewport;
 * does nothing where the browser has none.
 */
export function followVisualViewport(target: HTMLElement, viewport = window.visualViewport): void {
  if (!viewport) return;
  const follow = (): void => {
    const insetPx = Math.max(0, Math.round(window.innerHeight - viewport.height - viewport.offsetTop));
    target.style.setProperty('--keyboard-inset', `${insetPx}px`);
  };
  viewport.addEventListener('resize', follow);
  viewport.addEventListener('scroll', follow);
  follow();
}
