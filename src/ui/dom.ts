/** The element `selector` finds under `root`; throws when the page lacks it (a broken page, not an input). */
export function must<T extends Element>(root: ParentNode, selector: string): T {
  const found = root.querySelector<T>(selector);
  if (!found) throw new Error(`missing element ${selector}`);
  return found;
}

/** Creates an element with attributes and optional text. */
export function html<K extends keyof HTMLElementTagNameMap>(
  tag: K,
  props: Record<string, string> = {},
  text = '',
): HTMLElementTagNameMap[K] {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(props)) e.setAttribute(k, v);
  if (text) e.textContent = text;
  return e;
}

/**
 * A term and its value in a details list: `<div><dt>term</dt><dd>value</dd></div>` (the div with
 * `props`), appended to `list`; returns the div and the dd.
 */
export function detailsRow(
  list: HTMLElement,
  term: string,
  value: Node,
  props: Record<string, string> = {},
): { row: HTMLDivElement; dd: HTMLElement } {
  const row = html('div', props);
  const dd = html('dd');
  dd.append(value);
  row.append(html('dt', {}, term), dd);
  list.append(row);
  return { row, dd };
}
