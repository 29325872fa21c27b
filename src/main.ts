/**
 * Page entry: styles, the calculator (with the test probe only in the `e2e` build mode), and the
 * offline service worker of the production build (src/build/serviceWorker.ts).
 */
import './ui/style.css';
import './ui/quickLookup.css';
import './ui/toolShelf.css';
import './ui/shopSheet.css';
import './ui/present.css';
import './ui/scrollCue.css';
// After the stylesheet, so the printed sheet's rules win over the screen layout's.
import './ui/print.css';
import { CalculatorApp } from './ui/app';
import { startWithProbe } from './ui/probe';

const root = document.getElementById('app');
if (root) {
  // `import.meta.env.MODE` is replaced at build time: in production this is `new CalculatorApp(root)`
  // alone, and the probe module is dropped from the bundle.
  if (import.meta.env.MODE === 'e2e') startWithProbe(root);
  else new CalculatorApp(root);
}

/**
 * Whether the page runs in a frame of another origin (an embed in another site's page). There a
 * service worker would be the host's third-party storage: partitioned or refused (an error in the
 * host's console). `ancestorOrigins` (Chromium, WebKit) names each ancestor's origin without
 * touching it; without it any frame counts (a cross-origin `top.location` read is itself an error).
 */
function inCrossOriginFrame(): boolean {
  if (window.top === window) return false;
  const ancestors = window.location.ancestorOrigins;
  return ancestors === undefined || [...ancestors].some((origin) => origin !== window.location.origin);
}

// Registered after the page's load (the first result first), in the production build only: the dev
// server and the e2e build have no sw.js (the mode is asked, not PROD, which follows NODE_ENV, and
// Vitest's build runs with `test`). Offline use is an addition: a refused registration (a private
// window, storage blocked) changes nothing on the page.
if (import.meta.env.MODE === 'production' && 'serviceWorker' in navigator && !inCrossOriginFrame()) {
  window.addEventListener('load', () => {
    navigator.serviceWorker.register('./sw.js', { scope: './' }).catch(() => undefined);
  });
}
