/**
 * A number field tapped on a touch screen selects its whole text, so that what the user types
 * replaces the value (issue 21: at the machine, tap h and type the shop's value; no backspacing a
 * phone keyboard). A mouse click or the keyboard's Tab keep the browser's own caret placement.
 */

/** Wires `input`: the tap (touch pointer) that focuses it selects all its text. */
export function selectOnTouchFocus(input: HTMLInputElement): void {
  /** The tap under way focused the field, and nothing was typed since. */
  let fresh = false;
  input.addEventListener('pointerdown', (e) => {
    fresh = e.pointerType === 'touch' && document.activeElement !== input;
  });
  // Typing came first (the tap's click can arrive after the first keys): keep what was typed.
  input.addEventListener('input', () => {
    fresh = false;
  });
  // After the tap's click the browser has placed its caret: select then, so that the selection stays.
  input.addEventListener('click', () => {
    if (fresh) input.select();
    fresh = false;
  });
}
