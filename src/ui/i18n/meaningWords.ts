/**
 * What L and the heights mean on the surface asked (results.ts writes it in English under the
 * results: resultsText.ts surfaceMeaning on a cylinder, resultsText.ts curvedMeaning at a doubly
 * curved point), read back from that English and worded in a language (issue 30), the radii with
 * the locale's decimal sign. Pure.
 */
import type { Catalogue, Side } from './catalogue';
import { localDecimal } from './langChoice';

const CYLINDER = /^On this (convex|concave) cylinder \(radius (.+?), axis (along|across) the feed: /;
const CURVED =
  /^At this doubly curved point \(Rf (convex|concave) (.+?) along the feed, Rc (convex|concave) (.+?) across it\), /;

/** The surface's meaning in `c`'s language, or null for an English sentence the page never wrote. */
export function meaningIn(english: string, c: Catalogue): string | null {
  const side = (s: string | undefined): Side => (s === 'concave' ? 'concave' : 'convex');
  const n = (s: string | undefined) => localDecimal(s ?? '', c);
  const cylinder = CYLINDER.exec(english);
  if (cylinder)
    return c.said.cylinderMeaning(side(cylinder[1]), n(cylinder[2]), cylinder[3] === 'along' ? 'feed' : 'cross');
  const curved = CURVED.exec(english);
  if (curved) return c.said.curvedMeaning([side(curved[1]), n(curved[2])], [side(curved[3]), n(curved[4])]);
  return null;
}
