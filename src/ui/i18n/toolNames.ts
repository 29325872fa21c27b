/**
 * The catalogue tools' names in the language in force (issue 30): the preset box's options and
 * groups and the tool chips' hover titles (toolPresets.ts's English labels, "D6, corner R1 (paper
 * Tool 1)", "D1/2 in, ball end", read back), and the chips' legend ("Catalogue tools (mm)",
 * toolChips.ts). Pure (no DOM): language.ts writes them, and puts the English back. Loaded with the
 * language code.
 */
import type { Catalogue } from './catalogue';
import { localDecimal } from './langChoice';

/** A preset's label, the box's "custom" and its groups, the chips' legend, in `c`'s language; null: not one. */
export function toolNameIn(english: string, c: Catalogue): string | null {
  const preset = /^D(.+?), (?:corner R(.+?)|ball end)(?: \(paper Tool (\d+)\))?$/.exec(english);
  if (preset !== null)
    return c.said.preset(
      localDecimal(preset[1] ?? '', c),
      preset[2] === undefined ? null : localDecimal(preset[2], c),
      preset[3] ?? null,
    );
  const legend = /^Catalogue tools \((mm|inch|mm, inch)\)$/.exec(english);
  if (legend !== null) return c.said.catalogueTools((legend[1] ?? '').replace('inch', c.page.inch));
  return english === 'custom'
    ? c.said.custom
    : english === 'metric (mm)'
      ? c.said.metric
      : english === 'inch'
        ? c.page.inch
        : null;
}
