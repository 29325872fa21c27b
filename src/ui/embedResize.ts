/**
 * Auto-height for an embedded page: whenever the content's height changes, the page posts
 * `{ type: 'path-interval:resize', height }` (CSS pixels, a whole number) to the window that
 * embeds it, so the host can size its iframe to the content (public/embed.js does). The height is
 * not secret, so it goes to any origin (`'*'`): the page cannot know its host's origin, and the
 * host checks the message's origin and source.
 */

/** The message type the host listens for. */
export const RESIZE_MESSAGE = 'path-interval:resize';

export interface ResizeMessage {
  readonly type: typeof RESIZE_MESSAGE;
  /** Height of the page's content in CSS pixels (whole, at least 1). */
  readonly height: number;
}

/**
 * Observes `content` (the page's root element) and posts its height to `window.parent` on each
 * change; does nothing when the page is not in a frame. Returns a function that stops it.
 */
export function postHeightToParent(content: HTMLElement): () => void {
  if (window.parent === window) return () => undefined;
  let last = 0;
  const post = (): void => {
    const height = Math.max(1, Math.ceil(content.getBoundingClientRect().height));
    if (height === last) return;
    last = height;
    const message: ResizeMessage = { type: RESIZE_MESSAGE, height };
    window.parent.postMessage(message, '*');
  };
  const observer = new ResizeObserver(post);
  observer.observe(content);
  post();
  return () => observer.disconnect();
}
