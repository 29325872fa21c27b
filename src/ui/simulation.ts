/**
 * The Machined surface view's data: the `simulate` job, asked only while the view is open, for
 * the inputs on screen (latest wins: a new input stops the running simulation). Its replies pass
 * the same Freshness check as the results; the view draws exactly what `shown` says, with the
 * progress of the simulation under way.
 */
import type { RestartInfo } from '../worker/client';
import { type SolveRequest, sameRequest } from '../worker/protocol';
import type { SimulateReply } from '../worker/simulate';
import { SimulateClient } from '../worker/simulateClient';
import { Freshness, type Shown } from './freshness';
import type { Unit } from './state';

/** What draws the simulation (the view, loaded with the other views' code). */
export interface SurfaceDisplay {
  /** `progress`: the fraction done of the simulation of the inputs on screen, when it reported one. */
  show(shown: Shown<SimulateReply>, unit: Unit, progress: number | null): void;
}

export class SimulationLoader {
  private readonly fresh = new Freshness<SimulateReply>();
  private readonly client: SimulateClient;
  private asked: SolveRequest | null = null;
  private open = false;
  private unit: Unit = 'mm';
  private progress: number | null = null;
  private display: SurfaceDisplay | null = null;

  constructor(onRestart: (info: RestartInfo) => void) {
    this.client = new SimulateClient({
      onReply: (reply) => {
        if (!reply.ok && reply.cancelled) {
          // Stopped without a newer request (never expected): ask again when wanted.
          if (sameRequest(reply.request, this.asked)) this.asked = null;
          this.ask();
          return;
        }
        if (this.fresh.receive(reply)) this.progress = null;
        this.draw();
      },
      onRestart: (info) => {
        if (info.gaveUp) {
          this.fresh.fail();
          this.asked = null;
        }
        onRestart(info);
        this.draw();
      },
      onProgress: (request, fraction) => {
        if (!sameRequest(request, this.fresh.request) || this.fresh.shown.kind === 'current') return;
        this.progress = fraction;
        this.draw();
      },
    });
  }

  /** The inputs changed: the request they ask (null when invalid) and the unit to show. */
  want(request: SolveRequest | null, unit: Unit): void {
    if (!sameRequest(request, this.fresh.request)) this.progress = null;
    this.fresh.want(request);
    this.unit = unit;
    this.ask();
    this.draw();
  }

  /** The view opened or closed: the simulation runs only while it is open. */
  setOpen(open: boolean): void {
    this.open = open;
    this.ask();
  }

  attach(display: SurfaceDisplay): void {
    this.display = display;
    this.draw();
  }

  get workerStarts(): number {
    return this.client.started;
  }

  private ask(): void {
    const request = this.fresh.request;
    if (!this.open || request === null || this.fresh.shown.kind === 'current') return;
    if (sameRequest(request, this.asked)) return;
    this.asked = request;
    this.client.request(request);
  }

  private draw(): void {
    this.display?.show(this.fresh.shown, this.unit, this.progress);
  }
}
