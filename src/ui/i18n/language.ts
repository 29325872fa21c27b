/**
 * The page's language (issue 30): English, Japanese or German. A link's `lang=` (the field
 * registry's; an embed's `lang` attribute puts it there) wins; else the language chosen on an
 * earlier visit (localStorage); else, on a first visit, the browser's first language the page
 * has; else English. One tap on the switch changes it, remembers it and writes it into the link.
 * A catalogue loads only when its language is chosen (ja.ts, de.ts); English is the page as
 * written, its words read from the page itself before any other language replaces them.
 */
import { CURVATURE_ROWS, type CurvatureRowKey, PROCEDURES, type ProcedureKey } from '../../core/procedures/procedures';
import { ZERO_FEED_LABEL } from '../results';
import { REVOLUTION_NOTE } from '../roughness';
import type { ToolStorage } from '../savedTools';
import type { Catalogue, CurvedRowTitle, FinishPhrase, LabelKey, Lang, Phrase, SurfacePresetKey } from './catalogue';
import { describeInputErrorIn, describeThreeAxisErrorIn } from './errorText';
import { chooseLang, LANGUAGE_KEY, langOf, localDecimal, storedLanguage } from './langChoice';
import { meaningIn } from './meaningWords';
import { noticeParts } from './noticeWords';
import { notesIn } from './tableNotes';
import { toolNameIn } from './toolNames';
import { setCatalogue, catalogue as wordsInForce } from './words';

/** Loads a language's catalogue (null for English). */
export function loadCatalogue(lang: Lang): Promise<Catalogue | null> {
  if (lang === 'ja') return import('./ja').then((m) => m.catalogue);
  if (lang === 'de') return import('./de').then((m) => m.catalogue);
  return Promise.resolve(null);
}

/**
 * The parts of the page that stay in English in another language (their `lang` says so): the
 * teaching views (the translated ones carry their own lang), the notices' details.
 */
const ENGLISH_PARTS = '.teaching, .notices';

/** The page's English words of its `data-i18n` elements, read once before any language replaces them. */
const ENGLISH = new WeakMap<Element, string>();

/** Writes a catalogue's words (null: English) into the page's `data-i18n` elements and its `lang`. */
export function applyCatalogue(root: ParentNode, catalogue: Catalogue | null): void {
  for (const element of root.querySelectorAll<HTMLElement>('[data-i18n]')) {
    if (!ENGLISH.has(element)) ENGLISH.set(element, element.textContent ?? '');
    const key = element.dataset.i18n as keyof Catalogue['page'];
    const text = catalogue === null ? ENGLISH.get(element) : catalogue.page[key];
    if (text !== undefined && element.textContent !== text) element.textContent = text;
  }
  // The Copy buttons' words: English by default (copy.ts), the language's from the results' pass.
  if (catalogue === null)
    for (const button of root.querySelectorAll<HTMLElement>('button.copy')) {
      delete button.dataset.label;
      delete button.dataset.copied;
      delete button.dataset.failed;
      button.textContent = 'Copy';
      if (button.dataset.ariaEnglish) button.setAttribute('aria-label', button.dataset.ariaEnglish);
    }
  // The landmarks' names (index.html's English kept to go back to).
  for (const e of root.querySelectorAll<HTMLElement>('[data-i18n-label]')) {
    e.dataset.ariaEnglish ??= e.getAttribute('aria-label') ?? '';
    const name = catalogue?.labels[e.dataset.i18nLabel as LabelKey];
    if (name !== undefined) e.setAttribute('aria-label', name);
  }
  // A radius's side box (fields.ts: its name from its field's label, its options) and the link's text
  // box (copyLink.ts), written in English once; their English kept to go back to.
  for (const e of root.querySelectorAll<HTMLElement>('select[data-testid^="side-"], [data-testid="link-text"]')) {
    e.dataset.ariaEnglish ??= e.getAttribute('aria-label') ?? '';
    const key = e.closest<HTMLElement>('[data-field]')?.dataset.field as 'Rf' | 'Rc' | undefined;
    if (catalogue !== null)
      e.setAttribute(
        'aria-label',
        key === undefined ? catalogue.said.linkText : catalogue.said.sideBox(catalogue.fields[key].label),
      );
    for (const option of e.querySelectorAll<HTMLOptionElement>('option')) {
      option.dataset.english ??= option.textContent ?? '';
      const text = catalogue?.question[option.value as 'convex' | 'concave' | 'straight'] ?? option.dataset.english;
      if (option.textContent !== text) option.textContent = text;
    }
  }
  // The procedures table's and its box's names back in English (procedureNames put them into the language).
  if (catalogue === null)
    for (const e of root.querySelectorAll<HTMLElement>('[data-aria-english]:not(button.copy)'))
      e.setAttribute('aria-label', e.dataset.ariaEnglish ?? '');
  // The finish box's words back in English.
  if (catalogue === null)
    for (const e of root.querySelectorAll<HTMLElement>('[data-phrase]'))
      if (e.dataset.phrase && e.textContent !== e.dataset.phrase) e.textContent = e.dataset.phrase;
  // The parts still in English say so (WCAG 3.1.2, language of parts): screen readers read them as English.
  for (const e of root.querySelectorAll<HTMLElement>(ENGLISH_PARTS))
    if (catalogue === null) e.removeAttribute('lang');
    else e.setAttribute('lang', 'en');
  // A translated element inside such a part (the scene's camera buttons) is in the language again.
  for (const e of root.querySelectorAll<HTMLElement>('[data-i18n]'))
    if (catalogue !== null && e.parentElement?.closest(ENGLISH_PARTS)) e.lang = catalogue.lang;
    else e.removeAttribute('lang');
  // The catalogue tools' names (toolNames.ts), and the chips' legend.
  localizeToolNames(root, catalogue);
  localizeSurfacePresets(root, catalogue);
  const legend = root.querySelector<HTMLElement>('[data-testid="tool-chips"] legend');
  if (legend !== null) localizeToolLegend(legend, catalogue);
  document.documentElement.lang = catalogue?.lang ?? 'en';
  const title = root.querySelector('[data-i18n="title"]')?.textContent;
  if (title) document.title = title;
}

