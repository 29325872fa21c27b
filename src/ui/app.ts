/**
 * The calculator page: wires the parts together and holds the one state (the fields as typed).
 * Each change of state goes one way: state -> request (request.ts: validated, in mm) -> the
 * workers; each reply comes back through a Freshness check and is drawn only if it answers the
 * inputs on screen. The parts: fields.ts (inputs), urlState.ts (address bar), messages.ts
 * (notices), results.ts (headline and table), teaching.ts (views loading), highlight.ts, and the
 * 3D scene (render/scene.ts).
 */

import { FIELDS } from '../core/input/fields';
import type { PassPattern } from '../core/input/validate';
import type { ProcedureKey } from '../core/procedures/procedures';
import type { CameraPreset, ToolScene } from '../render/scene';
import type { RestartInfo } from '../worker/client';
import { equivalentPlaneRequest } from '../worker/equivalentPlane';
import { isSolveRequest, type PageReply, type PageRequest, type ThreeAxisReply } from '../worker/pageProtocol';
import type { SolveMode } from '../worker/protocol';
import { solveClient } from '../worker/workers';
import { browserStorage } from './browserStorage';
import { applyProcedureColours } from './colours';
import { wireCopyButtons } from './copy';
import { wireCopyLink } from './copyLink';
import { must } from './dom';
import { RESULT_VIEW, startResultCard } from './embedCard';
import { postHeightToParent } from './embedResize';
import { listenForHostTheme } from './embedTheme';
import { FieldsPanel } from './fields';
import { finishInputs, finishKeyMessages, LazyFinish } from './finishLazy';
import { FreshJob } from './freshness';
import { Highlighter } from './highlight';
import { langOf } from './i18n/langOf';
import { localize } from './i18n/words';
import { LazyButton } from './lazyButton';
import { LazyToolShelf } from './lazyToolShelf';
import { plainLengths } from './lengthFields';
import { linkNotice, Notice, restartMessage } from './messages';
import { stateMessages } from './pageMessages';
import { readPreferences, withPreferences, writePreferences } from './preferences';
import { PresentMode, parsePresent } from './present';
import { buildPageRequest, pageModeKind } from './questionRequest';
import { questionWords } from './questionWords';
import type { BuiltRequest, PageFieldError } from './requestTypes';
import { ResultBar } from './resultBar';
import { type QuestionKind, ResultsPanel } from './results';
import { RoughnessPanel } from './roughness';
import type { ToolStorage } from './savedTools';
import { sceneOfReply } from './sceneLabels';
import { SceneSlot } from './sceneSlot';
import { SimulationLoader } from './simulation';
import {
  type CalculatorState,
  convertState,
  type FieldKey,
  fieldInMm,
  parseField,
  parseUrl,
  type Target,
  type ToolSize,
  toSearch,
  type Unit,
  withField,
  withSize,
  withValues,
} from './state';
import { withCurvedPreset } from './surfaceState';
import type { TargetSaPanel } from './targetSaPanel';
import { TeachingLoader } from './teaching';
import { onThemeChange, setThemeOverride, startTheme } from './theme';
import { parseTheme } from './themeChoice';
import { TypingGate } from './typing';
import { UrlState } from './urlState';
import type { ViewId } from './views/panel';

/** The teaching views' ids, as the link's `view=` names them (the field registry's; here, so the views' code can load lazily). */
/** A three-axis question's build while its builder loads (app.ts loadThreeAxis): no request yet, no message. */
const NOT_LOADED = (): BuiltRequest => ({ ok: false, errors: [] });
/** No three-axis wording while it loads (no three-axis reply can be on screen then). */
const NONE = (): PageFieldError[] => [];

const VIEW_IDS = FIELDS.view.values.filter((v): v is ViewId => v !== RESULT_VIEW);

/** Observes the page from outside (the e2e build's probe); the page itself needs none. */
export interface AppObserver {
  /** A reply to the inputs on screen was drawn. */
  resultShown?(): void;
  /** The 3D scene drew a frame; `current` when results and scene answer the inputs on screen. */
  frame?(current: boolean): void;
  /** The page built a request (once per input: issue 27 point 4). */
  built?(): void;
}

