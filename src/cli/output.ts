/**
 * Standard output for a Unix tool: text is gathered and written in large pieces, each write
 * awaited (backpressure), and a write error is kept rather than thrown, so the caller can stop
 * reading, end quietly on a closed pipe (EPIPE) and name any other error in one line.
 */
import type { Writable } from 'node:stream';
import { escapeControls } from '../core/input/visibleText';

/** Gathered text is written once it exceeds this many characters. */
export const FLUSH_CHARS = 1 << 16;

export class Output {
  private parts: string[] = [];
  private size = 0;
  private failure: Error | null = null;

  constructor(private readonly stream: Writable) {
    stream.on('error', (e: Error) => {
      this.failure ??= e;
    });
  }

  /** The first write error, or null. */
  get error(): Error | null {
    return this.failure;
  }

  /** Characters gathered and not yet written. */
  get pending(): number {
    return this.size;
  }

  /** Gathers text; nothing is written after an error. */
  write(text: string): void {
    if (this.failure !== null) return;
    this.parts.push(text);
    this.size += text.length;
  }

  /** Writes what was gathered and waits until the stream took it (or failed). */
  async flush(): Promise<void> {
    const data = this.parts.join('');
    this.parts = [];
    this.size = 0;
    if (this.failure !== null || data === '') return;
    await new Promise<void>((resolve) => {
      this.stream.write(data, (e) => {
        if (e) this.failure ??= e;
        resolve();
      });
    });
  }
}

/** True for the error of a reader that went away (`head -1`): not worth a message. */
export function isClosedPipe(e: Error): boolean {
  const code = (e as NodeJS.ErrnoException).code;
  return code === 'EPIPE' || code === 'ERR_STREAM_DESTROYED';
}

/** One line naming an error: its code and message, never a stack trace. */
export function describeSystemError(e: unknown): string {
  if (e instanceof Error) {
    const code = (e as NodeJS.ErrnoException).code;
    return code !== undefined && !e.message.includes(code) ? `${code}: ${e.message}` : e.message;
  }
  return String(e);
}

/** Every control character written as an escape (core/input/visibleText.ts; here for the command line's writers). */
export { escapeControls };

/**
 * The one line on stderr of an error: `error: ` and the message, control characters escaped
 * ({@link escapeControls}). Every error the command line writes goes through here.
 */
export function errorLine(message: string): string {
  return `error: ${escapeControls(message)}\n`;
}
