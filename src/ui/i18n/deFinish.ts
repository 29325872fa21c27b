/**
 * The finish box's worker messages and own sentences in German (issue 30): each refusal of a
 * finish field from its data (the field's name as the page gives it, the bound in the user's unit
 * with a decimal comma, what was typed), as the English ones do (core/finish/finishInput.ts); the
 * areal parameters' names as DIN EN ISO 25178-2 gives them. Part of de.ts.
 */
import type { Catalogue, FinishErrorText } from './catalogue';

const gotOf = (t: FinishErrorText) => `(eingegeben: ${t.got})`;
const what = (part: 'marks' | 'areal') => (part === 'areal' ? 'Die flächenhaften Kenngrößen' : 'Die Vorschubmarken');
const ONLY =
  'nur auf einer Ebene (jeder Anstell- und Kippwinkel, in einer Richtung oder Zickzack) und auf der geneigten Ebene der 3-Achs-Bearbeitung.';

export const DE_FINISH: Catalogue['finishText'] = {
  errors: {
    missing: (t) => `${t.label} fehlt: bitte eine Zahl eingeben.`,
    'not-a-number': (t) => `${t.label} muss eine Zahl sein (eingegeben: „${t.got}“).`,
    'not-finite': (t) => `${t.label} muss eine endliche Zahl sein ${gotOf(t)}.`,
    'not-an-integer': (t) => `${t.label} muss eine ganze Schneidenzahl von 1 bis ${t.maxFlutes} sein ${gotOf(t)}.`,
    'not-positive': (t) => `${t.label} muss größer als 0${t.unit === '' ? '' : ` ${t.unit}`} sein ${gotOf(t)}.`,
    negative: (t) => `${t.label} muss 0${t.unit === '' ? '' : ` ${t.unit}`} oder mehr betragen ${gotOf(t)}.`,
    'too-small': (t) => `${t.label} muss mindestens ${t.limit} betragen ${gotOf(t)}.`,
    'too-large': (t) =>
      t.field === 'fz'
        ? `${t.label} darf höchstens den Werkzeugradius R = ${t.limit} betragen ${gotOf(t)}.`
        : t.field === 'runout'
          ? `${t.label} darf höchstens R/10 = ${t.limit} betragen ${gotOf(t)}.`
          : `${t.label} darf höchstens ${t.limit} betragen ${gotOf(t)}.`,
    'out-of-range': (t) =>
      `${t.label} muss mindestens 0 und kleiner als 1 sein (ein Anteil der Vorschubperiode) ${gotOf(t)}.`,
    'both-feeds': () =>
      'Entweder den Vorschub pro Zahn fz oder die Vorschubgeschwindigkeit F mit der Drehzahl n angeben, nicht beides.',
    'rate-too-small': (t) => `Der Vorschub pro Zahn fz = F / (n z) = ${t.rateFz} muss mindestens ${t.limit} betragen.`,
    'rate-too-large': (t) =>
      `Der Vorschub pro Zahn fz = F / (n z) = ${t.rateFz} darf höchstens den Werkzeugradius R = ${t.limit} betragen.`,
    'not-computed-here': () => `Vorschubmarken werden auf dieser Fläche noch nicht berechnet: ${ONLY}`,
  },
  failure: (kind, part) =>
    kind === 'not-converged'
      ? `${what(part)} ließen sich für diesen Vorschub nicht berechnen: die Suche der Schneideneingriffe konvergierte nicht; ein kleineres fz versuchen.`
      : `${what(part)} sind hier nicht definiert: schmale Streifen zwischen den Bahnen schneidet keine Schneide (die Stirnschneiden verfehlen sie); einen kleineren Bahnabstand versuchen.`,
  scope: (kind) =>
    `Vorschubmarken werden ${
      kind === 'cylinder'
        ? 'auf Zylindern'
        : kind === 'doublyCurved'
          ? 'an doppelt gekrümmten Punkten'
          : kind === 'waterlineRevolution'
            ? 'für Z-Ebenen auf Rotationsflächen'
            : 'auf dieser Fläche'
    } noch nicht berechnet: ${ONLY}`,
  worker: (gaveUp, reason) =>
    gaveUp
      ? `Keine Oberfläche: ihr Rechenprozess hat aufgegeben (${reason}).`
      : `Der Rechenprozess der Oberfläche wurde neu gestartet (${reason}); es wird erneut gerechnet …`,
  targetSa: {
    runout:
      'Ziel-Sa wird ohne Rundlauffehler berechnet: für das beste Paar den Rundlauffehler e auf 0 setzen (oder leer lassen).',
    tooLong:
      'Die Suche für dieses Ziel-Sa wurde vor ihrem Ende abgebrochen (sie würde Minuten dauern): ihre Paare haben zu großen Vorschub oder zu viele Bahnen; stattdessen die Oberfläche zu einem Bahnabstand und Vorschub berechnen.',
    worker: (gaveUp, reason) =>
      gaveUp
        ? `Kein Paar: sein Rechenprozess hat aufgegeben (${reason}).`
        : `Der Rechenprozess für Ziel-Sa wurde neu gestartet (${reason}); es wird erneut gerechnet …`,
  },
  areal: {
    Sq: 'quadratischer Mittelwert der Höhe',
    Sz: 'maximale Höhe: höchste Spitze bis tiefstes Tal',
    Sp: 'Höhe der höchsten Spitze',
    Sv: 'Tiefe des tiefsten Tals',
    Ssk: 'Schiefe der Höhenverteilung',
    Sku: 'Steilheit der Höhenverteilung',
  },
  mapLabel: 'Höhen einer Periodenzelle, eingefärbt vom tiefsten (blau) bis zum höchsten Punkt (orange)',
  mapScale: (period, across, sz) =>
    `Eine Periodenzelle, ${period} in Vorschubrichtung (nach rechts) mal ${across} quer dazu (nach unten); blau der tiefste, orange der höchste Punkt: Sz = ${sz} dazwischen. Quadratisch gezeichnet, nicht maßstäblich.`,
  x3pComputing: 'Die Oberfläche wird im Rechenprozess berechnet …',
  x3pNone: (reason) => (reason === null ? 'Keine x3p-Datei.' : `Keine x3p-Datei: ${reason}`),
  x3pGaveUp: (reason) => `Keine x3p-Datei: ihr Rechenprozess hat aufgegeben (${reason}).`,
  x3pSaved: (fileName, size) => `${fileName} gespeichert: ${size} × ${size} Höhen über eine Periodenzelle.`,
};
