/**
 * The 3D scene's labels in another language (issue 30): sceneLabels.ts writes them in English
 * (`L = 2.8872 mm`); a catalogue's `scene.labels` (made here, one maker for ja.ts and de.ts) puts
 * the locale's decimal sign into them (every digit kept) and adds the view's accessible name and the
 * words the scene writes itself (render/sceneWords.ts: its word for an arc among them). The symbols
 * (L, L/2, y0, Lxy, dz) and units stay.
 */
import type { SceneWordTexts } from '../../render/sceneWords';
import type { SceneLabelTexts } from '../sceneLabelTexts';
import type { Catalogue, SceneWords } from './catalogue';
import { localDecimal } from './langChoice';

/**
 * The scene's words of language `lang`: `arc` after a dimension along an arc (with its separator),
 * the view's `name`, and the words it writes beside its symbols.
 */
export function sceneWordsIn(
  lang: Catalogue['lang'],
  arc: string,
  name: string,
  words: Omit<SceneWordTexts, 'arc'>,
): SceneWords {
  const local = (text: string) => localDecimal(text, { lang });
  return {
    labels: (t: SceneLabelTexts): SceneLabelTexts => ({
      ...t,
      interval: local(t.interval),
      halfInterval: local(t.halfInterval),
      contactOffset: t.contactOffset === null ? null : local(t.contactOffset),
      ...(t.programmedStep === undefined ? {} : { programmedStep: local(t.programmedStep) }),
      name,
      words: { ...words, arc },
    }),
  };
}