export class CalculatorApp {
  private state: CalculatorState;
  private readonly fields: FieldsPanel;
  private readonly url: UrlState;
  private readonly notice: Notice;
  private readonly results: ResultsPanel;
  /** The headline kept in view on a phone while a field has focus (resultBar.ts). */
  private readonly resultBar: ResultBar;
  /** Embedded with view=result: the compact card (embedCard.ts), which loads no 3D scene. */
  private readonly resultCard: boolean;
  /** The 3D scene, built after the first result (its code and WebGL context load then). */
  private readonly scene: SceneSlot<ToolScene>;
  private readonly sceneBox: HTMLElement;
  private readonly lookup: LazyButton;
  private readonly sheet: LazyButton;
  private readonly teaching: TeachingLoader | null;
  private readonly roughness: RoughnessPanel;
  /** The feed marks and areal finish (finishLazy.ts). */
  private readonly finish: LazyFinish;
  /** The best (L, fz) pair for a target Sa (targetSaPanel.ts): loaded with the first target Sa. */
  private targetSa: Promise<TargetSaPanel> | null = null;
  private readonly simulation: SimulationLoader;
  private readonly client = solveClient({
    onReply: (reply) => {
      this.notice.clear('results');
      if (!this.fresh.receive(reply)) return;
      // The worker's refusal of a text still being typed (a gouging radius half typed, 2 on the way
      // to 25) is held back as the page's own errors are (typing.ts): said at the pause.
      if (!reply.ok && this.typedKey !== null) {
        this.fields.rangeSliders(reply.limits, false);
        this.holdTyped(this.state, this.typedKey, this.built);
        return;
      }
      // A refusal only the worker finds (gouging, a limit of h, L or Ra, a three-axis limit): its
      // messages go on the fields and the parts beyond the results let the question go. A
      // three-axis answer on a sloped plane gives the simulation its plane question (follow).
      const follows = !reply.ok || reply.request.mode === 'three-axis';
      // The sliders' limits come with the reply, answer or refusal (the page solves nothing).
      this.fields.rangeSliders(reply.limits, !follows);
      if (follows) this.follow();
      this.draw();
    },
    onRestart: (info) => this.restarted('results', info),
  });
  /** The results: asked of the solver whenever no reply answers the inputs on screen. */
  private readonly fresh = new FreshJob<PageReply>({ ask: (request) => this.client.request(request) });
  /** Holds a half-typed text back until a pause or a commit (typing.ts): then its request, built at the key press, is asked. */
  private readonly typing = new TypingGate(() => this.change(this.state, this.held));
  /** The request of the text held back (built once, at its key press; the gate holds no other state). */
  private held: BuiltRequest = { ok: false, errors: [] };
  /** The field a text was typed into whose question is asked but not yet answered (null: none). */
  private typedKey: FieldKey | null = null;
  /** The field messages of the last committed state (kept while typing, so none flashes). */
  private messages: ReadonlyMap<FieldKey, string> = new Map();
  /** The finish worker's messages on the teeth-and-feed fields that answer the inputs on screen. */
  private finishMessages: ReadonlyMap<FieldKey, string> = new Map();

  /** The target-Sa box's place. */
  private readonly saBox: HTMLElement;
  /** The target-Sa worker's messages on the teeth fields that answer the inputs on screen. */
  private saMessages: ReadonlyMap<FieldKey, string> = new Map();

  /** The fields' messages: the page's and the solver's, then the finish and target-Sa workers' where a field has none. */
  private fieldMessages(): ReadonlyMap<FieldKey, string> {
    if (this.finishMessages.size + this.saMessages.size === 0) return this.messages;
    const all = new Map([...this.finishMessages, ...this.saMessages]);
    for (const [key, message] of this.messages) all.set(key, message);
    return all;
  }
  /** The last committed state's request, or its errors (built once per change). */
  private built: BuiltRequest = { ok: false, errors: [] };
  /**
   * Three-axis machining's builder and wording (threeAxisRequest.ts), loaded with the first
   * three-axis question rather than with the first result; null until then.
   */
  private threeAxis: typeof import('./threeAxisRequest') | null = null;
  /** Whether that load is on its way. */
  private threeAxisLoading = false;
  /** Where the machine and unit are remembered (preferences.ts); null in an embed or without storage. */
  private readonly storage: ToolStorage | null;
  /** The question's words of the number on screen (questionWords.ts), or null beside a dash. */
  private answeredWords: string | null = null;
  /** The reply and unit the scene shows. */
  private sceneDrawn: { reply: PageReply; unit: Unit } | null = null;