/**
 * The preset box's options and groups and the chips' titles under `root` in `c`'s language (null:
 * English, kept in data-english to go back to).
 */
function localizeToolNames(root: ParentNode, c: Catalogue | null): void {
  for (const e of root.querySelectorAll<HTMLElement>(
    '[data-testid="preset"] option, [data-testid="preset"] optgroup, .tool-chip[title]',
  )) {
    const attribute = e.tagName === 'OPTION' ? null : e.tagName === 'OPTGROUP' ? 'label' : 'title';
    const shown = (attribute === null ? e.textContent : e.getAttribute(attribute)) ?? '';
    e.dataset.english ??= shown;
    const english = e.dataset.english;
    const text = c === null ? english : (toolNameIn(english, c) ?? english);
    if (text === shown) continue;
    if (attribute === null) e.textContent = text;
    else e.setAttribute(attribute, text);
  }
}

/**
 * The surface box's presets (fields.ts writes them in English, from surfaceState.ts) and its raster
 * line in `c`'s language; their English kept to go back to.
 */
function localizeSurfacePresets(root: ParentNode, c: Catalogue | null): void {
  for (const option of root.querySelectorAll<HTMLOptionElement>('[data-testid="surface-preset"] option')) {
    option.dataset.english ??= option.textContent ?? '';
    const text = c?.said.surfacePresets[option.value as SurfacePresetKey] ?? option.dataset.english;
    if (option.textContent !== text) option.textContent = text;
  }
  const note = root.querySelector<HTMLElement>('[data-testid="surface-note"]');
  if (note === null || note.textContent === '') return;
  note.dataset.english ??= note.textContent ?? '';
  const text = c === null ? note.dataset.english : c.said.rasterNote;
  if (note.textContent !== text) note.textContent = text;
}

/**
 * What L and the heights mean on the surface asked (results.ts writes it in English on each drawing
 * that changes it) in the language; a sentence not known stays English, marked so.
 */
function surfaceMeaning(root: ParentNode, words: Catalogue): void {
  const meaning = root.querySelector<HTMLElement>('[data-testid="surface-meaning"]');
  const text = meaning?.textContent ?? '';
  if (meaning === null || text === '' || text === meaning.dataset.local) return;
  const local = meaningIn(text, words);
  if (local === null) {
    meaning.lang = 'en';
    return;
  }
  meaning.removeAttribute('lang');
  meaning.dataset.local = local;
  meaning.textContent = local;
}

