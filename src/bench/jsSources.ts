/**
 * Where the shipped JavaScript's bytes come from: builds the production site with source maps (into
 * test-results/js-sources, dist/ untouched) and attributes each chunk's minified bytes to the source
 * files its map names. Per chunk, the top sources by an estimated gzip share: the chunk's gzip size
 * times that source's text gzipped alone over the sum of all its sources' texts gzipped alone (gzip
 * is not additive; the estimate ranks, the chunk totals are exact). "(unmapped)" is text the map
 * names no source for: three.js's shader strings, Rolldown's helpers and cross-chunk imports.
 * Every .js file the build emits is listed (as bench:web counts them, src/bench/chunks.ts): a file
 * with no source map (the service worker, embed.js, a helper chunk Vite writes without one) counts
 * whole as "(no source map)".
 *
 *   npm run bench:js-sources            top 12 sources per chunk
 *   npm run bench:js-sources -- --top 40
 */
import { fileURLToPath } from 'node:url';
import { gzipSync } from 'node:zlib';
import { build } from 'vite';
import { siteFiles } from './siteFiles';

const BASE64 = 'ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/';

/**
 * The segments of a source map's `mappings` (version 3), per generated line: each segment's
 * generated column and, when it has one, its source index (absolute, the VLQ deltas summed).
 */
export function decodeMappings(mappings: string): Array<Array<{ column: number; source: number | null }>> {
  const lines: Array<Array<{ column: number; source: number | null }>> = [];
  let source = 0;
  for (const line of mappings.split(';')) {
    const segments: Array<{ column: number; source: number | null }> = [];
    let column = 0;
    for (const text of line.split(',')) {
      if (text === '') continue;
      const fields: number[] = [];
      let value = 0;
      let shift = 0;
      for (const ch of text) {
        const digit = BASE64.indexOf(ch);
        value += (digit & 31) << shift;
        if (digit & 32) shift += 5;
        else {
          fields.push(value & 1 ? -(value >>> 1) : value >>> 1);
          value = 0;
          shift = 0;
        }
      }
      column += fields[0] ?? 0;
      if (fields.length > 1) source += fields[1] ?? 0;
      segments.push({ column, source: fields.length > 1 ? source : null });
    }
    lines.push(segments);
  }
  return lines;
}

/** A chunk's text split by source file (each segment's text up to the next segment goes to its source). */
export function textBySource(code: string, map: { mappings: string; sources: string[] }): Map<string, string> {
  const out = new Map<string, string>();
  const add = (source: string, text: string) => out.set(source, (out.get(source) ?? '') + text);
  const lines = code.split('\n');
  decodeMappings(map.mappings).forEach((segments, i) => {
    const line = lines[i] ?? '';
    let from = 0;
    let owner = '(unmapped)';
    for (const s of segments) {
      add(owner, line.slice(from, s.column));
      from = s.column;
      owner = s.source === null ? '(unmapped)' : (map.sources[s.source] ?? '(unmapped)');
    }
    add(owner, `${line.slice(from)}\n`);
  });
  return out;
}

/** Source map v3, the fields read here. */
interface SourceMap {
  mappings: string;
  sources: string[];
}

/** A chunk's text by source file ({@link textBySource}); all of it "(no source map)" when it has no map. */
export function chunkSources(code: string, map: SourceMap | null): Map<string, string> {
  return map === null ? new Map([['(no source map)', code]]) : textBySource(code, map);
}

const gzip = (text: string | Buffer) => gzipSync(text, { level: 9 }).length;
const kB = (bytes: number) => (bytes / 1024).toFixed(1);

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const topArg = process.argv.indexOf('--top');
  const top = topArg > 0 ? Number(process.argv[topArg + 1]) : 12;
  const root = fileURLToPath(new URL('../..', import.meta.url));
  const outDir = `${root}test-results/js-sources`;
  await build({ root, logLevel: 'warn', build: { outDir, emptyOutDir: true, sourcemap: true } });
  const files = siteFiles(outDir);
  const text = (path: string) => new TextDecoder().decode(files.get(path));
  let total = 0;
  for (const name of [...files.keys()].filter((p) => p.endsWith('.js')).sort()) {
    // Without the map's comment, so that the sizes are those of the production build (no maps).
    const code = text(name).replace(/\n\/\/# sourceMappingURL=\S+\s*$/, '\n');
    const chunkGzip = gzip(code);
    total += chunkGzip;
    const map = files.has(`${name}.map`) ? (JSON.parse(text(`${name}.map`)) as SourceMap) : null;
    const parts = [...chunkSources(code, map)].map(([source, part]) => ({
      source: source.replace(/^(\.\.\/)+/, '').replace(root.replace(/^\//, ''), ''),
      raw: part.length,
      alone: gzip(part),
    }));
    const aloneSum = parts.reduce((sum, p) => sum + p.alone, 0);
    console.log(`\n${name}: ${kB(chunkGzip)} kB gzip, ${kB(code.length)} kB raw`);
    for (const p of parts.sort((a, b) => b.alone - a.alone).slice(0, top))
      console.log(
        `  ~${kB((chunkGzip * p.alone) / aloneSum).padStart(6)} kB gzip ${kB(p.raw).padStart(7)} kB raw  ${p.source}`,
      );
  }
  console.log(`\nevery .js file: ${kB(total)} kB gzip`);
}
