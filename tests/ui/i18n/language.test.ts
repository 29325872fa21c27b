/**
 * The page's language chosen (issue 30, src/ui/i18n/language.ts): a link's lang= wins, then the
 * language remembered, then the browser's first language the page has, then English; a lang= that
 * is not one is said in a notice. The decimal sign of the language in force (words.ts) changes only
 * the sign: every digit stays, no grouping.
 */
import { describe, expect, it } from 'vitest';
import { catalogue as de } from '../../../src/ui/i18n/de';
import { catalogue as ja } from '../../../src/ui/i18n/ja';
import { browserLang, chooseLang, langOf, localDecimal } from '../../../src/ui/i18n/langChoice';

describe('the language a visit starts in', () => {
  it("a link's lang= wins over the remembered and the browser's", () => {
    expect(chooseLang('?R=3&lang=ja', 'de', ['de-DE'])).toEqual({ lang: 'ja', fromLink: true, notice: null });
  });
  it('then the remembered one, then the browser language (its region ignored), then English', () => {
    expect(chooseLang('?R=3', 'de', ['ja-JP'])).toEqual({ lang: 'de', fromLink: false, notice: null });
    expect(chooseLang('', null, ['fr-FR', 'de-AT', 'ja'])).toEqual({ lang: 'de', fromLink: false, notice: null });
    expect(chooseLang('', null, ['fr-FR', 'pt'])).toEqual({ lang: 'en', fromLink: false, notice: null });
    expect(chooseLang('', null, [])).toEqual({ lang: 'en', fromLink: false, notice: null });
  });
  it('a stored value that is not a language is ignored (storage is untrusted)', () => {
    expect(chooseLang('', '<script>', ['ja']).lang).toBe('ja');
    expect(langOf('constructor')).toBeNull();
    expect(browserLang(['JA-jp'])).toBe('ja');
  });
  it('a language tag as HTML and browsers write it: de-DE, DE, ja_JP; an empty lang= is not given', () => {
    expect(chooseLang('?lang=de-DE', null, []).lang).toBe('de');
    expect(chooseLang('?lang=DE', null, []).lang).toBe('de');
    expect(chooseLang('?lang=ja_JP', null, []).lang).toBe('ja');
    expect(chooseLang('?lang=', 'de', [])).toEqual({ lang: 'de', fromLink: false, notice: null });
  });

  it("a lang= that is not one: a notice naming the three, and the visit's own language", () => {
    const chosen = chooseLang('?lang=fr', 'de', []);
    expect(chosen.lang).toBe('de');
    expect(chosen.notice).toBe('lang="fr" is not en, ja or de; showing de.');
  });
});

describe('numbers in the language in force', () => {
  it('German: a decimal comma, every digit kept, no grouping; Japanese and English: a point', () => {
    expect(localDecimal('2.8872 mm', de)).toBe('2,8872 mm');
    expect(localDecimal('12345.678901 mm', de)).toBe('12345,678901 mm');
    expect(localDecimal('-0.3579 mm (-24.79 %)', de)).toBe('-0,3579 mm (-24,79 %)');
    expect(localDecimal('Eqs. 4-8', de)).toBe('Eqs. 4-8');
    expect(localDecimal('2.8872 mm', ja)).toBe('2.8872 mm');
    expect(localDecimal('2.8872 mm', null)).toBe('2.8872 mm');
  });
});
