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
 * calculator's address (default: the folder this script was loaded from); `title` the iframe's
 * accessible name. The page posts { type: 'path-interval:resize', height } whenever its content
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

    /** The iframe's address: the calculator with the attributes as query parameters and embed=1. */
    get url() {
      const url = new URL(this.getAttribute('src') || defaultBase, document.baseURI);
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
      this.origin = url.origin;
      this.frame.title = this.getAttribute('title') || 'Path interval calculator';
      if (this.frame.src !== url.href) this.frame.src = url.href;
    }
  }

  if (!customElements.get('path-interval-calculator'))
    customElements.define('path-interval-calculator', PathIntervalCalculator);
})();
