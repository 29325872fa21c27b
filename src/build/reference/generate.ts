/**
 * `npm run reference`: writes the reference data set (public/reference/scallop-reference.csv and its JSON
 * description) from the seeded strata (strata/index.ts): each proposed row is answered by the
 * calculator (answer.ts), rows it refuses in a valid stratum or answers with a non-finite number are
 * left out and counted, then the independent reference is computed, and a row whose reference lies
 * beyond its bound of the answer (or whose polished reference lies beyond the sampled brute force's
 * bound) is left out, printed and counted: the run ends with exit code 1 if there is any, so a
 * disagreement is never published. Deterministic: the same code gives the same bytes.
 */
import { mkdirSync, writeFileSync } from 'node:fs';
import { csvNumber } from '../../core/output/csvWrite.ts';
import { calculatorAnswer } from './answer.ts';
import {
  calculatorToleranceMm,
  REFERENCE_COLUMNS,
  REFERENCE_CSV,
  REFERENCE_METHODS,
  REFERENCE_SEED,
  REFERENCE_VERSION,
  type ReferenceRow,
} from './columns.ts';
import { csvOf, REFERENCE_CSV_PATH, REFERENCE_DIR, REFERENCE_JSON_PATH, sha256Of } from './dataset.ts';
import type { Draft } from './draft.ts';
import { seededRandom } from './oracles/bruteForce.ts';
import { STRATA } from './strata/index.ts';

const text = (v: number | string | undefined): string =>
  v === undefined ? '' : typeof v === 'number' ? csvNumber(v) : v;

/** Per stratum: rows kept, rows left out and why, the largest |answer - reference| and its ratio to the bound. */
interface Tally {
  rows: number;
  refused: number;
  nonFinite: number;
  disagreeing: number;
  referenceFailed: number;
  worstDeviationMm: number;
  worstDeviationOverBound: number;
}

const started = performance.now();
const rows: ReferenceRow[] = [];
const tallies = new Map<string, Tally>();
const problems: string[] = [];
const notes: string[] = [];
/** Optional: `npm run reference -- <stratum prefix> [count]` runs one stratum (not written), for a look. */
const only = process.argv[2];
const countOverride = process.argv[3] === undefined ? undefined : Number(process.argv[3]);

STRATA.forEach((stratum, index) => {
  if (only !== undefined && !stratum.name.startsWith(only)) return;
  const t0 = performance.now();
  const rand = seededRandom(REFERENCE_SEED + index);
  const invalid = stratum.name.startsWith('invalid');
  for (const draft of stratum.drafts(rand, countOverride ?? stratum.count) as Iterable<Draft>) {
    const tally = tallies.get(draft.stratum) ?? {
      rows: 0,
      refused: 0,
      nonFinite: 0,
      disagreeing: 0,
      referenceFailed: 0,
      worstDeviationMm: 0,
      worstDeviationOverBound: 0,
    };
    tallies.set(draft.stratum, tally);
    const cells: Record<string, string> = { stratum: draft.stratum, mode: draft.mode, quantity: draft.quantity };
    for (const [k, v] of Object.entries(draft.inputs)) cells[k] = text(v);
    const answer = calculatorAnswer(cells);
    if (answer.ok === invalid) {
      tally.refused += 1;
      if (invalid) problems.push(`${draft.stratum}: accepted ${JSON.stringify(draft.inputs)}`);
      continue;
    }
    let answerMm = Number.NaN;
    if (answer.ok) {
      if (!Number.isFinite(answer.valueMm)) {
        tally.nonFinite += 1;
        continue;
      }
      answerMm = answer.valueMm;
      cells.answer = csvNumber(answerMm);
    } else {
      cells.errorCode = answer.code;
      cells.errorField = answer.field;
      if (answer.limit !== null) {
        answerMm = answer.limit;
        cells.answer = csvNumber(answer.limit);
      }
    }
    let ref: ReturnType<Draft['reference']>;
    try {
      ref = draft.reference(answerMm);
    } catch (e) {
      tally.referenceFailed += 1;
      notes.push(`${draft.stratum}: reference failed (${(e as Error).message}) on ${JSON.stringify(cells)}`);
      continue;
    }
    if (ref !== null) {
      const R = Number(cells.R);
      const bound = ref.uncertaintyMm + calculatorToleranceMm(Number.isFinite(R) ? R : 1);
      const deviation = Math.abs(answerMm - ref.valueMm);
      const sampledOff =
        ref.sampledMm !== undefined && !(Math.abs(ref.sampledMm - ref.valueMm) <= (ref.sampledBoundMm as number));
      const detail = `${JSON.stringify(cells)}: answer ${answerMm}, reference ${ref.valueMm} (bound ${bound}), sampled ${ref.sampledMm} +- ${ref.sampledBoundMm}`;
      if (sampledOff) {
        // The polished reference contradicts its own sampled start: the reference failed, not the calculator.
        tally.referenceFailed += 1;
        notes.push(`${draft.stratum}: polished reference outside the sampled bound, ${detail}`);
        continue;
      }
      if (!(deviation <= bound)) {
        tally.disagreeing += 1;
        problems.push(`${draft.stratum}: disagreement, ${detail}`);
        continue;
      }
      tally.worstDeviationMm = Math.max(tally.worstDeviationMm, deviation);
      tally.worstDeviationOverBound = Math.max(tally.worstDeviationOverBound, deviation / bound);
      Object.assign(cells, {
        reference: csvNumber(ref.valueMm),
        referenceUncertainty: csvNumber(ref.uncertaintyMm),
        bound: csvNumber(bound),
        method: ref.method,
        sampled: ref.sampledMm === undefined ? '' : csvNumber(ref.sampledMm),
        sampledBound: ref.sampledBoundMm === undefined ? '' : csvNumber(ref.sampledBoundMm),
      });
    }
    tally.rows += 1;
    rows.push(cells);
  }
  console.log(`${stratum.name}: ${((performance.now() - t0) / 1000).toFixed(1)} s`);
});