  constructor(
    root: HTMLElement,
    private readonly observer: AppObserver = {},
  ) {
    applyProcedureColours(document.documentElement);
    // The address as the visit began (the URL is rewritten from the state once the inputs settle).
    const linkSearch = window.location.search;
    const parsed = parseUrl(linkSearch);
    const embed = parsed.embed;
    // A bare visit starts on the machine and unit chosen last time; a link or an embed as it says.
    this.storage = embed ? null : browserStorage();
    const remembered = readPreferences(this.storage);
    this.state = withPreferences(parsed.state, parsed.bare, remembered);
    const requested = VIEW_IDS.find((v) => v === parsed.view);
    const extra: Record<string, string> = {};
    document.documentElement.classList.toggle('embed', embed);
    document.documentElement.classList.toggle('single-view', embed && requested !== undefined);
    document.documentElement.dataset.view = requested ?? '';
    this.resultCard = startResultCard(root, embed && parsed.view === RESULT_VIEW, this.state);
    if (this.resultCard) extra[FIELDS.view.url] = RESULT_VIEW;
    if (embed) extra[FIELDS.embed.url] = '1';
    if (requested) extra[FIELDS.view.url] = requested;
    const theme = parseTheme(linkSearch);
    // The link's language stays in the address from the first write on (the language's code loads later).
    const linkedLang = langOf(new URLSearchParams(linkSearch).get(FIELDS.lang.url));
    if (linkedLang !== null) extra[FIELDS.lang.url] = linkedLang;
    startTheme(theme);
    if (theme.override) extra[FIELDS.theme.url] = theme.override;
    // Presentation mode: the full page's only (an embed ignores it); in the URL while on.
    const present = embed ? { on: false, notice: null } : parsePresent(parsed.present);
    this.url = new UrlState(
      present.on ? { ...extra, [FIELDS.present.url]: FIELDS.present.values[0] } : extra,
      root.querySelector<HTMLAnchorElement>('[data-testid="open-full"]'),
    );
    this.present = new PresentMode(
      must(root, '[data-testid="present-toggle"]'),
      must(root, '[data-testid="present-inputs"]'),
      { changed: (on) => this.url.setExtra(FIELDS.present.url, on ? FIELDS.present.values[0] : null) },
    );
    this.present.set(present.on);
    this.notice = new Notice(must(root, '[data-testid="notice"]'));
    this.results = new ResultsPanel(root);
    this.resultBar = new ResultBar(root);
    this.roughness = new RoughnessPanel(root);
    this.finish = new LazyFinish(
      root.querySelector<HTMLElement>('[data-testid="finish-results"]'),
      (fields) => this.change(withValues(this.state, fields)),
      (messages) => {
        this.finishMessages = messages;
        this.fields.render(this.state, this.fieldMessages());
      },
    );
    this.saBox = must(root, '[data-testid="target-sa-results"]');
    this.simulation = new SimulationLoader(
      (info) => this.restarted('simulation', info),
      () => this.notice.clear('simulation'),
    );
    // The lookup table's download and the shop sheet: their code loads on their first press.
    const tableStatus = must<HTMLElement>(root, '[data-testid="download-table-status"]');
    this.lookup = new LazyButton(must(root, '[data-testid="download-table"]'), (button) =>
      import('./lookupDownload').then(({ LookupDownload }) => new LookupDownload(button, tableStatus)),
    );
    this.sheet = new LazyButton(must(root, '[data-testid="shop-sheet"]'), (button) =>
      import('./shopSheet').then(({ ShopSheetPanel }) => new ShopSheetPanel(button)),
    );
    const sceneBox = must<HTMLElement>(root, '.scene');
    this.sceneBox = sceneBox;
    this.scene = new SceneSlot(() => import('../render/scene').then(({ ToolScene }) => new ToolScene(sceneBox)));
    this.sceneSection = must(root, '.view');
    this.scene.onFrame = () => this.observer.frame?.(this.fresh.shown.kind === 'current');
    this.scene.run('theme', (s) => s.applyTheme());
    onThemeChange(() => this.scene.run('theme', (s) => s.applyTheme()));
    if (embed) {
      // The host's theme changes restyle the page in place; the address keeps the theme in force.
      listenForHostTheme((override) => {
        setThemeOverride(override);
        if (override === null) delete extra[FIELDS.theme.url];
        else extra[FIELDS.theme.url] = override;
        // The URL state keeps its own copy of the page settings: tell it (it writes the address at once).
        this.url.setExtra(FIELDS.theme.url, override);
      });
      postHeightToParent(root);
    }
    // "Copy embed code": its code loads on the first press (not with the first result), which it then copies.
    const embedButton = must<HTMLButtonElement>(root, '[data-testid="copy-embed"]');
    const embedCodeNow = (code: (pageUrl: string, search: string) => string) =>
      code(
        `${window.location.origin}${window.location.pathname}`,
        toSearch(plainLengths(this.state), {
          ...extra,
          [FIELDS.view.url]: this.teaching?.activeView ?? requested ?? 'profile',
        }),
      );
    embedButton.addEventListener(
      'click',
      () =>
        void import('./embedCode').then(({ embedCode, wireCopyEmbed }) => {
          wireCopyEmbed(embedButton, must(root, '[data-testid="copy-embed-status"]'), () => embedCodeNow(embedCode));
          embedButton.click();
        }),
      { once: true },
    );
    this.fields = new FieldsPanel(root, {
      onField: (key, text, typing) => this.edit(key, withField(this.state, key, text), typing),
      // A committed field shows the plain number a written length (1/2", 12.7 mm) means.
      onCommit: () => {
        this.typedKey = null;
        const plain = plainLengths(this.state);
        // A text held back was built at its key press (plain lengths: the same request).
        if (this.typing.release()) this.change(plain, this.held);
        else if (plain !== this.state) this.change(plain);
      },
      onSize: (size: ToolSize) => this.change(withSize(plainLengths(this.state), size)),
      onMode: (mode: SolveMode) => this.change({ ...this.state, mode }),
      onUnit: (unit: Unit) => this.change(convertState(plainLengths(this.state), unit)),
      onPattern: (pattern: PassPattern) => this.change({ ...this.state, pattern }),
      onTarget: (target: Target) => this.change({ ...this.state, target }),
      // A doubly curved point chosen with both radii straight starts as a dome.
      onSurface: (surface) =>
        this.change(
          surface === 'curved' && this.state.feedSide === 'straight' && this.state.crossSide === 'straight'
            ? withCurvedPreset({ ...this.state, surface }, 'dome')
            : { ...this.state, surface },
        ),
      onMachine: (machine) => this.change({ ...this.state, machine }),
      onPasses: (passes) => this.change({ ...this.state, passes }),
      onSide: (key, side) => this.change({ ...this.state, [key === 'Rf' ? 'feedSide' : 'crossSide']: side }),
      onSurfacePreset: (preset) => this.change(withCurvedPreset(this.state, preset, this.state.machine === '3axis')),
      onSurfaceAxis: (surfaceAxis) => this.change({ ...this.state, surfaceAxis }),
      onPreset: (p, unit) =>
        this.change(
          withValues(unit ? convertState(plainLengths(this.state), unit) : this.state, { R: p.R, Rcr: p.Rcr }),
        ),
    });
    // A first visit (no unit chosen yet on this device) offers the tools of both units (toolChips.ts).
    this.fields.chips?.offerBothUnits(this.storage !== null && parsed.bare && remembered.unit === null);
    this.shelf = new LazyToolShelf(must(root, '[data-testid="tool-shelf"]'), {
      // A library tool's flutes (a Fusion 360 NOF) give the teeth of the finish.
      onTool: (t) =>
        this.change({
          ...withValues(this.state, {
            R: t.diameterMm / 2,
            Rcr: t.cornerRadiusMm,
            ...(t.flutes === null ? {} : { z: t.flutes }),
          }),
          toolName: t.name,
        }),
      onUnit: (unit) => this.change(convertState(plainLengths(this.state), unit)),
      current: () => {
        const plain = plainLengths(this.state);
        const r = fieldInMm(plain, 'R');
        return { diameterMm: typeof r === 'number' ? 2 * r : r, cornerRadiusMm: fieldInMm(plain, 'Rcr') };
      },
    });
    wireCopyLink(must(root, '[data-testid="copy-link"]'), must(root, '[data-testid="copy-link-status"]'), () => {
      const view = this.teaching?.activeView;
      const search = toSearch(plainLengths(this.state), view ? { [FIELDS.view.url]: view } : {});
      return `${window.location.origin}${window.location.pathname}${search}`;
    });
    // An embedded calculator without a teaching view shows none: no views, no views' worker.
    this.teaching =
      embed && requested === undefined
        ? null
        : new TeachingLoader({
            root: must(root, '[data-testid="teaching"]'),
            display: { showTraceFrame: (frame) => this.scene.run('trace', (s) => s.showTraceFrame(frame)) },
            initialView: requested ?? 'profile',
            reveal: !embed && requested !== undefined,
            onLoadCondition: (c) =>
              this.change(
                withValues({ ...this.state, mode: 'forward', pattern: 'one-way', surface: 'plane' }, { ...c, tilt: 0 }),
              ),
            onRestart: (info) => this.restarted('views', info),
            onAnswer: () => this.notice.clear('views'),
            surface: this.simulation,
          });
    const highlighter = new Highlighter(root, (key: ProcedureKey | null) => this.teaching?.highlight(key));
    this.highlighter = highlighter;
    for (const button of root.querySelectorAll<HTMLButtonElement>('[data-camera]'))
      button.addEventListener('click', () =>
        this.scene.run('camera', (s) => s.setCamera(button.dataset.camera as CameraPreset)),
      );
    wireCopyButtons(root, must(root, '[data-testid="copy-status"]'), () => questionWords(this.state));
    const notices = [...parsed.notices];
    if (parsed.view !== null && requested === undefined && !this.resultCard)
      notices.push(`view="${parsed.view}" is not one of ${VIEW_IDS.join(', ')}.`);
    if (theme.notice !== null) notices.push(theme.notice);
    if (present.notice !== null) notices.push(present.notice);
    if (notices.length > 0) this.notice.show(linkNotice(notices), 0);
    this.change(this.state);
    // The language (issue 30): the switch's code loads after the first answer is asked (English, the
    // page as written, needs nothing), a catalogue when its language is chosen; then the words code
    // writes are redrawn.
    void import('./i18n/language').then(({ startLanguage }) =>
      startLanguage(
        root,
        this.storage,
        {
          changed: () => {
            // The request built anew (the page's own messages are worded as it is built), the fields'
            // messages worded anew (follow), the table drawn anew, then the results.
            this.built = this.build(this.state);
            // The scene drawn anew too (its labels' words).
            this.sceneDrawn = null;
            this.results.invalidate();
            this.follow();
            this.draw();
            this.teaching?.relabel();
          },
          link: (lang) => this.url.setExtra(FIELDS.lang.url, lang),
          notice: (text) => this.notice.show(linkNotice([text]), 0),
        },
        linkSearch,
      ),
    );
  }

