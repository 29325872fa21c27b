/**
 * CSV per RFC 4180, streaming: a reader fed chunk by chunk that never holds more than one record
 * (bounded by a size limit), and the writer's quoting with a guard against spreadsheet formulas.
 * Pure (no I/O).
 *
 * Reader: fields are separated by commas, records by LF, CRLF or CR. A field in double quotes may
 * hold commas, line breaks and doubled quotes (`""`); spaces or tabs around a quoted field are
 * ignored. A record that breaks the rules (a quote inside an unquoted field, text after a closing
 * quote, a quote never closed, more characters than the limit) is still returned, once, with its
 * `error`; the next record starts cleanly after it.
 */

/** One record of the input. */
export interface CsvRecord {
  /** The fields, unquoted; empty when the record was too long (its text was not kept). */
  readonly fields: string[];
  /** Line (1-based) on which the record starts. */
  readonly line: number;
  /** What was wrong with the record's syntax, or null. */
  readonly error: string | null;
  /** True for an empty or whitespace-only line: no field, no quote. */
  readonly blank: boolean;
}

/**
 * Default limit on the characters of one record: 1 MiB (1,048,576 characters, the line break that
 * ends it not counted; a line break inside a quoted field is).
 */
export const MAX_RECORD_CHARS = 1 << 20;

enum State {
  /** At the start of a field (only spaces or tabs so far). */
  FieldStart = 0,
  /** Inside an unquoted field. */
  Unquoted = 1,
  /** Inside a quoted field. */
  Quoted = 2,
  /** A quote inside a quoted field: the closing quote, or the first of a doubled one. */
  QuoteInQuoted = 3,
  /** After a closing quote (only spaces or tabs may follow before the separator). */
  AfterQuoted = 4,
}

/**
 * Streaming RFC 4180 reader. `push` each decoded chunk and `end` once; each returns the records
 * completed so far. Memory is bounded by `maxRecordChars` whatever the input.
 */
export class CsvReader {
  private readonly maxRecordChars: number;
  private fields: string[] = [];
  private field = '';
  private state = State.FieldStart;
  private quoted = false;
  private recordChars = 0;
  private oversized = false;
  private error: string | null = null;
  private line = 1;
  private recordLine = 1;
  private quoteLine = 1;
  /** The previous chunk ended with CR: a leading LF belongs to the same line break. */
  private pendingCr = false;
  /** Inside a quoted field, the previous character was CR (CRLF counts as one line). */
  private crInQuoted = false;
  private started = false;
  private bomChecked = false;

  constructor(maxRecordChars: number = MAX_RECORD_CHARS) {
    this.maxRecordChars = maxRecordChars;
  }