/** The chips' legend (toolChips.ts writes it in English on each drawing) in `c`'s language. */
function localizeToolLegend(legend: HTMLElement, c: Catalogue | null): void {
  const text = legend.textContent ?? '';
  const local = c === null ? null : toolNameIn(text, c);
  if (local !== null && local !== text) legend.textContent = local;
}

/**
 * The results in the language in force (issue 30): the headline's label in its words, and every
 * number of the headline, the details and the procedures' table with the locale's decimal sign.
 * Run after each drawing of the results (words.ts localize); English, the page as written, is left
 * as drawn. Copy keeps its own text (data-copy, with a point).
 */
export function localizeResults(results: object): void {
  const words = wordsInForce();
  if (words === null) return;
  if (results instanceof HTMLElement && results.dataset.testid === 'copy-status') {
    spoken(results, words);
    return;
  }
  // The copy-link and embed-code buttons' status (copyLink.ts, embedCode.ts: copied, or refused).
  if (results instanceof HTMLElement && results.classList.contains('embed-status')) {
    const said = words.phrases[results.textContent as Phrase];
    if (said !== undefined) results.textContent = said;
    return;
  }
  const root = results as ParentNode;
  // The headline's label, and the three-axis step's (forward and inverse).
  for (const label of root.querySelectorAll<HTMLElement>('[data-role="headline-label"], [data-role="step-label"]')) {
    const english = label.textContent ?? '';
    const named =
      english === 'Step-over L'
        ? words.headline.stepOver
        : english === 'Scallop height h'
          ? words.headline.scallopHeight
          : english === ZERO_FEED_LABEL
            ? words.headline.zeroFeed
            : words.phrases[english as Phrase];
    if (named !== undefined) label.textContent = named;
  }
  // A flat end lying flat on a plane: the sentence with its L = 2R.
  const flat = root.querySelector<HTMLElement>('[data-testid="no-scallop"]');
  const diameter = /^No scallop: a flat end without lead or tilt .* so L = 2R = (.+) for any h\.$/.exec(
    flat?.textContent ?? '',
  )?.[1];
  if (flat && diameter !== undefined) flat.textContent = words.said.noScallopPlane(localDecimal(diameter, words));
  // The roughness's rule of thumb (roughness.ts) and L's share of the tool diameter (results.ts), from their English.
  const rule = root.querySelector<HTMLElement>('[data-testid="result-ra-rule"]');
  const ruled = /^Rule of thumb Ra ~ h\/4 = (.+): (\S+) % against the exact Ra\.$/.exec(rule?.textContent ?? '');
  if (rule && ruled)
    rule.textContent = words.said.ruleOfThumb(localDecimal(ruled[1] ?? '', words), localDecimal(ruled[2] ?? '', words));
  else if (rule && rule.textContent === REVOLUTION_NOTE) rule.textContent = words.said.revolution;
  const share = root.querySelector<HTMLElement>('[data-testid="result-percent-diameter"]');
  const shared = /^L = (\S+) % of the tool diameter$/.exec(share?.textContent ?? '');
  if (share && shared) share.textContent = words.said.diameterShare(localDecimal(shared[1] ?? '', words));
  procedureNames(root, words);
  tableNotes(root, words);
  surfaceMeaning(root, words);
  localizeSurfacePresets(root, words);
  // The roughness rows' "h for this Ra" (roughness.ts), marked as the finish box's words are.
  const raHeight = root.querySelector('[data-testid="result-ra-height"]')?.parentElement?.previousElementSibling;
  if (raHeight instanceof HTMLElement) raHeight.dataset.phrase ??= 'h for this Ra';
  // The finish box's words (finishPanel.ts keeps each element's English in data-phrase).
  for (const e of root.querySelectorAll<HTMLElement>('[data-phrase]')) {
    const text = words.finish[e.dataset.phrase as FinishPhrase];
    if (text !== undefined && e.textContent !== text) e.textContent = text;
  }
  // The status line, the no-scallop line and the Copy buttons (copy.ts reads data-label back).
  for (const e of root.querySelectorAll<HTMLElement>(
    '[data-testid="results-status"], [data-testid="no-scallop"], button.copy',
  )) {
    if (e.matches('button.copy')) {
      e.dataset.label = words.phrases.Copy;
      e.dataset.copied = words.phrases.Copied;
      e.dataset.failed = words.phrases['Copy failed'];
      if (e.textContent !== words.phrases.Copied && e.textContent !== words.phrases['Copy failed'])
        e.textContent = words.phrases.Copy;
      // Its accessible name holds its visible word (WCAG 2.5.3): the English name kept to go back to.
      e.dataset.ariaEnglish ??= e.getAttribute('aria-label') ?? '';
      const name = words.phrases[e.dataset.ariaEnglish as Phrase];
      if (name !== undefined) e.setAttribute('aria-label', name);
      continue;
    }
    const phrase = words.phrases[e.textContent as Phrase];
    if (phrase !== undefined) e.textContent = phrase;
  }
  // Only the text nodes change (a cell's <output> and its test id stay).
  for (const e of root.querySelectorAll<HTMLElement>(
    '.headline output, .results .procedures td, .results .pct, .finish-results output, [data-role="headline-question"]',
  )) {
    const walker = document.createTreeWalker(e, NodeFilter.SHOW_TEXT);
    for (let node = walker.nextNode(); node !== null; node = walker.nextNode()) {
      const text = node.nodeValue ?? '';
      const local = localDecimal(text, words);
      if (local !== text) node.nodeValue = local;
    }
  }
}

