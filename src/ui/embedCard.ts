/**
 * The compact result card (issue 28): `?embed=1&view=result` (the element's `view="result"`) shows
 * a documentation page only the number: one line naming the inputs, the headline answer and its
 * Copy button, no inputs panel, no teaching views, no 3D scene (its code is not loaded). The card
 * is the page's own headline (ResultsPanel draws it, Copy copies it), laid out by embed.css under
 * the root element's `result-card` class; this module adds the line of inputs, written once from
 * the link's state (an embedded card has no fields to change it).
 */
import { cardSummary } from './embedCardText';
import type { CalculatorState } from './stateTypes';
import './embed.css';

/** The `view=` word that asks for the card (embedded only; not a teaching view). */
export const RESULT_VIEW = 'result';

/** The root element's class while the page is the card. */
const CARD_CLASS = 'result-card';

/**
 * Makes the page the result card when `card` (embedded with view=result): the root element's class
 * and the line of inputs above the headline. Returns `card`.
 */
export function startResultCard(root: ParentNode, card: boolean, state: CalculatorState): boolean {
  document.documentElement.classList.toggle(CARD_CLASS, card);
  if (!card) return false;
  const headline = root.querySelector('.headline');
  const line = document.createElement('p');
  line.className = 'card-summary';
  line.dataset.testid = 'card-summary';
  line.textContent = cardSummary(state);
  headline?.prepend(line);
  return true;
}
