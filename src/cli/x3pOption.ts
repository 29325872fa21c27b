/**
 * `--x3p FILE` (issue 29): the areal surface the teeth leave, written as an ISO 25178-72 x3p file
 * (core/output/x3p.ts) over a whole number of period cells, on the notes' grid (sample i at
 * x = (i + 1/2) dx; shared/notes/surface-finish.md), so that metrology software computing Sa on
 * it without levelling or filtering gets the sampled value of the definition. `--x3p-size NX,NY`
 * (default 1024,1024) and `--x3p-cells CX,CY` (default 1,1) set the grid. Pure but for the caller's
 * write: the bytes and the facts the report names.
 */
import type { PassPattern, ToolInput } from '../core/domain/tool';
import { arealMap } from '../core/finish/arealMap';
import type { FinishInput } from '../core/finish/finishInput';
import { toothModel } from '../core/finish/toothModel';

/** The x3p writer, loaded by {@link loadX3pWriter} (its zip library builds tables at load: ~8 ms). */
let writer: typeof import('../core/output/x3p') | null = null;

/**
 * Loads the x3p writer before an `--x3p` question is answered, so that a command line without
 * `--x3p` starts without the zip library (the compiled bundle initialises it only here).
 */
export async function loadX3pWriter(): Promise<void> {
  writer ??= await import('../core/output/x3p');
}

/** The grid's default size, points along x (the feed) and y (across). */
export const X3P_DEFAULT_SIZE = [1024, 1024] as const;
/** The largest number of points along an axis (a 8192 x 8192 grid is 512 MB of heights). */
export const X3P_MAX_POINTS = 8192;
/** The largest number of cells along an axis. */
export const X3P_MAX_CELLS = 1000;

/** A pair `A,B` of whole numbers from 1 to `max`, or the one-line reason it is not. */
export function readPair(
  option: string,
  text: string | undefined,
  fallback: readonly [number, number],
  max: number,
): { ok: true; value: readonly [number, number] } | { ok: false; error: string } {
  if (text === undefined) return { ok: true, value: fallback };
  const m = /^\s*(\d{1,9})\s*[,x]\s*(\d{1,9})\s*$/i.exec(text);
  const a = m === null ? Number.NaN : Number(m[1]);
  const b = m === null ? Number.NaN : Number(m[2]);
  if (!(a >= 1 && a <= max && b >= 1 && b <= max)) {
    const shown = text.length > 40 ? `${text.slice(0, 37)}...` : text;
    const example = option === 'x3p-cells' ? '2,2' : '512,256';
    return {
      ok: false,
      error: `--${option} must be two whole numbers from 1 to ${max}, as ${example} (got "${shown}")`,
    };
  }
  return { ok: true, value: [a, b] };
}

/** What a written x3p holds, as the report names it (lengths mm). */
export interface X3pFacts {
  readonly nx: number;
  readonly ny: number;
  readonly cellsX: number;
  readonly cellsY: number;
  readonly dxMm: number;
  readonly dyMm: number;
}

/**
 * The x3p bytes of the surface `tool` leaves with `finish`, passes `intervalMm` apart: `size`
 * points over `cells` period cells; the comment names the question.
 */
export function x3pOfFinish(
  tool: ToolInput,
  pattern: PassPattern,
  intervalMm: number,
  finish: FinishInput,
  size: readonly [number, number],
  cells: readonly [number, number],
  comment: string,
): { bytes: Uint8Array; facts: X3pFacts } {
  if (writer === null) throw new Error('the x3p writer is not loaded (loadX3pWriter)');
  const m = toothModel({ tool, pattern, intervalMm, finish });
  const map = arealMap(m, size[0], size[1], cells[0], cells[1]);
  const bytes = writer.x3pBytes(
    {
      nx: map.nx,
      ny: map.ny,
      dxMm: map.dxMm,
      dyMm: map.dyMm,
      heightsMm: map.heightsMm,
      xOriginMm: map.dxMm / 2,
      yOriginMm: map.dyMm / 2,
    },
    { comment },
  );
  return {
    bytes,
    facts: { nx: map.nx, ny: map.ny, cellsX: cells[0], cellsY: cells[1], dxMm: map.dxMm, dyMm: map.dyMm },
  };
}
