/**
 * German (issue 30): the shop's and the CAM systems' terms (Bahnabstand, Rautiefe, Z-Zustellung,
 * Anstellwinkel, Vorschub pro Zahn; roughness names as DIN EN ISO 4287 gives them); the paper's
 * symbols kept. The README's glossary names each term's source. Loaded only when chosen.
 */
import type { Catalogue } from './catalogue';
import { curvedMessageIn, radiusFieldIn } from './curvedText';
import { DE_CHART } from './deChart';
import { DE_CURVED } from './deCurved';
import { DE_ERRORS } from './deErrors';
import { DE_FINISH } from './deFinish';
import { DE_FORMULAS } from './deFormulas';
import { DE_LINK_NOTICES } from './deLinkNotices';
import { DE_PROCEDURES } from './deProcedures';
import { DE_PROFILE } from './deProfile';
import { DE_RADIUS } from './deRadius';
import { DE_SHEET } from './deSheet';
import { DE_SLOPE } from './deSlope';
import { DE_STEPPER } from './deStepper';
import { DE_SURFACE } from './deSurface';
import { DE_TABLES } from './deTables';
import { DE_THREE_AXIS } from './deThreeAxis';
import { sceneWordsIn } from './sceneText';

export const catalogue: Catalogue = {
  lang: 'de',
  page: {
    title: 'Bahnabstand eines Torusfräsers in jeder Anstellung',
    stepOverMeaning:
      'Der Bahnabstand L ist der Abstand benachbarter Kontaktpunktbahnen (CC-Bahnen), wie ein CAM-System den Zeilenabstand versteht.',
    centreOffset:
      'Um stattdessen den Werkzeugmittelpunkt O zu programmieren, jede CC-Bahn quer zum Vorschub verschieben um',
    fullStop: '.',
    lede: 'Exakter Bahnabstand für eine gewählte Rautiefe, bei jedem Anstell- und Kippwinkel, in einer Richtung oder im Zickzack, neben den Näherungen von Sekine, Redonnet und Bedi (Sekine & Kameya 2022), dem Schmiegekreis und der Eckenkugel.',
    language: 'Sprache',
    machine: 'Maschine',
    machine5: '5-Achs',
    machine3: '3-Achs',
    unit: 'Einheit',
    inch: 'Zoll',
    sizeAs: 'Werkzeuggröße als',
    sizeD: 'Durchmesser D',
    sizeR: 'Radius R',
    preset: 'Werkzeugvorlage',
    shelf: 'Meine Werkzeuge: gespeicherte Werkzeuge und Fusion-360-Bibliotheken',
    passes: 'Bahnstrategie',
    raster: 'Zeilen',
    waterline: 'Z-Ebenen',
    solveFor: 'Gesucht',
    forward: 'Bahnabstand',
    inverse: 'Rautiefe',
    given: 'Vorgabe',
    givenH: 'Rautiefe h',
    givenRa: 'Mittenrauwert Ra',
    pattern: 'Bahnfolge',
    oneWay: 'in einer Richtung',
    zigzag: 'Zickzack',
    surface: 'Fläche',
    plane: 'Ebene',
    convex: 'konvexer Zylinder',
    concave: 'konkaver Zylinder',
    curved: 'doppelt gekrümmter Punkt',
    axis: 'Zylinderachse',
    axisFeed: 'in Vorschubrichtung',
    axisCross: 'quer zum Vorschub',
    finish: 'Schneiden und Vorschub (optional): Vorschubmarken und flächenhafte Rauheit',
    downloadTable: 'Nachschlagetabelle laden (CSV)',
    shopSheet: 'Werkstattblatt',
    copyLink: 'Link kopieren',
    copyEmbed: 'Einbettungscode kopieren',
    cameraIso: 'Isometrisch',
    cameraFeed: 'In Vorschubrichtung',
    cameraTop: 'Draufsicht',
    rightFlank: '(rechte Flanke)',
    leftFlank: '(linke Flanke)',
    contactOffset: '(Versatz des Kontaktpunkts)',
    cuspHeights: 'Kammhöhen (Zickzack)',
    openFull: 'Vollständigen Rechner öffnen',
    embedTitle: 'Bahnabstandsrechner',
    teachingViews: 'Lehransichten',
    alongSurface: 'L entlang der Fläche',
    cuspNormal: 'Kammhöhe h (normal zur Fläche)',
    equivalentLead: 'Äquivalenter Anstellwinkel ρ',
    equivalentTilt: 'Äquivalenter Kippwinkel β',
    lookupNote:
      'Exakter Bahnabstand L und L/2 dieses Werkzeugs und dieser Bahnfolge je Rautiefe × Anstellwinkel × Kippwinkel (3-Achs: × Neigung, der programmierte Abstand Lxy oder dz), in der Einheit am Bildschirm (in jeder Spalte und im Dateinamen genannt), im Stapelformat der Kommandozeile.',
    sheetNote:
      'Eine druckbare Seite: der Bahnabstand dieses Werkzeugs, dieser Anstellung und Fläche je Rautiefe × Anstellwinkel (3-Achs: × Neigung), mit CSV.',
    staleBadge: 'Zeigt den letzten gültigen Zustand',
    typingBadge: 'Eingabe: die Szene folgt, sobald Sie innehalten oder die Eingabetaste drücken',
    camera: 'Kamera',
    legendTool: 'Werkzeug und seine Nachbarbahnen (im Zickzack gespiegelt)',
    legendPath: 'Kontaktpunktbahnen (CC), im Abstand L',
    legendContact: 'CC (P_base): Kontaktpunkt dieser Bahn',
    legendDimension: 'L und L/2, ab der CC-Bahn dieser Bahn',
    legendOffset: 'y0: Versatz des Kontaktpunkts vom Werkzeugmittelpunkt O',
    legendCentre: 'O: Werkzeugmittelpunkt',
    legendAxis: 'Werkzeugachse, ab ihrem Fußpunkt auf der Fläche',
    legendDesign: 'Sollebene',
    legendHplane: 'h-Pseudoebene',
    legendPhp: 'P_hp: Punkt des Werkzeugs auf Kammhöhe',
    legendSection: 'Schnittkreis durch jeden P_hp',
    legendLoop: 'Torus / h-Pseudoebene',
    legendRidge: 'Kämme in Vorschubrichtung (die Grate zwischen den Bahnen)',
    legendDesignCurved:
      'Zylinder oder doppelt gekrümmte Fläche (gefärbt nach der Höhe über der Tangentialebene: blau fällt ab, orange steigt, in Bändern)',
    legendHsurface: 'h-Pseudofläche (die um h versetzte Fläche)',
    legendCusp: 'Kämme darauf',
    legendAxes:
      'X (Vorschub), Y, Z am Kontaktpunkt (3-Achs: die Szene steht in der Maschine, Werkzeugachse senkrecht, Lxy oder dz ist der programmierte Abstand)',
    legendTrace: 'Schritt für Schritt: geprüfter Schnitt, Kandidaten P_hp[i], gefundener Punkt',
    legendExaggeration:
      'Höhen nahe der Fläche N-fach überhöht, wenn der Kamm zu niedrig zum Sehen ist (Hinweis in der Szene; Zahlen unverändert)',
    givenSa: 'Ziel-Sa (flächenhaft, mit den Schneiden)',
    surfacePreset: 'Flächenvorgabe',
    present: 'Präsentation',
    leavePresent: 'Präsentation beenden (Esc)',
    presentInputs: 'Eingaben',
    hideInputs: 'Eingaben ausblenden',
  },
  labels: {
    fullCalculator: 'Vollständiger Rechner',
    notices: 'Hinweise',
    teaching: 'Lehransichten',
    inputs: 'Eingaben',
    results: 'Ergebnisse',
    finish: 'Oberfläche',
    targetSa: 'Ziel-Sa',
    view3d: '3D-Ansicht',
    currentAnswer: 'Aktuelle Antwort',
  },
  fields: {
    R: { label: 'Werkzeugradius R', hint: 'halber Werkzeugdurchmesser' },
    Rcr: { label: 'Eckenradius Rcr', hint: '0 = Schaftfräser, R = Kugelfräser' },
    rho: { label: 'Anstellwinkel rho', hint: 'Neigung des Werkzeugs in Vorschubrichtung' },
    tilt: { label: 'Kippwinkel beta', hint: 'Neigung quer zum Vorschub; + neigt den Schaft nach +Y' },
    Rs: { label: 'Flächenradius Rs', hint: 'Radius des Zylinders, positiv (konvex oder konkav wird oben gewählt)' },
    h: { label: 'Rautiefe h', hint: 'Höhe des höchsten Kamms zwischen den Bahnen' },
    ra: { label: 'Mittenrauwert Ra', hint: 'Zielrauheit quer zum Vorschub; die Rautiefe folgt daraus' },
    L: { label: 'Bahnabstand L', hint: 'Abstand benachbarter Kontaktpunktbahnen' },
    slope: {
      label: 'Flächenneigung alpha',
      hint: 'Neigung der Fläche gegen die Waagerechte am Kontaktpunkt (0: ebener Boden)',
    },
    psi: {
      label: 'Zeilenwinkel psi',
      hint: 'Bahnrichtung in der Draufsicht zur Falllinie: 0 auf und ab, 90 entlang der Höhenlinie',
    },
    Rf: {
      label: 'Radius längs Rf',
      hint: 'Hauptkrümmungsradius in Vorschubrichtung, positiv; die Seite daneben wählen',
    },
    Rc: { label: 'Radius quer Rc', hint: 'Hauptkrümmungsradius quer zum Vorschub, positiv; die Seite daneben wählen' },
    Lxy: {
      label: 'Waagerechter Bahnabstand Lxy',
      hint: 'waagerechter Abstand benachbarter Zeilen, wie das CAM-System ihn programmiert',
    },
    dz: {
      label: 'Z-Zustellung dz',
      hint: 'senkrechter Abstand benachbarter Ebenen (Werkzeugspitzen), wie das CAM-System ihn programmiert',
    },
    z: { label: 'Schneidenzahl z', hint: 'Schneiden; mit fz: die Vorschubmarken' },
    fz: { label: 'Vorschub pro Zahn fz', hint: 'Vorschub je Schneide; leer: keine Vorschubmarken' },
    runout: { label: 'Rundlauffehler e', hint: 'radialer Rundlauffehler (Vorgabe 0)' },
    runoutPhase: { label: 'Phase des Rundlauffehlers', hint: 'Richtung des Rundlauffehlers ab Schneide 0' },
    passPhase: { label: 'Bahnphase q', hint: 'Versatz der Bahnen als Anteil der Vorschubperiode' },
    F: { label: 'Vorschubgeschwindigkeit F', hint: 'mit n: fz = F / (n z); aus, solange fz eingetragen ist' },
    n: { label: 'Drehzahl n', hint: 'Spindeldrehzahl; mit F ergibt sie fz' },
    sa: {
      label: 'Ziel-Sa',
      hint: 'flächenhafte Rauheit, die die Schneiden hinterlassen (Ebene, kein Rundlauffehler); mit der Zähnezahl z: bester Bahnabstand und fz',
    },
  },
  diameter: {
    label: 'Werkzeugdurchmesser D',
    hint: 'wie im Katalog; D = 2R',
    cornerHint: 'Rcr = 0: Schaftfräser, Rcr = D/2: Kugelfräser',
  },
  degrees: 'Grad',
  slider: ' Schieberegler',
  headline: { stepOver: 'Bahnabstand L', scallopHeight: 'Rautiefe h', zeroFeed: 'Bahnabstand L0 (fz → 0: Ra = Sa)' },
  phrases: {
    'Typing: the results follow when you pause or press Enter.':
      'Eingabe: die Ergebnisse folgen, sobald Sie innehalten oder die Eingabetaste drücken.',
    'Updating: these numbers are for the previous inputs.':
      'Wird aktualisiert: diese Zahlen gelten für die vorigen Eingaben.',
    'Out of date: the solver gave up; these numbers are for earlier inputs.':
      'Veraltet: der Rechner hat aufgegeben; diese Zahlen gelten für frühere Eingaben.',
    'No answer: the solver gave up.': 'Keine Antwort: der Rechner hat aufgegeben.',
    'No scallop: a flat end on a flat floor lies flat, so L = 2R for any h.':
      'Kein Kamm: ein Schaftfräser liegt auf ebenem Boden flach auf, also L = 2R für jedes h.',
    Copy: 'Kopieren',
    Copied: 'Kopiert',
    'Copy failed': 'Kopieren fehlgeschlagen',
    'Link copied: it opens this calculator with these inputs.':
      'Link kopiert: Er öffnet diesen Rechner mit diesen Eingaben.',
    'Copying was refused by the browser: the link is selected below, copy it by hand.':
      'Der Browser hat das Kopieren verweigert: Der Link ist unten markiert, bitte von Hand kopieren.',
    'Embed code copied: an iframe and the <path-interval-calculator> element.':
      'Einbettungscode kopiert: ein iframe und das Element <path-interval-calculator>.',
    'Copying was refused by the browser: the embed code is selected below, copy it with Ctrl+C.':
      'Der Browser hat das Kopieren verweigert: Der Einbettungscode ist unten markiert, mit Strg+C kopieren.',
    'Copy the headline value': 'Kopieren: den Hauptwert',
    'Copy L/2': 'Kopieren: L/2',
    'Copy the programmed step': 'Kopieren: den programmierten Abstand',
    'Copy L along the surface': 'Kopieren: L entlang der Fläche',
    'Copy the centre offset': 'Kopieren: den Versatz des Werkzeugmittelpunkts',
    'Copy the current answer': 'Kopieren: die aktuelle Antwort',
    'Horizontal step Lxy (as programmed)': 'Waagerechter Bahnabstand Lxy (wie programmiert)',
    'Step-down dz (as programmed)': 'Z-Zustellung dz (wie programmiert)',
  },
  finish: {
    'Finish: the feed marks the teeth leave': 'Oberfläche: die Vorschubmarken der Schneiden',
    'Scallop h (across the feed)': 'Rautiefe h (quer zum Vorschub)',
    'Feed marks hf (along the CC path)': 'Vorschubmarken hf (entlang der Kontaktbahn)',
    'Ra (across the feed)': 'Ra (quer zum Vorschub)',
    'Sa (areal)': 'Sa (flächenhaft)',
    'Feed period': 'Vorschubperiode',
    'Balanced feed fz* (hf = h)': 'Ausgewogener Vorschub fz* (hf = h)',
    'use the balanced feed': 'ausgewogenen Vorschub übernehmen',
    'Download x3p': 'x3p herunterladen',
    'none: hf stays below h at every fz up to R': 'keiner: hf bleibt bei jedem fz bis R unter h',
    'Computing the feed marks and the areal parameters...':
      'Vorschubmarken und flächenhafte Kenngrößen werden berechnet …',
    'Computing the areal parameters...': 'Flächenhafte Kenngrößen werden berechnet …',
    'Areal parameters over one period cell (ISO 25178-2, no filter, the design plane as reference); straight teeth, M3. The x3p file holds that cell, 256 x 256 heights (ISO 25178-72).':
      'Flächenhafte Kenngrößen über eine Periodenzelle (ISO 25178-2, ungefiltert, Bezug ist die Sollebene); gerade Schneiden, M3. Die x3p-Datei enthält diese Zelle, 256 × 256 Höhen (ISO 25178-72).',
    'Along the CC path (y = 0), two feed periods': 'Entlang der CC-Bahn (y = 0), zwei Vorschubperioden',
    'Across the feed, one period of the passes, where the feed marks stand highest:':
      'Quer zum Vorschub, eine Periode der Bahnen, wo die Vorschubmarken am höchsten stehen:',
    'not used with a target Sa: fz is its answer': 'nicht verwendet bei Ziel-Sa: fz ist die Antwort',
    'Target Sa: the best step-over and feed per tooth': 'Ziel-Sa: der beste Bahnabstand und Zahnvorschub',
    'Step-over L': 'Bahnabstand L',
    'Feed per tooth fz': 'Zahnvorschub fz',
    'use this pair': 'dieses Paar verwenden',
    'L * fz (area per tooth)': 'L · fz (Fläche je Zahn)',
    'Sa it leaves': 'Sa, das entsteht',
    'h for this Ra': 'Rautiefe h für dieses Ra',
    'Scallop h at this L': 'Kammhöhe h bei diesem L',
    'L0 (fz -> 0: Ra = Sa)': 'L0 (fz → 0: Ra = Sa)',
    'Computing the pairs of step-over and feed per tooth that leave this Sa (a few seconds)...':
      'Die Paare aus Bahnabstand und Zahnvorschub für dieses Sa werden berechnet (einige Sekunden)…',
    'The pair with the largest L * fz (the area machined per tooth: the fastest finish at a given spindle speed) among those whose areal Sa is the target (plane, straight teeth, no runout). "use this pair" solves for the scallop height at that L with that fz, both rounded down.':
      'Das Paar mit dem größten L · fz (die je Zahn bearbeitete Fläche: das schnellste Schlichten bei gegebener Drehzahl) unter denen, deren flächenhaftes Sa das Ziel ist (Ebene, gerade Schneiden, kein Rundlauffehler). „dieses Paar verwenden“ berechnet die Kammhöhe bei diesem L mit diesem fz, beide abgerundet.',
    'Every pair that leaves this Sa: the dot is the best, the curve ends at L0 where fz -> 0':
      'Alle Paare, die dieses Sa ergeben: der Punkt ist das beste, die Kurve endet bei L0, wo fz → 0',
    "The teeth's surface (z teeth, fz per tooth, passes L apart; feed periods x pass periods shown):":
      'Die Oberfläche der Schneiden (z Schneiden, fz pro Zahn, Bahnabstand L; gezeigt Vorschubperioden × Bahnperioden):',
    'Continuous passes: the tool sweeps without teeth.':
      'Durchgehende Bahnen: das Werkzeug als Rotationskörper, ohne einzelne Schneiden.',
    'Along the feed, lengths drawn longer by': 'In Vorschubrichtung Längen gestreckt um',
  },
  tabs: {
    'Cross-feed profile': 'Profil quer zum Vorschub',
    'L against lead and tilt': 'L über Anstell- und Kippwinkel',
    'Step against slope': 'Abstand über Flächenneigung',
    'L against each radius': 'L über jedem Radius',
    "The paper's tables": 'Tabellen der Studie',
    '3D procedure, step by step': '3D-Verfahren, Schritt für Schritt',
    Formulas: 'Formeln',
    'Machined surface': 'Bearbeitete Fläche',
  },
  question: {
    ', ': ', ',
    '5-axis': '5-Achs',
    '3-axis': '3-Achs',
    lead: 'Anstellung',
    tilt: 'Kippung',
    'one-way': 'in einer Richtung',
    zigzag: 'Zickzack',
    plane: 'Ebene',
    'convex cylinder': 'konvexer Zylinder',
    'concave cylinder': 'konkaver Zylinder',
    'along the feed': 'in Vorschubrichtung',
    'across the feed': 'quer zum Vorschub',
    'curved point': 'gekrümmter Punkt',
    across: 'quer',
    straight: 'gerade',
    convex: 'konvex',
    concave: 'konkav',
    waterline: 'Z-Ebenen',
    slope: 'Neigung',
    raster: 'Zeilenwinkel',
    'flat floor': 'ebener Boden',
  },
  errors: DE_ERRORS,
  sheet: DE_SHEET,
  said: {
    noScallopPlane: (d) =>
      `Kein Kamm: ein Schaftfräser ohne Anstell- und Kippwinkel liegt flach auf der Ebene und hinterlässt bei keinem Bahnabstand bis zu seinem Durchmesser einen Kamm, also L = 2R = ${d} für jedes h.`,
    copied: (v, u, q) => `${v} (${u}) kopiert${q === null ? '' : `: ${q}`}.`,
    copyFailed: (v, u) => `Kopieren nicht möglich: den Wert markieren und von Hand kopieren (${v} ${u}).`,
    empty: 'leer',
    restarted: (who, restarts) => {
      const subject = who === 'results' ? 'Der Rechner' : 'Der Rechner der Lehransichten';
      return restarts === null
        ? [`${subject} wurde neu gestartet (`, '). Ihre letzte Anfrage wurde erneut gesendet.']
        : [
            `${subject} hat nach ${restarts} Neustarts in Folge aufgehört (`,
            `): ${who === 'results' ? 'die gezeigten Zahlen sind' : 'die Ansichten sind'} veraltet und so markiert. Eine beliebige Eingabe ändern, um es erneut zu versuchen.`,
          ];
    },
    linkReplaced: 'Einige Werte des Links wurden ersetzt: ',
    ruleOfThumb: (ra, pct) => `Faustregel Ra ~ h/4 = ${ra}: ${pct} % gegenüber dem exakten Ra.`,
    diameterShare: (pct) => `L = ${pct} % des Werkzeugdurchmessers`,
    revolution:
      'Rz, Ra und Rq werden hier nicht angegeben: Z-Ebenen auf einer Rotationsfläche ändern ihren Abstand von Ebene zu Ebene, daher hat das Profil keine Periode, über die sie zu messen wären; die Rautiefe h ist die Antwort.',
    preset: (d, r, tool) =>
      `D${d}, ${r === null ? 'Kugelfräser' : `Eckenradius R${r}`}${tool === null ? '' : ` (Werkzeug ${tool} der Studie)`}`,
    custom: 'eigene Werte',
    metric: 'metrisch (mm)',
    catalogueTools: (units) => `Katalogwerkzeuge (${units})`,
    reason: (kind) =>
      kind === 'failed'
        ? 'der Löser ist fehlgeschlagen'
        : kind === 'threw'
          ? 'im Löser ist ein unerwarteter Fehler aufgetreten'
          : kind === 'load'
            ? 'der Löser wurde nicht geladen'
            : 'der Löser antwortet nicht mehr',
    notAvailable: 'nicht berechenbar',
    cylinderMeaning: (side, r, axis) =>
      axis === 'feed'
        ? `Auf diesem ${side === 'convex' ? 'konvexen' : 'konkaven'} Zylinder (Radius ${r}, Achse in Vorschubrichtung: die Bahnen laufen entlang der Achse) sind L und die Flankenbreiten Bogenlängen auf der Fläche zwischen den CC-Bahnen, und jede Höhe wird radial vom Zylinder aus gemessen.`
        : `Auf diesem ${side === 'convex' ? 'konvexen' : 'konkaven'} Zylinder (Radius ${r}, Achse quer zum Vorschub: die Bahnen laufen um ihn herum und rücken entlang der Achse vor) werden L und die Flankenbreiten entlang der Achse gemessen, jede Höhe radial vom Zylinder aus.`,
    curvedMeaning: ([fs, fr], [cs, cr]) =>
      `An diesem doppelt gekrümmten Punkt (Rf ${fs === 'convex' ? 'konvex' : 'konkav'} ${fr} in Vorschubrichtung, Rc ${cs === 'convex' ? 'konvex' : 'konkav'} ${cr} quer dazu) sind L und die Flankenreichweiten Bogenlängen entlang der Fläche quer zum Vorschub zwischen den CC-Bahnen, und jede Höhe wird radial in der Querebene durch den Kontaktpunkt gemessen.`,
    sideBox: (label) => `${label}: konvex, konkav oder gerade`,
    linkText: 'Link zu diesem Zustand',
    targetNotOffered: (symbol) =>
      `Ein Ziel-${symbol} wird bei der 3-Achs-Bearbeitung nicht angeboten: bitte die Rautiefe h angeben.`,
    surfacePresets: {
      custom: 'eigene Radien',
      dome: 'Kuppel (in beiden Richtungen konvex)',
      bowl: 'Schale (in beiden Richtungen konkav)',
      saddle: 'Sattel (längs konvex, quer konkav)',
      sphere: 'Kugel (Rc = Rf, konvex)',
      'cylinder-along': 'Zylinder, Achse in Vorschubrichtung (Rf gerade)',
      'cylinder-across': 'Zylinder, Achse quer zum Vorschub (Rc gerade)',
      plane: 'Ebene (in beiden Richtungen gerade)',
      boss: 'Zapfen (rundum konvex, gerade Mantellinie)',
      fillet: 'Taschenverrundung (konkav, Rc der kleinere)',
    },
    rasterNote:
      'Zeilen auf einer geneigten Ebene: Flächenneigung und Zeilenwinkel bestimmen den Anstell- und den Kippwinkel des Werkzeugs im Kontaktpunkt.',
    tableWorker: (gaveUp, reason) =>
      gaveUp
        ? `Keine Tabelle: ihr Rechenprozess hat aufgegeben (${reason}). Klicken, um es erneut zu versuchen.`
        : `Der Rechenprozess der Tabelle wurde neu gestartet (${reason}); sie wird erneut berechnet …`,
    tableComputing: 'Die Tabelle wird im Rechenprozess berechnet …',
    tableSaved: (file, rows, h, unit, axes, empty) =>
      `${file} gespeichert: ${rows} Zeilen, h ${h[0]} bis ${h[1]} ${unit} × ${
        axes.kind === 'five-axis'
          ? `Anstellwinkel ${axes.lead[0]} bis ${axes.lead[1]}° × Kippwinkel ${axes.tilt[0]} bis ${axes.tilt[1]}°`
          : `Flächenneigung ${axes.slope[0]} bis ${axes.slope[1]}°, der programmierte Abstand (${axes.step}) in jeder Zeile`
      }; ${empty} Zellen außerhalb des gültigen Bereichs bleiben leer, der Grund steht in der Spalte error.`,
  },
  threeAxis: DE_THREE_AXIS,
  chart: DE_CHART,
  slope: DE_SLOPE,
  radius: DE_RADIUS,
  finishText: DE_FINISH,
  surface: DE_SURFACE,
  profile: DE_PROFILE,
  procedures: DE_PROCEDURES,
  linkNotices: DE_LINK_NOTICES,
  stepper: DE_STEPPER,
  formulas: DE_FORMULAS,
  tables: DE_TABLES,
  curved: (e, state) => curvedMessageIn(catalogue, DE_CURVED, e, state),
  radiusField: (key, text, value) => radiusFieldIn(catalogue, DE_CURVED, key, text, value),
  scene: sceneWordsIn(
    'de',
    ' (Bogenlänge)',
    '3D-Ansicht des Werkzeugs in seiner Anstellung, der benachbarten Bahnen und der Kammschnitte',
    {
      designPlane: 'Sollebene',
      designSurface: 'Sollfläche',
      hPlane: 'h-Pseudoebene',
      hSurface: 'h-Pseudofläche',
      cusp: 'Kamm',
      converged: 'P_hp (konvergiert)',
      best: 'bestes P_hp[i]',
      single: 'einziger Kontakt',
      xAxis: 'X (Vorschub)',
      scale: (k) => (k === null ? 'Höhen maßstäblich' : `Höhen ${k}-fach überhöht (bis 2h über der Ebene)`),
      scaleTitle: (k) =>
        k === null
          ? 'Alle Längen und Höhen sind maßstäblich gezeichnet.'
          : `Damit der Kamm sichtbar wird, sind Höhen von der Ebene bis zur doppelten Rautiefe ${k}-fach überhöht gezeichnet, das Werkzeug darüber maßstäblich. Nur die Zeichnung: jede Zahl ist die des Lösers.`,
    },
  ),
  viewNotes: {
    curved: {
      tables: 'Die Tabellen der Studie gelten für deren eigene Bedingungen, auf einer Ebene',
      stepper: 'Das Verfahren der Studie, Schritt für Schritt, löst eine Ebene oder einen Zylinder',
      formulas: 'Die Formeln der Studie gelten für eine Ebene oder einen Zylinder',
      surface: 'Die Simulation der bearbeiteten Fläche läuft auf einer Ebene oder einem Zylinder',
    },
    curvedAnswered:
      'Diesen doppelt gekrümmten Punkt beantworten die Ergebnisse oben, das Profil (sein Schnitt quer zum Vorschub) und das Diagramm „L über jedem Radius“.',
    question: (slope, psi) => `Neigung ${slope}°, ${psi === null ? 'Z-Ebenen' : `Zeilenwinkel ${psi}°`}`,
    tables:
      'Die Tabellen der Studie: deren eigene 5-Achs-Bedingungen (Anstellung auf einer Ebene), zum Nachschlagen; sie sind nicht die 3-Achs-Frage am Bildschirm.',
    revolution: (q) =>
      `Z-Ebenen auf einer Rotationsfläche (${q}) ändern ihren Abstand von Ebene zu Ebene; diese Ansicht zeichnet kongruente Bahnen und hat hier nichts zu zeichnen: das Diagramm „Abstand über Flächenneigung“ und die 3D-Szene zeigen sie.`,
    equivalent: (q, lead, tilt, surface) =>
      `Das senkrechte Werkzeug bei ${q} ist das Werkzeug mit Anstellwinkel ${lead}°, Kippwinkel ${tilt}° auf einer Ebene, in einer Richtung: ${surface ? 'seine Bahnen im Koordinatensystem der Ebene simuliert.' : 'im Koordinatensystem der Ebene gezeichnet (Längen entlang der Ebene, h entlang ihrer Normalen).'}`,
  },
};