  private readonly highlighter: Highlighter;
  /** Presentation mode (present.ts): the scene and the open view fill the window. */
  private readonly present: PresentMode;
  /** Saved tools and imported tool libraries. */
  private readonly shelf: LazyToolShelf;
  /** The 3D view's section (marked `cylinder` while the scene shows one: its legend follows). */
  private readonly sceneSection: HTMLElement;

  /** Read by the e2e build's probe (and handy in a debugger). */
  get diagnostics() {
    return {
      frames: () => this.scene.frames,
      softwareRendering: () => this.scene.softwareRendering,
      activeView: () => this.teaching?.activeView ?? null,
      workerStarts: () => this.client.started,
      sceneFraming: () => this.scene.peek()?.framing() ?? null,
    };
  }

  /**
   * The state's request, or its errors: the page's one builder (questionRequest.ts), once per input.
   * A three-axis question asked before its builder has loaded is no request yet (no message, no
   * number): the load is started, and the state on screen is built again when it is in.
   */
  private build(state: CalculatorState): BuiltRequest {
    this.observer.built?.();
    const plain = plainLengths(state);
    if (this.threeAxis === null && pageModeKind(plain) === 'threeAxis') this.loadThreeAxis();
    return buildPageRequest(plain, this.threeAxis?.buildThreeAxisRequest ?? NOT_LOADED);
  }

