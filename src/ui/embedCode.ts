/**
 * "Copy embed code": the HTML a documentation page needs to embed the calculator in its current
 * state and view, as a plain iframe and as the <path-interval-calculator> custom element
 * (public/embed.js, which reserves the view's height and loads the frame when scrolled to). The
 * button copies it to the clipboard and says so; where the clipboard is refused it shows the code
 * selected, to copy by hand.
 */
import { embedAttributeOfParam } from '../core/input/fields';
import { wireClipboardCopy } from './copyLink';
import { html } from './dom';

function escapeAttribute(text: string): string {
  return text.replace(/&/g, '&amp;').replace(/"/g, '&quot;').replace(/</g, '&lt;');
}

/**
 * The embed code for a page at `pageUrl` (the calculator's address, without query) showing the
 * state of `search` (a query string such as `?R=3&Rcr=1&...`; `embed` is added, `view` kept).
 */
export function embedCode(pageUrl: string, search: string): string {
  const params = new URLSearchParams(search);
  params.delete('embed');
  const frameParams = new URLSearchParams(params);
  frameParams.set('embed', '1');
  const src = `${pageUrl}?${frameParams.toString()}`;
  // Each parameter as the custom element's attribute (the field registry's; public/embed.js maps them back).
  const attributes = [...params].map(([k, v]) => `${embedAttributeOfParam(k) ?? k}="${escapeAttribute(v)}"`).join(' ');
  const script = new URL('embed.js', pageUrl).href;
  return [
    '<!-- Path interval calculator: a plain iframe (fixed height) -->',
    `<iframe src="${escapeAttribute(src)}" width="100%" height="480" style="border:0" title="Path interval calculator"></iframe>`,
    '',
    '<!-- Or the custom element: it keeps the height of its view (or height="640") and loads when scrolled to -->',
    `<script src="${escapeAttribute(script)}" defer></script>`,
    `<path-interval-calculator ${attributes}></path-interval-calculator>`,
  ].join('\n');
}

/**
 * Wires the "Copy embed code" button: on click it copies `code()` and confirms in `status`
 * (a live region); if the clipboard is refused, the code is shown in a read-only text box, selected.
 */
export function wireCopyEmbed(button: HTMLButtonElement, status: HTMLElement, code: () => string): void {
  const fallback = html('textarea', {
    class: 'embed-code',
    readonly: '',
    rows: '6',
    'aria-label': 'Embed code',
    'data-testid': 'embed-code',
  });
  wireClipboardCopy(button, status, fallback, code, {
    copied: 'Embed code copied: an iframe and the <path-interval-calculator> element.',
    refused: 'Copying was refused by the browser: the embed code is selected below, copy it with Ctrl+C.',
    clearAfterMs: 4000,
  });
}
