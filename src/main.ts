/** Page entry: styles and the calculator (with the test probe only in the `e2e` build mode). */
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
