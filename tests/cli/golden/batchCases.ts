/**
 * The inputs of the batch golden (batchGolden.test.ts): a few hundred varied records over every
 * layout the batch reads (plane, cylinders, doubly curved points, a target Ra, a step-over L,
 * three-axis raster and waterline, columns in inches or mm, --unit inch), valid rows over the
 * domain's strata and refused ones (out of range, not a number, empty, a formula, a quoted comma or
 * line break, a control character, a wrong field count, a stray quote, CRLF, a BOM, blank lines).
 * Deterministic (mulberry32, the seed in each case's name), so `npx tsx
 * tests/cli/golden/generate.ts` writes the same inputs again; the golden stores them with the
 * outputs, so the test reads no generator.
 */
import { scallopHeightLimits } from '../../../src/core/index';
import { logUniform, pick, random, randomHeight, randomTool } from '../helpers';

/** One run of `--batch`: its extra arguments and its stdin. */
export interface BatchCase {
  readonly name: string;
  readonly args: readonly string[];
  readonly stdin: string;
}

/** A number as a person or a program may write it: full precision, fixed, exponent, padded, signed. */
function written(rand: () => number, x: number): string {
  const form = Math.floor(rand() * 8);
  if (form === 0 && Math.abs(x) >= 0.1) return x.toFixed(3);
  if (form === 1) return x.toPrecision(6);
  if (form === 2) return x.toExponential(4);
  if (form === 3) return ` ${String(x)} `;
  if (form === 4 && x > 0) return `+${String(x)}`;
  if (form === 5 && x > 0 && x < 1) return String(x).replace(/^0\./, '.');
  return String(x);
}

/** A field that no validation takes, or one that tests the CSV writer's quoting and escapes. */
const BAD_FIELDS = [
  '',
  ' ',
  'abc',
  '-1',
  '0',
  '1e999',
  'NaN',
  'Infinity',
  '=1+1',
  '@SUM(A1)',
  '"3,5"',
  '"2\n1"',
  '3\u001b[31m',
  '"say ""hi"""',
  '\t-2',
  '0x10',
  '1/0',
  '5e-324',
];

/** Columns of a record written in `order` from the values by column. */
function line(order: readonly string[], values: Readonly<Record<string, string>>): string {
  return order.map((c) => values[c] ?? '').join(',');
}

/** The header's columns in a shuffled order (each run reads its own layout). */
function shuffled(rand: () => number, columns: readonly string[]): string[] {
  const out = [...columns];
  for (let i = out.length - 1; i > 0; i--) {
    const j = Math.floor(rand() * (i + 1));
    [out[i], out[j]] = [out[j] as string, out[i] as string];
  }
  return out;
}

/** With probability `p`, one field of the record replaced by a bad one. */
function spoiled(rand: () => number, values: Record<string, string>, columns: readonly string[], p: number): void {
  if (rand() >= p) return;
  values[pick(rand, columns)] = pick(rand, BAD_FIELDS);
}

/** A valid tool and height on a plane (strata of helpers.ts), the height sometimes over the limit. */
function planeCase(rand: () => number): Record<string, string> {
  const t = randomTool(rand);
  const tool = { toolRadiusMm: t.R, cornerRadiusMm: t.Rcr, leadAngleDeg: t.rho, tiltAngleDeg: t.tilt };
  const limit = scallopHeightLimits(tool).limitMm;
  const h = rand() < 0.05 ? limit * 1.5 : randomHeight(rand, limit);
  return {
    R: written(rand, t.R),
    Rcr: t.Rcr > 0.99 * t.R ? String(t.Rcr) : written(rand, t.Rcr),
    rho: written(rand, t.rho),
    h: written(rand, h),
    tilt: rand() < 0.3 ? '' : written(rand, t.tilt),
    pattern: pick(rand, ['', 'one-way', 'zigzag', ' zigzag ', '', 'one-way', 'zigzag', 'ONE-WAY']),
  };
}

/** A shop tool in mm (R 0.5 to 12, a corner below it, a lead to 60 degrees, h to 0.1 mm). */
function shopCase(rand: () => number): Record<string, string> {
  const R = 0.5 + 11.5 * rand();
  return {
    R: written(rand, R),
    Rcr: written(rand, R * rand()),
    rho: written(rand, 60 * rand()),
    h: written(rand, logUniform(rand, 1e-4, 0.1)),
    tilt: rand() < 0.5 ? '' : written(rand, 40 * rand() - 20),
    pattern: pick(rand, ['', 'one-way', 'zigzag']),
  };
}

