/**
 * The page's notices (one status box): link values replaced, a worker restarted or given up.
 * Field messages are written by the core's describeInputError (see request.ts).
 */
import { MAX_CONSECUTIVE_RESTARTS, type RestartInfo } from '../worker/client';

export class Notice {
  private timer: ReturnType<typeof setTimeout> | null = null;
  /** Who the message on screen is about, when it lasts only while that holds (clear). */
  private owner: string | null = null;

  constructor(private readonly box: HTMLElement) {}

  /**
   * Shows a message, for `ms` milliseconds (0: until replaced). `owner` names what it is about (a
   * worker that gave up), so clear(owner) takes it away once that no longer holds.
   */
  show(message: string, ms: number, owner: string | null = null): void {
    this.box.textContent = message;
    this.box.hidden = false;
    this.owner = owner;
    if (this.timer !== null) clearTimeout(this.timer);
    this.timer = ms > 0 ? setTimeout(() => this.hide(), ms) : null;
  }

  /** Hides the message on screen if `owner` showed it (its worker answers again); others stay. */
  clear(owner: string): void {
    if (this.owner === owner && !this.box.hidden) this.hide();
  }

  hide(): void {
    if (this.timer !== null) clearTimeout(this.timer);
    this.timer = null;
    this.owner = null;
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
