/**
 * A link that gives one of the page's parameters more than once (`?unit=mm&...&unit=inch`, a
 * second `h=`): the page reads the first (as URLSearchParams.get does) and says which values it
 * ignored, as it says of any value it could not use. Pure (no DOM).
 */
import { URL_PARAMS } from '../core/input/fields';

/** The most ignored values a notice quotes (a link may repeat a key thousands of times); the rest are counted. */
export const REPEATS_QUOTED = 3;

/** The parameters the page reads. */
const READ: ReadonlySet<string> = new Set(URL_PARAMS);

/** A value as a notice quotes it: `name="value"`, cut at 20 characters as the other link notices do. */
const quoted = (name: string, value: string) => `${name}="${value.slice(0, 20)}"`;

/**
 * One notice for each registry parameter (fields.ts URL_PARAMS: every parameter the page reads)
 * that `params` gives more than once, in the link's order: how many times, the first value (the
 * one used) and the values ignored. Parameters the page does not read are not its business and
 * are passed over.
 */
export function repeatedParamNotices(params: URLSearchParams): string[] {
  const notices: string[] = [];
  const names = new Set(params.keys());
  for (const name of names) {
    if (!READ.has(name)) continue;
    const [first, ...ignored] = params.getAll(name);
    if (first === undefined || ignored.length === 0) continue;
    const shown = ignored.slice(0, REPEATS_QUOTED).map((v) => quoted(name, v));
    const more = ignored.length - shown.length;
    const list = more > 0 ? `${shown.join(', ')} and ${more} more` : shown.join(', ');
    notices.push(
      `${name} is in the link ${ignored.length + 1} times; using the first, ${quoted(name, first)} (${list} ignored).`,
    );
  }
  return notices;
}