rows.forEach((row, i) => {
  (row as Record<string, string>).id = String(i + 1);
});
const csv = csvOf(rows);
const strata = Object.fromEntries(
  [...tallies].map(([name, t]) => [
    name,
    {
      rows: t.rows,
      leftOut: {
        refused: t.refused,
        nonFinite: t.nonFinite,
        referenceFailed: t.referenceFailed,
        disagreeing: t.disagreeing,
      },
      worstDeviationMm: t.worstDeviationMm,
    },
  ]),
);
const description = {
  name: 'path-interval scallop reference',
  version: REFERENCE_VERSION,
  description:
    "Step-over, scallop height and roughness of a filleted (bull-nose) end mill: each row the inputs, the calculator's answer, an independent reference value of the same quantity and the bound within which they agree; refused inputs with their error code and limit.",
  generatedBy: 'npm run reference (src/build/reference/generate.ts)',
  seed: REFERENCE_SEED,
  csv: REFERENCE_CSV,
  sha256: sha256Of(csv),
  rows: rows.length,
  conventions:
    'Lengths in mm, angles in degrees. Frame at the cutter contact: X the feed, Z the surface normal, Y = Z x X; the tool axis (cos(tilt) sin(rho), sin(tilt), cos(tilt) cos(rho)). Scallop heights along the surface normal (radially on curved surfaces); step-overs between cutter-contact paths, as arc length on curved surfaces. Numbers are the shortest decimal text that reads back to the same double.',
  columns: REFERENCE_COLUMNS,
  methods: REFERENCE_METHODS,
  strata,
};
if (only === undefined) {
  mkdirSync(REFERENCE_DIR, { recursive: true });
  writeFileSync(REFERENCE_CSV_PATH, csv);
  writeFileSync(REFERENCE_JSON_PATH, `${JSON.stringify(description, null, 2)}\n`);
}
for (const [name, t] of tallies)
  console.log(
    `${name.padEnd(34)} ${String(t.rows).padStart(5)} rows  worst |answer - reference| ${t.worstDeviationMm.toExponential(2)} mm (${t.worstDeviationOverBound.toExponential(2)} of the bound)  left out: ${t.refused} refused, ${t.nonFinite} non-finite, ${t.referenceFailed} reference failed, ${t.disagreeing} disagreeing`,
  );
console.log(
  `${rows.length} rows in ${((performance.now() - started) / 1000).toFixed(1)} s${only === undefined ? `, written to ${REFERENCE_DIR}` : ' (not written: one stratum only)'}`,
);
for (const p of notes) console.error(`note: ${p}`);
for (const p of problems) console.error(p);
if (problems.length > 0) process.exitCode = 1;
