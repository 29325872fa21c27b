/**
 * Loading the teaching views: their code (charts, typesetting) loads after the first result, and
 * their data comes from the `teach` job on its own worker a moment after the inputs settle, so
 * they never delay the results or the 3D frame. The views are drawn only from a reply to the
 * inputs on screen; otherwise the panel is marked out of date.
 */
import type { ProcedureKey } from '../core/procedures/procedures';
import type { RestartInfo } from '../worker/client';
import { isSolveRequest, type PageRequest } from '../worker/pageProtocol';
import type { TeachReply } from '../worker/protocol';
import type { CurvedTeachReply, PageTeachReply, ThreeAxisTeachReply } from '../worker/teachProtocol';
import { teachClient } from '../worker/workers';
import { FreshJob } from './freshness';
import type { Unit } from './state';
import type { PageViewContext } from './views/common';
import type { TeachingPanel, ViewId } from './views/panel';
import type { TraceDisplay } from './views/stepperView';
import type { SurfaceSource } from './views/surfaceView';

/** The wait after the last input before the views' data is asked (a slider being dragged). */
const SETTLE_MS = 150;

export interface TeachingOptions {
  readonly root: HTMLElement;
  readonly display: TraceDisplay;
  readonly initialView: ViewId;
  readonly onLoadCondition: (c: { R: number; Rcr: number; rho: number; h: number }) => void;
  readonly onRestart: (info: RestartInfo<PageRequest>) => void;
  /** The views' worker answered (it works again after a give-up). */
  readonly onAnswer?: () => void;
  /** The Machined surface view's simulation. */
  readonly surface: SurfaceSource;
  /**
   * The link asked for a view (`?view=`): once the views are built, scroll the page to them, unless
   * the page is no longer at its top (the user scrolled, or the browser restored a position).
   */
  readonly reveal?: boolean;
}

export class TeachingLoader {
  private readonly client = teachClient({
    onReply: (reply) => {
      this.options.onAnswer?.();
      if (this.fresh.receive(reply)) this.schedule();
    },
    onRestart: (info) => {
      if (info.gaveUp) this.fresh.gaveUp(info.request);
      this.options.onRestart(info);
      this.schedule();
    },
  });
  /** Asked a moment after the inputs settle (a slider being dragged asks once it rests). */
  private readonly fresh = new FreshJob<PageTeachReply>({
    ask: (request) => this.client.request(request),
    settleMs: SETTLE_MS,
  });
  private panel: TeachingPanel | null = null;
  private loading = false;
  private drawTimer: ReturnType<typeof setTimeout> | null = null;
  private unit: Unit = 'mm';
  /** The inputs are being typed (held back, typing.ts): said instead of "invalid". */
  private typing = false;
  private highlighted: ProcedureKey | null = null;
  /** The reply and unit the views show now. */
  private drawn: { reply: PageTeachReply; unit: Unit } | null = null;

  constructor(private readonly options: TeachingOptions) {}

  /**
   * The inputs changed: the request they ask (null when invalid), and the unit to show.
   */
  want(request: PageRequest | null, unit: Unit, typing = false): void {
    this.unit = unit;
    this.typing = typing;
    this.fresh.want(request);
    this.schedule();
  }

  /** The language changed: the tabs named anew, the visible view drawn anew in its words. */
  relabel(): void {
    this.panel?.relabel();
  }

  highlight(key: ProcedureKey | null): void {
    this.highlighted = key;
    this.panel?.highlight(key);
  }

  get activeView(): ViewId | null {
    return this.panel?.activeView ?? null;
  }

  get workerStarts(): number {
    return this.client.started;
  }

  /** Draws after the current task, so a reply's message never waits on the views' drawing. */
  private schedule(): void {
    this.markStale();
    if (this.drawTimer !== null) return;
    this.drawTimer = setTimeout(() => {
      this.drawTimer = null;
      this.draw();
    }, 0);
  }

  private markStale(): void {
    const shown = this.fresh.shown;
    const text =
      shown.kind === 'current'
        ? null
        : shown.kind === 'invalid' && this.typing
          ? 'Typing: these views follow when you pause or press Enter.'
          : shown.kind === 'invalid'
            ? 'Out of date: the inputs are invalid, so these views still show the last valid inputs.'
            : shown.kind === 'failed'
              ? "Out of date: the teaching views' solver gave up; change any input to try again."
              : 'Updating: these views still show the previous inputs.';
    this.panel?.setStale(text);
  }

  private draw(): void {
    const shown = this.fresh.shown;
    if (shown.kind !== 'current') return;
    if (this.panel === null) {
      this.load();
      return;
    }
    const reply = shown.reply;
    if (this.drawn?.reply === reply && this.drawn.unit === this.unit) return;
    this.drawn = { reply, unit: this.unit };
    if (isSolveRequest(reply.request)) {
      const classic = reply as TeachReply;
      if (classic.ok) this.panel.update({ data: classic, unit: this.unit });
      else if (classic.reason !== null) this.panel.showMessage(classic.reason);
    } else {
      const page = reply as CurvedTeachReply | ThreeAxisTeachReply;
      if (page.ok) {
        const ctx: PageViewContext =
          'slope' in page
            ? { kind: 'three-axis', data: page, unit: this.unit }
            : { kind: 'curved', data: page, unit: this.unit };
        this.panel.updatePage(ctx);
      } else if (page.reason !== null) this.panel.showMessage(page.reason);
    }
    this.markStale();
  }

  /** Loads the views' code once, then draws. */
  private load(): void {
    if (this.loading) return;
    this.loading = true;
    void import('./views/panel').then(({ TeachingPanel }) => {
      const o = this.options;
      this.panel = new TeachingPanel(o.root, o.display, o.onLoadCondition, o.initialView, o.surface);
      this.panel.highlight(this.highlighted);
      this.draw();
      if (o.reveal && window.scrollY === 0) o.root.scrollIntoView({ block: 'start' });
    });
  }
}