/**
 * The procedures' table in the language (results.ts draws it in English, from the registry): its
 * head, each procedure's name (with "lead only" when the tool is tilted) and the cylinder's rows.
 */
function procedureNames(root: ParentNode, words: Catalogue): void {
  const names = words.procedures;
  // The table's and its box's names (index.html's English kept to go back to) and its rows' hover title.
  for (const [selector, name] of [
    ['[data-testid="procedures-scroll"]', names.region],
    ['[data-testid="procedures-table"]', names.table],
  ] as const)
    for (const e of root.querySelectorAll<HTMLElement>(selector)) {
      e.dataset.ariaEnglish ??= e.getAttribute('aria-label') ?? '';
      e.setAttribute('aria-label', name);
    }
  for (const tr of root.querySelectorAll<HTMLElement>('.procedures tr[data-procedure][title]'))
    if (tr.title === 'Click to select this procedure in every view') tr.title = names.select;
  for (const th of root.querySelectorAll<HTMLElement>('.procedures thead th')) {
    const head = names.head[th.textContent as keyof ProcedureNamesHead];
    if (head !== undefined) th.textContent = head;
  }
  for (const th of root.querySelectorAll<HTMLElement>('.procedures tr[data-procedure] > th')) {
    const key = (th.parentElement as HTMLElement).dataset.procedure as ProcedureKey;
    const english = PROCEDURES[key]?.label;
    const name = names.names[key]?.label;
    if (english === undefined || name === undefined) continue;
    if (th.textContent === english) th.textContent = name;
    else if (th.textContent === `${english}, lead only`) th.textContent = `${name}${names.leadOnly}`;
  }
  for (const th of root.querySelectorAll<HTMLElement>('.procedures tr.curvature-head > th'))
    th.textContent = names.cylinderHead;
  for (const th of root.querySelectorAll<HTMLElement>('.procedures tr[data-curvature] > th')) {
    const tr = th.parentElement as HTMLElement;
    const key = tr.dataset.curvature as CurvatureRowKey;
    const row = CURVATURE_ROWS[key];
    const name = names.rows[key]?.label;
    if (row !== undefined && name !== undefined && th.textContent === row.label) th.textContent = name;
    // Its hover title: what it assumes, or its note (read back by tableNotes.ts).
    if (row !== undefined && tr.title === row.assumes) tr.title = names.assumes[key];
  }
  // A row's note as its hover title, and a value a row cannot give ("n/a").
  for (const tr of root.querySelectorAll<HTMLElement>('.procedures tr[title]')) {
    const note = notesIn(tr.title, words);
    if (note.length === 1 && note[0]?.[1] === false) tr.title = note[0][0];
    const title = names.curvedTitles[tr.title as CurvedRowTitle];
    if (title !== undefined) tr.title = title;
  }
  for (const output of root.querySelectorAll<HTMLElement>('.procedures td output'))
    if (output.textContent === 'n/a') output.textContent = words.said.notAvailable;
  // A doubly curved point's rows: the exact answers by their English, a corrected procedure by its key.
  for (const th of root.querySelectorAll<HTMLElement>('.procedures tr[data-curved] > th')) {
    const key = (th.parentElement as HTMLElement).dataset.curved as CurvatureRowKey;
    const english = th.textContent ?? '';
    const row = CURVATURE_ROWS[key];
    const name =
      names.curved[english as CurvedRowName] ??
      (row !== undefined && english === `${row.shortLabel} (1/rho = 1/Reff + 1/Rc)`
        ? `${names.rows[key].shortLabel} (1/rho = 1/Reff + 1/Rc)`
        : undefined);
    if (name !== undefined) th.textContent = name;
  }
}

