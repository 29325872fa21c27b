/**
 * The page's notices (one status box): link values replaced, a worker restarted or given up.
 * Field messages are written by the core's describeInputError (see request.ts).
 */
import { MAX_CONSECUTIVE_RESTARTS, type RestartInfo } from '../worker/client';

export class Notice {
  private timer: ReturnType<typeof setTimeout> | null = null;

  constructor(private readonly box: HTMLElement) {}

  /** Shows a message, for `ms` milliseconds (0: until replaced). */
  show(message: string, ms: number): void {
    this.box.textContent = message;
    this.box.hidden = false;
    if (this.timer !== null) clearTimeout(this.timer);
    this.timer = ms > 0 ? setTimeout(() => this.hide(), ms) : null;
  }

  hide(): void {
    if (this.timer !== null) clearTimeout(this.timer);
    this.timer = null;
    this.box.hidden = true;
  }
}

/** What to say when a worker restarts or gives up. */
export function restartMessage(who: 'results' | 'views', info: RestartInfo): string {
  const subject = who === 'results' ? 'The solver' : "The teaching views' solver";
  if (info.gaveUp) {
    const shown = who === 'results' ? 'the numbers shown are' : 'the views are';
    return `${subject} stopped after ${MAX_CONSECUTIVE_RESTARTS} restarts in a row (${info.reason}): ${shown} out of date, marked stale. Change any input to try again.`;
  }
  return `${subject} was restarted: ${info.reason}. Your last request was sent again.`;
}

/** The notice for link values that were replaced by defaults. */
export function linkNotice(notices: readonly string[]): string {
  return `Some link values were replaced: ${notices.join(' ')}`;
}
