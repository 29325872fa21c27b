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
import { FreshJob, type Shown } from './freshness';
import type { Unit } from './state';

/** What draws the simulation (the view, loaded with the other views' code). */
export interface SurfaceDisplay {
  /** `progress`: the fraction done of the simulation of the inputs on screen, when it reported one. */
  show(shown: Shown<SimulateReply>, unit: Unit, progress: number | null): void;
}

export class SimulationLoader {
  private readonly client: SimulateClient;
  /** Asks only while the view is open (setOpen). */
  private readonly job: FreshJob<SimulateReply>;
  private unit: Unit = 'mm';
  private progress: number | null = null;
  private display: SurfaceDisplay | null = null;

  /**
   * `onRestart`: the simulation's worker was restarted or gave up; `onAnswer`: it answered (it
   * works again after a give-up).
   */
  constructor(onRestart: (info: RestartInfo<SolveRequest>) => void, onAnswer: () => void = () => undefined) {
    this.job = new FreshJob<SimulateReply>({ ask: (request) => this.client.request(request), open: false });
    this.client = new SimulateClient({
      onReply: (reply) => {
        onAnswer();
        // Stopped without a newer request (never expected): no answer, so it is asked again.
        if (!reply.ok && reply.cancelled) this.job.sync();
        else if (this.job.receive(reply)) this.progress = null;
        this.draw();
      },
      onRestart: (info) => {
        if (info.gaveUp) this.job.gaveUp(info.request);
        onRestart(info);
        this.draw();
      },
      onProgress: (request, fraction) => {
        if (!sameRequest(request, this.job.request) || this.job.shown.kind === 'current') return;
        this.progress = fraction;
        this.draw();
      },
    });
  }

  /** The inputs changed: the request they ask (null when invalid) and the unit to show. */
  want(request: SolveRequest | null, unit: Unit): void {
    if (!sameRequest(request, this.job.request)) this.progress = null;
    this.unit = unit;
    this.job.want(request);
    this.draw();
  }

  /** The view opened or closed: the simulation runs only while it is open. */
  setOpen(open: boolean): void {
    this.job.setOpen(open);
  }

  attach(display: SurfaceDisplay): void {
    this.display = display;
    this.draw();
  }

  get workerStarts(): number {
    return this.client.started;
  }

  private draw(): void {
    this.display?.show(this.job.shown, this.unit, this.progress);
  }
}