  /** Reads one chunk; returns the records it completed. */
  push(chunk: string): CsvRecord[] {
    const out: CsvRecord[] = [];
    let text = chunk;
    if (!this.bomChecked && text.length > 0) {
      this.bomChecked = true;
      if (text.charCodeAt(0) === 0xfeff) text = text.slice(1);
    }
    const n = text.length;
    let i = 0;
    if (this.pendingCr && n > 0) {
      this.pendingCr = false;
      if (text.charCodeAt(0) === 10) i = 1;
    }
    // Start of the run of ordinary characters not yet added to `field`.
    let runStart = i;
    const flushRun = (end: number) => {
      if (end > runStart && !this.oversized) this.field += text.slice(runStart, end);
    };
    for (; i < n; i++) {
      const c = text.charCodeAt(i);
      if (!this.started) {
        this.started = true;
        this.recordLine = this.line;
      }
      // The line break that ends a record is not one of its characters (one inside quotes is):
      // a record of exactly the limit is read whether a line break or the end of input follows.
      const endsRecord = (c === 10 || c === 13) && this.state !== State.Quoted;
      if (!endsRecord) this.recordChars++;
      if (this.recordChars > this.maxRecordChars && !this.oversized) {
        this.oversized = true;
        this.fields = [];
        this.field = '';
      }
      switch (this.state) {
        case State.FieldStart:
        case State.Unquoted:
          if (c === 44 /* , */) {
            flushRun(i);
            this.endField();
            runStart = i + 1;
          } else if (c === 10 || c === 13) {
            flushRun(i);
            out.push(this.endRecord());
            i = this.lineBreakEnd(text, i, c);
            runStart = i + 1;
          } else if (c === 34 /* " */) {
            flushRun(i);
            if (this.state === State.FieldStart) {
              // Spaces before a quoted field are not part of it.
              this.field = '';
              this.state = State.Quoted;
              this.quoted = true;
              this.quoteLine = this.line;
              this.crInQuoted = false;
            } else {
              this.fail('a quote inside an unquoted field (quote the whole field and double the quote)');
              if (!this.oversized) this.field += '"';
            }
            runStart = i + 1;
          } else if (this.state === State.FieldStart && c !== 32 && c !== 9) {
            this.state = State.Unquoted;
          }
          break;
        case State.Quoted:
          if (c === 34) {
            flushRun(i);
            this.state = State.QuoteInQuoted;
            runStart = i + 1;
          } else if (c === 13 || (c === 10 && !this.crInQuoted)) {
            this.line++;
          }
          this.crInQuoted = c === 13;
          break;
        case State.QuoteInQuoted:
          if (c === 34) {
            // A doubled quote stands for one quote.
            if (!this.oversized) this.field += '"';
            this.state = State.Quoted;
            runStart = i + 1;
            break;
          }
          this.state = State.AfterQuoted;
          i--; // read this character again after the closing quote (and count it once)
          if (!endsRecord) this.recordChars--;
          runStart = i + 1;
          break;
        case State.AfterQuoted:
          if (c === 44) {
            this.endField();
            runStart = i + 1;
          } else if (c === 10 || c === 13) {
            out.push(this.endRecord());
            i = this.lineBreakEnd(text, i, c);
            runStart = i + 1;
          } else if (c !== 32 && c !== 9) {
            this.fail('text after the closing quote of a field');
            this.state = State.Unquoted;
            runStart = i;
          } else runStart = i + 1;
          break;
      }
    }
    if (this.state !== State.QuoteInQuoted && this.state !== State.AfterQuoted) flushRun(n);
    return out;
  }

  /** Ends the input; returns the last record if the input did not end with a line break. */
  end(): CsvRecord[] {
    if (!this.started) return [];
    if (this.state === State.Quoted) {
      this.fail(`a quoted field opened on line ${this.quoteLine} is never closed`);
    }
    return [this.endRecord()];
  }

  private fail(message: string): void {
    if (this.error === null) this.error = message;
  }

  private endField(): void {
    if (!this.oversized) this.fields.push(this.field);
    this.field = '';
    this.state = State.FieldStart;
  }

  /**
   * After a record ended at the line break `c` (CR or LF) at `i`: counts the line and returns the
   * break's last index (a CR LF pair is one break; a CR last in the chunk waits for the next one).
   */
  private lineBreakEnd(text: string, i: number, c: number): number {
    this.line++;
    if (c !== 13) return i;
    if (i + 1 < text.length) return text.charCodeAt(i + 1) === 10 ? i + 1 : i;
    this.pendingCr = true;
    return i;
  }

  private endRecord(): CsvRecord {
    this.endField();
    const blank = this.fields.length === 1 && !this.quoted && this.error === null && isBlank(this.fields[0] as string);
    const error = this.oversized ? `the record is longer than ${this.maxRecordChars} characters: not read` : this.error;
    const record: CsvRecord = { fields: this.oversized ? [] : this.fields, line: this.recordLine, error, blank };
    this.fields = [];
    this.quoted = false;
    this.recordChars = 0;
    this.oversized = false;
    this.error = null;
    this.started = false;
    return record;
  }
}

function isBlank(text: string): boolean {
  return text.trim() === '';
}

/** Reads a whole text at once (tests and small inputs). */
export function parseCsv(text: string, maxRecordChars: number = MAX_RECORD_CHARS): CsvRecord[] {
  const reader = new CsvReader(maxRecordChars);
  return [...reader.push(text), ...reader.end()];
}

export { csvField, csvText, isNumberText } from '../core/output/csvWrite';
