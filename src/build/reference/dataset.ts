/**
 * The reference data set's files: where they are, how a row becomes a CSV line and back, and the
 * SHA-256 that the JSON description states. Used by the generator and by the check.
 */
import { createHash } from 'node:crypto';
import { fileURLToPath } from 'node:url';
import { parseCsv } from '../../cli/csv.ts';
import { csvField } from '../../core/output/csvWrite.ts';
import { COLUMN_NAMES, REFERENCE_CSV, REFERENCE_JSON, type ReferenceRow } from './columns.ts';

/** The package's public/reference/ folder (also served by the site at reference/) (shipped as `path-interval/reference`). */
export const REFERENCE_DIR = fileURLToPath(new URL('../../../public/reference/', import.meta.url));
export const REFERENCE_CSV_PATH = `${REFERENCE_DIR}${REFERENCE_CSV}`;
export const REFERENCE_JSON_PATH = `${REFERENCE_DIR}${REFERENCE_JSON}`;

/** The CSV text of rows: the header, then one line per row, LF line ends, a final LF. */
export function csvOf(rows: readonly ReferenceRow[]): string {
  const lines = [COLUMN_NAMES.join(',')];
  for (const row of rows) lines.push(COLUMN_NAMES.map((name) => csvField(row[name] ?? '')).join(','));
  return `${lines.join('\n')}\n`;
}

/** The rows of a CSV text written by {@link csvOf}; throws on a header or record that does not fit. */
export function rowsOf(text: string): ReferenceRow[] {
  const records = parseCsv(text).filter((r) => !r.blank);
  const header = records[0];
  if (header === undefined || header.fields.join(',') !== COLUMN_NAMES.join(','))
    throw new Error(`unexpected header: ${header?.fields.join(',')}`);
  return records.slice(1).map((r) => {
    if (r.error !== null || r.fields.length !== COLUMN_NAMES.length)
      throw new Error(`line ${r.line}: ${r.error ?? `${r.fields.length} fields`}`);
    return Object.fromEntries(COLUMN_NAMES.map((name, i) => [name, r.fields[i] as string]));
  });
}

/** SHA-256 of a text (UTF-8), hexadecimal. */
export function sha256Of(text: string): string {
  return createHash('sha256').update(text, 'utf8').digest('hex');
}