/**
 * The table's notes (results.ts writes them in English, sentences joined by spaces) in the language:
 * each sentence worded by tableNotes.ts; one it does not know kept English, marked so.
 */
function tableNotes(root: ParentNode, words: Catalogue): void {
  const notes = root.querySelector<HTMLElement>('[data-testid="table-notes"]');
  const text = notes?.textContent ?? '';
  if (notes === null || text === '' || notes.dataset.worded === text) return;
  const parts = notesIn(text, words).flatMap(([sentence, english], i) => {
    const part: Array<string | HTMLElement> = i === 0 ? [] : [words.lang === 'ja' ? '' : ' '];
    if (!english) return [...part, sentence];
    const span = document.createElement('span');
    span.lang = 'en';
    span.textContent = sentence;
    return [...part, span];
  });
  notes.replaceChildren(...parts);
  notes.dataset.worded = notes.textContent ?? '';
}

type ProcedureNamesHead = Catalogue['procedures']['head'];
type CurvedRowName = keyof Catalogue['procedures']['curved'];

/**
 * Copy's spoken confirmation (copy.ts writes it in English into its live region, then asks for
 * this): the same value (with a point, as copied) and unit, the question in the language with its
 * decimal sign.
 */
function spoken(live: HTMLElement, words: Catalogue): void {
  const text = live.textContent ?? '';
  const copied = /^Copied (\S+) \(([^)]*)\)(?:: (.*))?\.$/s.exec(text);
  const failed = /^Could not copy: select the value and copy it by hand \((\S+) ?(.*)\)\.$/.exec(text);
  if (copied)
    live.textContent = words.said.copied(
      copied[1] ?? '',
      copied[2] ?? '',
      copied[3] === undefined ? null : localDecimal(copied[3], words),
    );
  else if (failed) live.textContent = words.said.copyFailed(failed[1] ?? '', failed[2] ?? '');
}

/**
 * The notice box in the language in force: the page writes it in English (a worker restarted or
 * stopped, link values replaced); its sentence is put into the language with the worker's reason
 * (an exception's own text in the box's hover title), a reason not known and the link's values
 * (named by their parameters) kept in English in a part that says so. The English
 * is kept to word it again in another language, or to put it back.
 */
export function localizeNotice(box: HTMLElement): void {
  const words = wordsInForce();
  const text = box.textContent ?? '';
  const ours = box.dataset.worded === text;
  if (ours && (words?.lang ?? 'en') === (box.getAttribute('lang') ?? 'en')) return;
  const english = ours ? (box.dataset.english ?? text) : text;
  delete box.dataset.worded;
  delete box.dataset.english;
  box.removeAttribute('lang');
  box.removeAttribute('title');
  if (ours && words === null) box.textContent = english;
  if (words === null) return;
  const parts = noticeParts(english, words);
  if (parts !== null) {
    const [before, kept, after, detail] = parts;
    // An exception's own text: in the hover title, not in the sentence.
    if (detail !== '') box.title = detail;
    // The part kept English (a reason not known, details not read back), marked so; none when all is worded.
    const part = document.createElement('span');
    part.lang = 'en';
    part.textContent = kept;
    if (kept === '') box.replaceChildren(before, after);
    else box.replaceChildren(before, part, after);
    box.lang = words.lang;
    box.dataset.english = english;
    box.dataset.worded = box.textContent ?? '';
  }
}