  /** Loads the three-axis builder, then builds the state on screen again (a failed load is tried again by the next change). */
  private loadThreeAxis(): void {
    if (this.threeAxisLoading) return;
    this.threeAxisLoading = true;
    import('./threeAxisRequest').then(
      (loaded) => {
        this.threeAxis = loaded;
        // A text held back is asked at its pause with the request built now; else the state is asked.
        if (this.typing.holding) this.held = this.build(this.state);
        else this.change(this.state);
      },
      () => {
        this.threeAxisLoading = false;
      },
    );
  }

  /**
   * A field edited: a slider's value, or a typed text that makes a valid question, changes the
   * state at once; a typed text that does not (half-typed, or wrong) is held back until a pause or
   * a commit, meanwhile every number is a dash marked "typing" and no message changes but the
   * typed field's own, which is cleared.
   */
  private edit(key: FieldKey, state: CalculatorState, typing: boolean): void {
    const built = this.build(state);
    if (!typing || built.ok) {
      this.typing.release();
      this.change(state, built);
      // A typed text asked at once: the worker's refusal of it waits for the pause (onReply).
      if (typing) this.typedKey = key;
      return;
    }
    this.holdTyped(state, key, built);
  }

  /**
   * Holds a typed text back until a pause or a commit (its request `built`, asked then if valid):
   * every number a dash marked "typing", no message changed but the typed field's own, cleared.
   */
  private holdTyped(state: CalculatorState, key: FieldKey, built: BuiltRequest): void {
    this.typedKey = null;
    this.typing.hold();
    this.held = built;
    this.state = state;
    this.fresh.want(null);
    const kept = new Map(this.fieldMessages());
    kept.delete(key);
    this.fields.render(state, kept);
    this.teaching?.want(null, state.unit, true);
    this.simulation.want(null, state.unit);
    this.lookup.want(null, state.unit);
    this.sheet.want(null, state.unit);
    this.draw();
  }

