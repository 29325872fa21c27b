/**
 * The "Copy link" button: the current state as a URL (the full calculator's, plain numbers), for a
 * colleague or a bookmark. Copied to the clipboard with a confirmation; where the browser refuses,
 * the link is shown selected in a text box to copy by hand.
 */
import { html } from './dom';

/**
 * Wires the button: on click it copies `link()` and says so in `status` (a live region); if the
 * clipboard is refused, the link is shown in a read-only field, selected.
 */
export function wireCopyLink(button: HTMLButtonElement, status: HTMLElement, link: () => string): void {
  const fallback = html('input', {
    type: 'text',
    class: 'link-text',
    readonly: '',
    'aria-label': 'Link to this state',
    'data-testid': 'link-text',
  });
  fallback.hidden = true;
  status.after(fallback);
  button.addEventListener('click', () => {
    const text = link();
    fallback.value = text;
    const refused = (): void => {
      fallback.hidden = false;
      fallback.select();
      status.textContent = 'Copying was refused by the browser: the link is selected below, copy it by hand.';
    };
    const clipboard = navigator.clipboard;
    if (!clipboard) {
      refused();
      return;
    }
    clipboard.writeText(text).then(() => {
      fallback.hidden = true;
      status.textContent = 'Link copied: it opens this calculator with these inputs.';
    }, refused);
  });
}