/** A run of `rows` records with a header of `columns` (shuffled), each from `make`, some spoiled. */
function run(
  name: string,
  seed: number,
  columns: readonly string[],
  rows: number,
  make: (rand: () => number) => Record<string, string>,
  options: {
    readonly args?: readonly string[];
    readonly spoil?: number;
    /** The header's name of a column (`R_in`), when not its own. */
    readonly rename?: Readonly<Record<string, string>>;
    /** Keep the columns in the given order. */
    readonly ordered?: boolean;
  } = {},
): BatchCase {
  const rand = random(seed);
  const order = options.ordered ? [...columns] : shuffled(rand, columns);
  const lines = [order.map((c) => options.rename?.[c] ?? c).join(',')];
  for (let i = 0; i < rows; i++) {
    const values = make(rand);
    spoiled(rand, values, columns, options.spoil ?? 0.12);
    lines.push(line(order, values));
  }
  return { name: `${name} (seed ${seed})`, args: ['--batch', ...(options.args ?? [])], stdin: `${lines.join('\n')}\n` };
}

const PLANE = ['R', 'Rcr', 'rho', 'h', 'tilt', 'pattern'];

/** Every case of the golden, in order. */
export function batchCases(): BatchCase[] {
  const cases: BatchCase[] = [];
  cases.push(run('plane, the strata of the valid domain', 2701, PLANE, 90, planeCase));
  cases.push(run('plane, shop tools', 2702, PLANE, 60, shopCase));
  cases.push(
    run('plane R,Rcr,rho,h alone, the bench rows', 2703, ['R', 'Rcr', 'rho', 'h'], 40, (rand) => ({
      R: '3',
      Rcr: '1',
      rho: String(Math.floor(rand() * 60)),
      h: (0.01 + Math.floor(rand() * 50) * 0.001).toFixed(3),
    })),
  );
  cases.push(
    run('cylinders, convex and concave, both axes', 2704, [...PLANE, 'surfaceRadius', 'surfaceAxis'], 50, (rand) => {
      const v = shopCase(rand);
      const R = Number(v.R);
      const rs = (rand() < 0.5 ? -1 : 1) * R * logUniform(rand, 0.8, 200);
      return { ...v, surfaceRadius: written(rand, rs), surfaceAxis: pick(rand, ['', 'feed', 'cross']) };
    }),
  );
  cases.push(
    run(
      'doubly curved points, one radius (a cylinder), both, or a cylinder too',
      2705,
      [...PLANE, 'feedRadius', 'crossRadius', 'surfaceRadius'],
      45,
      (rand) => {
        const v = shopCase(rand);
        const R = Number(v.R);
        const radius = () => written(rand, (rand() < 0.5 ? -1 : 1) * R * logUniform(rand, 1.5, 100));
        const which = Math.floor(rand() * 5);
        return {
          ...v,
          feedRadius: which === 1 ? '' : radius(),
          crossRadius: which === 2 ? '' : radius(),
          surfaceRadius: which === 3 ? radius() : '',
        };
      },
      { spoil: 0.1 },
    ),
  );
  cases.push(
    run(
      'a target Ra on planes and cylinders',
      2706,
      [...PLANE.filter((c) => c !== 'h'), 'Ra', 'surfaceRadius'],
      24,
      (rand) => {
        const v = shopCase(rand);
        const R = Number(v.R);
        return {
          ...v,
          Ra: written(rand, logUniform(rand, 1e-4, 0.02)),
          surfaceRadius: rand() < 0.4 ? written(rand, R * logUniform(rand, 5, 100)) : '',
        };
      },
    ),
  );
  cases.push(
    run(
      'a step-over L on planes, cylinders and doubly curved points',
      2707,
      [...PLANE.filter((c) => c !== 'h'), 'L', 'surfaceRadius', 'feedRadius', 'crossRadius'],
      40,
      (rand) => {
        const v = shopCase(rand);
        const R = Number(v.R);
        const form = Math.floor(rand() * 3);
        const rs = () => written(rand, (rand() < 0.5 ? -1 : 1) * R * logUniform(rand, 2, 100));
        return {
          ...v,
          L: written(rand, R * logUniform(rand, 0.01, 2.2)),
          surfaceRadius: form === 1 ? rs() : '',
          feedRadius: form === 2 ? rs() : '',
          crossRadius: form === 2 ? rs() : '',
        };
      },
    ),
  );
  const threeAxis = (rand: () => number): Record<string, string> => {
    const R = 0.5 + 11.5 * rand();
    const waterline = rand() < 0.4;
    const rText = String(R);
    const corner = pick(rand, ['0', rText, '', '']);
    return {
      R: rText,
      Rcr: corner === '' ? written(rand, 0.9 * R * rand()) : corner,
      h: written(rand, logUniform(rand, 1e-4, 0.1)),
      slope: written(rand, pick(rand, [0, 90, 90 * rand(), 90 * rand()])),
      passes: waterline ? 'waterline' : pick(rand, ['', 'raster']),
      rasterAngle: waterline ? pick(rand, ['', '', '90', '45']) : pick(rand, ['', written(rand, 89 * rand())]),
      feedRadius: rand() < 0.15 ? written(rand, R * logUniform(rand, 2, 100)) : '',
      crossRadius: '',
      rho: rand() < 0.05 ? '5' : '',
      tilt: rand() < 0.05 ? '3' : '',
    };
  };
  cases.push(
    run(
      'three-axis raster and waterline',
      2708,
      ['R', 'Rcr', 'h', 'slope', 'passes', 'rasterAngle', 'feedRadius', 'crossRadius', 'rho', 'tilt'],
      50,
      threeAxis,
    ),
  );
  cases.push(
    run(
      'three-axis read back (lead and tilt are result columns), in inches',
      2709,
      ['R', 'Rcr', 'h', 'slope', 'passes', 'rasterAngle', 'lead', 'tilt'],
      16,
      (rand) => {
        const v = threeAxis(rand);
        return {
          ...v,
          R: String(Number(v.R) / 25.4),
          Rcr: String(Number(v.Rcr) / 25.4),
          h: '.0004',
          lead: 'stale',
          tilt: '12',
        };
      },
      { args: ['--unit', 'inch'], ordered: true },
    ),
  );
  const inches = (rand: () => number): Record<string, string> => {
    const v = shopCase(rand);
    const R = pick(rand, ['1/4', '1/2"', '.25in', '0.125', '3/8', '6mm', '12.7mm', '1 1/4']);
    return {
      ...v,
      R,
      Rcr: pick(rand, ['.030in', '1/32', '0.02', '0.5mm', '0', '500um', '30thou']),
      h: pick(rand, ['.0004', '0.0001in', '5um', '0.01mm', '1/1000', written(rand, logUniform(rand, 1e-5, 4e-3))]),
    };
  };
  cases.push(run('--unit inch, the shop\u2019s lengths', 2710, PLANE, 30, inches, { args: ['--unit', 'inch'] }));
  cases.push(
    run('columns naming their unit (R_in, Rcr_mm, h_in), the run in mm', 2711, PLANE, 24, inches, {
      rename: { R: 'R_in', Rcr: 'Rcr_mm', h: 'h_in' },
    }),
  );
  cases.push(
    run(
      'Ra named in inches, --unit inch',
      2712,
      ['R', 'Rcr', 'rho', 'Ra_in'],
      10,
      (rand) => ({
        R: pick(rand, ['1/4', '0.125', '3/8']),
        Rcr: pick(rand, ['1/32', '0.02', '0']),
        rho: written(rand, 30 * rand()),
        Ra_in: written(rand, logUniform(rand, 1e-6, 2e-4)),
      }),
      { args: ['--unit', 'inch'], spoil: 0.05 },
    ),
  );
  cases.push({
    name: 'odd records: CRLF, a BOM, blank lines, wrong field counts, stray quotes, output columns read back',
    args: ['--batch'],
    stdin:
      '\ufeffexact,R,Rcr,error,rho,h,note\r\n' +
      '1,3,1,x,5,0.05,y\r\n' +
      '\r\n' +
      '  \r\n' +
      '2,3,1\r\n' +
      '3,3,1,,5,0.05,,extra\r\n' +
      '4,3,1,,5,0"05,\r\n' +
      '5,3,1,,"5" x,0.05,\r\n' +
      '6,"3",1,,"5",0.05,"a ""b"""\r\n' +
      '7,3,1,,5,"0.05\r\n",\r\n' +
      '8,3,1,,5,0.05,"never closed\r\n',
  });
  return cases;
}