  /**
   * The one way the state changes: ask the solver first, then draw the fields, write the URL.
   * `built` is the state's request when the caller built it already (one build per input).
   */
  private change(state: CalculatorState, built: BuiltRequest = this.build(state)): void {
    this.typing.release();
    this.typedKey = null;
    this.state = state;
    this.built = built;
    // Asked (unless answered already) before any drawing, so the worker solves while the page draws.
    this.fresh.want(built.ok ? built.request : null);
    this.follow();
    this.draw();
    // The question and the link read written lengths (1/2", 12.7 mm) as plain numbers.
    this.url.write(plainLengths(state));
    writePreferences(this.storage, state);
  }

  /**
   * The fields' messages and the parts beyond the results, from the state's request and the reply
   * to it: a request the worker refused is no question for them (its messages are on the fields).
   */
  private follow(): void {
    const state = this.state;
    const shown = this.fresh.shown;
    const reply = shown.kind === 'current' ? shown.reply : null;
    const request = this.built.ok && reply?.ok !== false ? this.built.request : null;
    this.messages = stateMessages(plainLengths(state), this.built, reply, this.threeAxis?.threeAxisFieldErrors ?? NONE);
    this.fields.render(state, this.fieldMessages());
    this.shelf.render(state.unit);
    // The simulation and the table answer a plane's or a cylinder's question (five-axis); the views
    // draw any (those that do not draw a doubly curved or three-axis question say so).
    // A sloped plane machined three-axis is simulated as the plane at its equivalent posture.
    const classic =
      request !== null && isSolveRequest(request)
        ? request
        : reply?.ok && reply.request.mode === 'three-axis'
          ? equivalentPlaneRequest(reply as ThreeAxisReply)
          : null;
    this.teaching?.want(request, state.unit, false);
    this.simulation.want(classic, state.unit);
    // The lookup table: a plane's, a cylinder's, a doubly curved point's or three-axis machining's.
    this.lookup.want(request, state.unit);
    // The shop sheet: any valid question (its tool, posture, pattern and surface; three-axis by slope).
    this.sheet.want(request, state.unit);
  }

