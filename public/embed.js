/*
 * <path-interval-calculator>: embeds the path interval calculator in an iframe that takes the
 * height of its content. Plain JavaScript, no build step: load this file with a <script> tag
 * from the site that serves the calculator, then write for example
 *
 *   <path-interval-calculator view="profile" r="3" rcr="1" rho="5" h="0.05" theme="dark">
 *   </path-interval-calculator>
 *
 * Attributes (all optional; each becomes the query parameter of the same name, see the README):
 * r, rcr, rho, tilt, h, l, ra, target, mode, pattern, unit, view, theme; `src` is the
 * calculator's address (default: the folder this script was loaded from): an http(s) or a relative
 * address only; any other (javascript:, data:, ...) would run in the host page or in no origin of
 * the calculator's, so it is refused with a console warning naming `src`, and nothing is loaded.
 * `title` is the iframe's accessible name. The other attributes only ever become query parameters
 * (encoded), never an address. The page posts { type: 'path-interval:resize', height } whenever its content
 * changes height; only messages from the iframe's own window and origin are taken.
 */
(() => {
  const PARAMS = {
    r: 'R',
    rcr: 'Rcr',
    rho: 'rho',
    tilt: 'tilt',
    h: 'h',
    l: 'L',
    ra: 'ra',
    target: 'target',
    mode: 'mode',
    pattern: 'pattern',
    unit: 'unit',
    view: 'view',
    theme: 'theme',
  };
  const MIN_HEIGHT = 80;
  const MAX_HEIGHT = 20000;
  const script = document.currentScript;
  const defaultBase = script?.src ? new URL('./', script.src).href : new URL('./', document.baseURI).href;

  /** True for an address with a scheme of its own (not relative), as the URL parser reads it. */
  function isAbsolute(text) {
    try {
      new URL(text);
      return true;
    } catch {
      return false;
    }
  }

  /**
   * The address of the `src` attribute, or null when it is refused: only http(s) and relative
   * addresses (these take the host page's own scheme) are loaded. The check reads the parsed
   * address, so spellings such as " JavaScript:" or "java\tscript:" are caught as the browser
   * would read them.
   */
  function frameAddress(text) {
    let url;
    try {
      url = new URL(text, document.baseURI);
    } catch {
      return null;
    }
    if (url.protocol === 'http:' || url.protocol === 'https:') return url;
    return isAbsolute(text) ? null : url;
  }

  class PathIntervalCalculator extends HTMLElement {
    static get observedAttributes() {
      return [...Object.keys(PARAMS), 'src', 'title'];
    }

    constructor() {
      super();
      this.frame = null;
      this.origin = '';
      this.onMessage = (event) => {
        const frame = this.frame;
        if (!frame || event.source !== frame.contentWindow || event.origin !== this.origin) return;
        const data = event.data;
        if (data?.type !== 'path-interval:resize') return;
        const height = Number(data.height);
        if (!Number.isFinite(height)) return;
        frame.style.height = `${Math.round(Math.min(MAX_HEIGHT, Math.max(MIN_HEIGHT, height)))}px`;
        this.dispatchEvent(new CustomEvent('path-interval:resize', { detail: { height } }));
      };
    }

    /**
     * The iframe's address: the calculator with the attributes as query parameters and embed=1;
     * null when the `src` attribute is not an http(s) or relative address (refused).
     */
    get url() {
      const url = frameAddress(this.getAttribute('src') || defaultBase);
      if (url === null) return null;
      for (const [attribute, param] of Object.entries(PARAMS)) {
        const value = this.getAttribute(attribute);
        if (value !== null) url.searchParams.set(param, value);
      }
      url.searchParams.set('embed', '1');
      return url;
    }

    connectedCallback() {
      this.style.display = 'block';
      window.addEventListener('message', this.onMessage);
      if (!this.frame) {
        this.frame = document.createElement('iframe');
        this.frame.style.border = '0';
        this.frame.style.width = '100%';
        this.frame.style.height = '360px';
        this.frame.style.display = 'block';
        this.append(this.frame);
      }
      this.load();
    }

    disconnectedCallback() {
      window.removeEventListener('message', this.onMessage);
    }

    attributeChangedCallback() {
      if (this.frame) this.load();
    }

    load() {
      const url = this.url;
      this.frame.title = this.getAttribute('title') || 'Path interval calculator';
      if (url === null) {
        // Refused: say so, and leave nothing of a previous address loaded (no message is taken).
        console.warn(
          `<path-interval-calculator>: the src attribute ${JSON.stringify(this.getAttribute('src'))} is not an http(s) or relative address; nothing is loaded.`,
        );
        this.origin = '';
        if (this.frame.getAttribute('src') !== 'about:blank') this.frame.src = 'about:blank';
        return;
      }
      this.origin = url.origin;
      if (this.frame.src !== url.href) this.frame.src = url.href;
    }
  }

  if (!customElements.get('path-interval-calculator'))
    customElements.define('path-interval-calculator', PathIntervalCalculator);
})();
