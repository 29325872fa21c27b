/**
 * The question an answer answers, in words (issue 28, point 1): the machine first, then what sets
 * the posture, the pass pattern and the surface, e.g. "5-axis, lead 5°, tilt 0°, one-way, plane",
 * "3-axis, flat floor", "3-axis, slope 30°, raster 30°", "3-axis, waterline, slope 30°, along the
 * feed concave 80 mm, across concave 40 mm". Shown under the headline, in the result bar and in
 * Copy's confirmation (the shop sheet's lines and the lookup table's file name name the machine
 * their own way), so that a shop never takes a five-axis answer for its three-axis machine. Numbers as the user gave them, in the page's unit; pure (no DOM).
 */
import { unitSymbol } from '../core/input/units';
import { parseField } from './fieldText';
import type { QuestionWord } from './i18n/catalogue';
import { catalogue } from './i18n/words';
import type { CalculatorState, FieldKey } from './stateTypes';
import { sideOf } from './surfaceState';

/** A word of the question in the language in force (English: the word itself). */
function w(word: QuestionWord): string {
  return catalogue()?.question[word] ?? word;
}

/** The question's parts joined as the language in force lists them (English ", "). */
function list(...parts: string[]): string {
  return parts.join(catalogue()?.question[', '] ?? ', ');
}

/** A field's number as given (a finite number, never "-0"), or "?" when it is not one. */
function given(state: CalculatorState, key: FieldKey): string {
  const n = parseField(state.fields[key]);
  if (n === null || !Number.isFinite(n)) return '?';
  return String(n); // String(-0) is "0"
}

/** A length field with the page's unit symbol: "50 mm". */
function length(state: CalculatorState, key: FieldKey): string {
  return `${given(state, key)} ${unitSymbol(state.unit)}`;
}

/** The doubly curved point (or the surface of revolution) by its two radii and their sides. */
function curvedWords(state: CalculatorState): string {
  const radius = (key: 'Rf' | 'Rc', name: QuestionWord): string => {
    const side = sideOf(state, key);
    return side === 'straight' ? `${w(name)} ${w('straight')}` : `${w(name)} ${w(side)} ${length(state, key)}`;
  };
  return list(radius('Rf', 'along the feed'), radius('Rc', 'across'));
}

/** The five-axis design surface in words. */
function surfaceWords(state: CalculatorState): string {
  switch (state.surface) {
    case 'plane':
      return w('plane');
    case 'convex':
    case 'concave':
      return `${w(`${state.surface} cylinder`)} ${length(state, 'Rs')} ${w(state.surfaceAxis === 'feed' ? 'along the feed' : 'across the feed')}`;
    case 'curved':
      return `${w('curved point')}: ${curvedWords(state)}`;
  }
}

/**
 * The question of a page state in words (see the module comment), in the language in force.
 * Three-axis: the slope and the raster angle (a slope of 0 is the flat floor, where the raster
 * angle does not matter), or the waterline passes with the slope and, on a surface of revolution,
 * its radii.
 */
export function questionWords(state: CalculatorState): string {
  if (state.machine === '3axis') {
    const slope = parseField(state.fields.slope);
    const slopeWords = `${w('slope')} ${given(state, 'slope')}°`;
    if (state.passes === 'waterline') {
      const curved = state.feedSide !== 'straight' || state.crossSide !== 'straight';
      return curved
        ? list(w('3-axis'), w('waterline'), slopeWords, curvedWords(state))
        : list(w('3-axis'), w('waterline'), slopeWords);
    }
    if (slope === 0) return list(w('3-axis'), w('flat floor'));
    return list(w('3-axis'), slopeWords, `${w('raster')} ${given(state, 'psi')}°`);
  }
  return list(
    w('5-axis'),
    `${w('lead')} ${given(state, 'rho')}°`,
    `${w('tilt')} ${given(state, 'tilt')}°`,
    w(state.pattern),
    surfaceWords(state),
  );
}
