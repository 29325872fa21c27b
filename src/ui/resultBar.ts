/**
 * The result bar (issue 21): on a phone the results panel lies below the inputs, so while a field
 * has focus the answer would be off screen. A compact bar fixed at the bottom of a narrow viewport
 * (style.css, shown while an input or select of the inputs has focus) mirrors the results panel's
 * headline: its label, its text (in the user's unit, a dash when there is no answer) and the value
 * its Copy button copies, with a mark while that value is stale or the field is being typed. It
 * computes nothing: it copies what ResultsPanel.render just drew, so it never shows a number the
 * panel does not show for the inputs on screen.
 */

function must<T extends Element>(root: ParentNode, selector: string): T {
  const found = root.querySelector<T>(selector);
  if (!found) throw new Error(`missing element ${selector}`);
  return found;
}

/** What the bar's mark says: typing, stale (the panel's `.stale` or aria-busy) or nothing. */
export type ResultBarMark = 'typing' | 'stale' | '';

export class ResultBar {
  private readonly section: HTMLElement;
  private readonly headlineLabel: HTMLElement;
  private readonly headline: HTMLOutputElement;
  private readonly label: HTMLElement;
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
    this.value = must(bar, 'output');
    this.copyButton = must(bar, 'button.copy');
    this.mark = must(bar, '[data-role="bar-mark"]');
    // A press on the bar keeps the focus in the field (the bar stays, and so does a phone's keyboard).
    bar.addEventListener('mousedown', (event) => event.preventDefault());
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
    const copy = this.headline.dataset.copy;
    if (copy === undefined) {
      delete this.value.dataset.copy;
      delete this.value.dataset.copyUnit;
    } else {
      this.value.dataset.copy = copy;
      this.value.dataset.copyUnit = this.headline.dataset.copyUnit ?? '';
    }
    this.copyButton.disabled = copy === undefined;
    this.copyButton.setAttribute('aria-label', `Copy ${this.headlineLabel.textContent ?? 'the headline value'}`);
    const stale = this.section.classList.contains('stale') || this.section.getAttribute('aria-busy') === 'true';
    const mark: ResultBarMark = typing ? 'typing' : stale ? 'stale' : '';
    this.bar.dataset.mark = mark;
    setText(this.mark, mark === 'typing' ? 'typing' : mark === 'stale' ? 'out of date' : '');
    this.mark.hidden = mark === '';
  }
}