  /** Draws the results and the scene from what answers the inputs on screen. */
  private draw(): void {
    const shown = this.fresh.shown;
    const tilt = parseField(this.state.fields.tilt);
    const typing = this.typing.holding;
    this.results.render(shown, this.state.unit, this.state.mode, tilt, typing, {
      kind: this.kind(),
      passes: this.state.passes,
      saTarget: this.state.mode === 'forward' && this.state.target === 'sa',
    });
    this.results.showToolName(this.state.toolName ?? null);
    // The words of the question whose number is on screen: the current answer's, or, while a new
    // one is on its way (the old numbers shown, marked out of date), the old answer's; none
    // beside a dash (typing, invalid, refused).
    if (typing || shown.kind === 'invalid' || (shown.kind === 'current' && !shown.reply.ok)) this.answeredWords = null;
    else if (shown.kind === 'current') this.answeredWords = questionWords(this.state);
    else if (shown.last === null || !shown.last.ok) this.answeredWords = null;
    this.results.showQuestion(this.answeredWords);
    this.roughness.render(shown, this.state.unit);
    // The results and roughness rows drawn (in English): in the language in force, once, before the
    // result bar mirrors the headline.
    localize(document);
    this.resultBar.render(typing);
    this.sceneBox.classList.toggle('typing', typing);
    // The finish (issue 29): the answer on screen's feed marks, loaded with the first teeth and feed.
    const answered = shown.kind === 'current' && !typing ? shown.reply : null;
    // Written lengths (`1/500`, `0.002"`, `5 um`) read as the plain numbers they mean, as every field's.
    const plain = plainLengths(this.state);
    this.finish.show(plain, answered);
    // A target Sa (issue 29): its best pair, asked of the answer on screen (the target Ra at Ra = Sa);
    // the box's code loads with the first target Sa (each show runs in order, once it has).
    const sa = this.state.mode === 'forward' && this.state.target === 'sa';
    const inputs = finishInputs(plain);
    if (sa && this.targetSa === null)
      this.targetSa = import('./targetSaPanel').then(
        ({ TargetSaPanel }) =>
          new TargetSaPanel(
            this.saBox,
            // "use this pair": solve for the scallop height at its L, with its fz (the finish box then answers).
            ({ L, fz }) => this.change(withValues({ ...this.state, mode: 'inverse' }, { L, fz })),
            (errors) => {
              this.saMessages = finishKeyMessages(errors);
              this.fields.render(this.state, this.fieldMessages());
            },
          ),
      );
    void this.targetSa?.then((panel) => panel.show(inputs, answered, sa));
    this.highlighter.markRows();
    // The first answer (or the first error) is on screen: now the scene may take its time to load.
    if (shown.kind !== 'pending' && !this.resultCard) this.scene.load();
    const scene = shown.kind === 'current' ? sceneOfReply(shown.reply, this.state.unit) : null;
    if (shown.kind !== 'current' || scene === null) {
      this.scene.run('stale', (s) => s.setStale(true));
      // A three-axis answer with nothing to draw (no scallop): the results stand alone.
      if (shown.kind === 'current' && shown.reply.ok) this.observer.resultShown?.();
      return;
    }
    const reply = shown.reply;
    const unit = this.state.unit;
    this.scene.run('stale', (s) => s.setStale(false));
    if (this.sceneDrawn?.reply !== reply || this.sceneDrawn.unit !== unit) {
      this.sceneDrawn = { reply, unit };
      const cylinder = scene.curvedLegend;
      this.sceneSection.classList.toggle('cylinder', cylinder);
      for (const e of this.sceneSection.querySelectorAll<HTMLElement>('.legend .plane-only, .legend .cylinder-only'))
        e.hidden = e.classList.contains('plane-only') === cylinder;
      this.scene.run('update', (s) => s.update(scene.geometry, scene.labels));
    }
    this.observer.resultShown?.();
  }

  /** The kind of question the inputs on screen ask. */
  private kind(): QuestionKind {
    if (this.state.machine === '3axis') return 'three-axis';
    return this.state.surface === 'curved' && this.state.feedSide !== 'straight' && this.state.crossSide !== 'straight'
      ? 'curved'
      : 'classic';
  }

  private restarted(who: 'results' | 'views' | 'simulation', info: RestartInfo<PageRequest>): void {
    if (who === 'results') {
      if (info.gaveUp) this.fresh.gaveUp(info.request);
      this.draw();
    }
    // A give-up stays on screen until that worker answers again (notice.clear above).
    this.notice.show(
      restartMessage(who === 'results' ? who : 'views', info),
      info.gaveUp ? 0 : 5000,
      info.gaveUp ? who : null,
    );
  }
}