/** What the language switch tells the page. */
export interface LanguageEvents {
  /** The words changed (a catalogue applied): redraw what code writes. */
  readonly changed: (lang: Lang) => void;
  /** The link's `lang=` (null: none). */
  readonly link: (lang: Lang | null) => void;
  /** A line for the page's notice (a link's lang= that is not a language). */
  readonly notice: (text: string) => void;
}

/**
 * Starts the page's language: the one the visit asks for (langChoice.ts), kept in the link when the
 * link gave it, and the switch (`root`'s radios).
 */
export function startLanguage(
  root: HTMLElement,
  storage: ToolStorage | null,
  events: LanguageEvents,
  search: string,
): LanguageSwitch {
  const chosen = chooseLang(search, storedLanguage(storage), navigator.languages ?? [navigator.language]);
  if (chosen.fromLink) events.link(chosen.lang);
  if (chosen.notice !== null) events.notice(chosen.notice);
  return new LanguageSwitch(root, storage, events, chosen.lang);
}

/** The language switch (its radios in `root`), the storage it remembers in, and the loads. */
export class LanguageSwitch {
  /** The language last asked for: a slower load of an earlier choice never wins. */
  private wanted: Lang;
  private readonly radios: readonly HTMLInputElement[];

  constructor(
    root: HTMLElement,
    private readonly storage: ToolStorage | null,
    private readonly events: LanguageEvents,
    start: Lang,
  ) {
    this.wanted = start;
    // The notice box follows the language whenever the page writes into it.
    // The chips' legend follows the language whenever toolChips.ts writes it in English.
    const legend = document.querySelector<HTMLElement>('[data-testid="tool-chips"] legend');
    if (legend !== null)
      new MutationObserver(() => localizeToolLegend(legend, wordsInForce())).observe(legend, {
        childList: true,
        characterData: true,
        subtree: true,
      });
    const box = document.querySelector<HTMLElement>('[data-testid="notice"]');
    if (box !== null)
      new MutationObserver(() => localizeNotice(box)).observe(box, {
        childList: true,
        characterData: true,
        subtree: true,
      });
    const radios = [...root.querySelectorAll<HTMLInputElement>('input[name="lang"]')];
    this.radios = radios;
    // A tap made while this code was loading stands (the radio is checked already): taken as the user's.
    const tapped = langOf(radios.find((r) => r.checked && r.value !== 'en')?.value);
    for (const radio of radios) {
      radio.checked = radio.value === (tapped ?? start);
      radio.addEventListener('change', () => {
        const lang = langOf(radio.value);
        if (radio.checked && lang !== null) this.choose(lang, true);
      });
    }
    if (tapped !== null) this.choose(tapped, true);
    else if (start !== 'en') this.choose(start, false);
  }

  /** Switches to `lang`; `byUser`: remembered and written into the link. */
  choose(lang: Lang, byUser: boolean): void {
    this.wanted = lang;
    if (byUser) {
      try {
        this.storage?.setItem(LANGUAGE_KEY, lang);
      } catch {
        // A storage that refuses (private mode, full): the choice lasts this visit.
      }
      this.events.link(lang === 'en' ? null : lang);
    }
    void loadCatalogue(lang).then(
      (catalogue) => this.loaded(lang, catalogue),
      () => {
        // A catalogue that does not load (offline, a new deployment): the page stays in the
        // language in force, its radio checked again, and says so.
        if (this.wanted !== lang) return;
        const inForce = wordsInForce()?.lang ?? 'en';
        this.wanted = inForce;
        for (const radio of this.radios) radio.checked = radio.value === inForce;
        this.events.notice(`The ${lang} words could not be loaded; the page stays in ${inForce}.`);
      },
    );
  }

  private loaded(lang: Lang, catalogue: Catalogue | null): void {
    if (this.wanted !== lang) return;
    setCatalogue(
      catalogue,
      localizeResults,
      (e, unit, options) => (catalogue === null ? '' : describeInputErrorIn(catalogue, e, unit, options)),
      (e, unit, typed, waterline) =>
        catalogue === null ? '' : describeThreeAxisErrorIn(catalogue, e, unit, typed, waterline),
    );
    applyCatalogue(document, catalogue);
    const box = document.querySelector<HTMLElement>('[data-testid="notice"]');
    if (box !== null) localizeNotice(box);
    this.events.changed(lang);
  }
}
