/**
 * The x3p file (src/core/output/x3p.ts) taken apart in Node, and the sampled areal parameters
 * (src/core/output/arealSampled.ts) against exact arithmetic: the zip's members, both MD5s
 * (against node:crypto), the heights in metres bit for bit in row-major order with x fastest,
 * the increments and offsets in metres, the metadata escaped, and every bad grid refused with a
 * message naming its field. The outside readers' view of the same files: x3pReaders.test.ts.
 */
import { createHash } from 'node:crypto';
import Decimal from 'decimal.js';
import { strFromU8, unzipSync } from 'fflate';
import { describe, expect, it } from 'vitest';
import { seededRandom } from '../../../src/core/math/seededRandom';
import { arealSampled } from '../../../src/core/output/arealSampled';
import { type HeightGrid, x3pBytes } from '../../../src/core/output/x3p';
import { analyticSqMm, GRID_CASES, gridOf } from './x3pGrids';

const DATE = new Date(Date.UTC(2026, 11, 7, 6, 30, 15, 250));
const md5 = (bytes: Uint8Array) => createHash('md5').update(bytes).digest('hex');

/** The text of the first element `name` (after `after`, when given) of an XML document. */
function element(xml: string, name: string, after = ''): string {
  const from = after ? xml.indexOf(`<${after}>`) : 0;
  const match = new RegExp(`<${name}>([^<]*)</${name}>`).exec(xml.slice(from));
  if (!match) throw new Error(`no <${name}> after <${after}>`);
  return match[1] as string;
}

/** An asymmetric little grid: every height differs, and (i, j) is told from (j, i). */
function smallGrid(): HeightGrid {
  const nx = 5;
  const ny = 3;
  const heightsMm = Float64Array.from(
    { length: nx * ny },
    (_, k) => 0.001 * (k % nx) + 0.1 * Math.floor(k / nx) - 0.05,
  );
  return { nx, ny, dxMm: 0.004, dyMm: 0.0025, heightsMm, xOriginMm: 0.002, yOriginMm: 0.00125 };
}

describe('x3pBytes: the zip', () => {
  it('holds main.xml, bindata/data.bin and md5checksum.hex, with the MD5 of each where the standard puts it', () => {
    for (const c of GRID_CASES.slice(0, 4)) {
      const grid = gridOf(c);
      const files = unzipSync(x3pBytes(grid, { date: DATE }));
      expect(Object.keys(files).sort(), c.name).toEqual(['bindata/data.bin', 'main.xml', 'md5checksum.hex']);
      const mainXml = files['main.xml'] as Uint8Array;
      const data = files['bindata/data.bin'] as Uint8Array;
      expect(strFromU8(files['md5checksum.hex'] as Uint8Array)).toBe(`${md5(mainXml)} *main.xml\n`);
      const xml = strFromU8(mainXml);
      expect(element(xml, 'PointDataLink')).toBe('bindata/data.bin');
      expect(element(xml, 'MD5ChecksumPointData')).toBe(md5(data));
      expect(element(xml, 'ChecksumFile')).toBe('md5checksum.hex');
    }
  });

  it('stores the heights as little-endian float64 metres, row-major with x fastest', () => {
    const grid = smallGrid();
    const data = unzipSync(x3pBytes(grid, { date: DATE }))['bindata/data.bin'] as Uint8Array;
    expect(data.length).toBe(8 * grid.nx * grid.ny);
    const view = new DataView(data.buffer, data.byteOffset, data.byteLength);
    for (let j = 0; j < grid.ny; j++)
      for (let i = 0; i < grid.nx; i++) {
        const k = j * grid.nx + i;
        // Sample (i, j) = 0.001 i + 0.1 j - 0.05 mm, stored as that many metres (the double nearest h / 1000).
        expect(view.getFloat64(8 * k, true), `sample (${i}, ${j})`).toBe((0.001 * i + 0.1 * j - 0.05) / 1000);
      }
  });

  it('is the same bytes for the same grid and date', () => {
    const grid = gridOf(GRID_CASES[1] as (typeof GRID_CASES)[number]);
    expect(x3pBytes(grid, { date: DATE, comment: 'c' })).toEqual(x3pBytes(grid, { date: DATE, comment: 'c' }));
  });
});

describe('x3pBytes: main.xml', () => {
  it('a surface: incremental x and y with increments and offsets in metres, absolute float64 z, the matrix size', () => {
    const grid = smallGrid();
    const xml = strFromU8(unzipSync(x3pBytes(grid, { date: DATE }))['main.xml'] as Uint8Array);
    expect(
      xml.startsWith(
        '<?xml version="1.0" encoding="UTF-8"?>\n<p:ISO5436_2 xmlns:p="http://www.opengps.eu/2008/ISO5436_2"',
      ),
    ).toBe(true);
    expect(element(xml, 'Revision')).toBe('ISO25178-72:2017/DAM1');
    expect(element(xml, 'FeatureType')).toBe('SUR');
    expect([element(xml, 'AxisType', 'CX'), element(xml, 'DataType', 'CX')]).toEqual(['I', 'D']);
    expect(Number(element(xml, 'Increment', 'CX'))).toBe(0.000004);
    expect(Number(element(xml, 'Offset', 'CX'))).toBe(0.000002);
    expect([element(xml, 'AxisType', 'CY'), element(xml, 'DataType', 'CY')]).toEqual(['I', 'D']);
    expect(Number(element(xml, 'Increment', 'CY'))).toBe(0.0000025);
    expect(Number(element(xml, 'Offset', 'CY'))).toBe(0.00000125);
    expect([element(xml, 'AxisType', 'CZ'), element(xml, 'DataType', 'CZ')]).toEqual(['A', 'D']);
    expect([element(xml, 'Increment', 'CZ'), element(xml, 'Offset', 'CZ')]).toEqual(['1', '0']);
    expect([element(xml, 'SizeX'), element(xml, 'SizeY'), element(xml, 'SizeZ')]).toEqual(['5', '3', '1']);
    // The records and their elements in the schema's order.
    const order = [
      ...xml.matchAll(/<(Record\d|Date|Creator|Instrument|ProbingSystem|Comment|MatrixDimension|DataLink)>/g),
    ];
    expect(order.map((m) => m[1])).toEqual([
      'Record1',
      'Record2',
      'Date',
      'Instrument',
      'ProbingSystem',
      'Record3',
      'MatrixDimension',
      'DataLink',
      'Record4',
    ]);
  });

  it('Record2: the date with its zone, a computed surface (probing system Software), creator and comment escaped', () => {
    const comment = 'a <tool> & "feed" \'marks\'\nsecond line';
    const xml = strFromU8(
      unzipSync(x3pBytes(smallGrid(), { date: DATE, creator: '  Shop\t floor  ', comment, softwareVersion: '0.1.0' }))[
        'main.xml'
      ] as Uint8Array,
    );
    expect(element(xml, 'Date')).toBe('2026-12-07T06:30:15.250+00:00');
    expect(element(xml, 'Creator')).toBe('Shop floor');
    expect(element(xml, 'Type')).toBe('Software');
    expect(element(xml, 'Model')).toBe('path-interval');
    expect(element(xml, 'Version')).toBe('0.1.0');
    expect(xml).toContain('<Comment>a &lt;tool&gt; &amp; "feed" \'marks\'\nsecond line</Comment>');
  });

  it("a date outside the zip format's 1980..2099 is written as it is in main.xml (the zip time clamped)", () => {
    for (const date of [new Date(Date.UTC(1970, 0, 1)), new Date(Date.UTC(2150, 5, 1, 12))]) {
      const files = unzipSync(x3pBytes(smallGrid(), { date }));
      expect(element(strFromU8(files['main.xml'] as Uint8Array), 'Date')).toBe(
        date.toISOString().replace('Z', '+00:00'),
      );
    }
  });

  it('leaves out Creator and Comment when not given', () => {
    const xml = strFromU8(unzipSync(x3pBytes(smallGrid(), { date: DATE }))['main.xml'] as Uint8Array);
    expect(xml).not.toContain('<Creator>');
    expect(xml).not.toContain('<Comment>');
  });
});

describe('x3pBytes: refused grids', () => {
  const good = smallGrid();
  const cases: [string, HeightGrid, string][] = [
    ['nx 0', { ...good, nx: 0 }, 'x3p nx: must be a whole number >= 1 (got 0)'],
    ['ny 2.5', { ...good, ny: 2.5 }, 'x3p ny: must be a whole number >= 1 (got 2.5)'],
    ['dx 0', { ...good, dxMm: 0 }, 'x3p dxMm: must be a finite spacing > 0 mm (got 0)'],
    [
      'dy infinite',
      { ...good, dyMm: Number.POSITIVE_INFINITY },
      'x3p dyMm: must be a finite spacing > 0 mm (got Infinity)',
    ],
    ['x origin NaN', { ...good, xOriginMm: Number.NaN }, 'x3p xOriginMm: must be a finite length in mm (got NaN)'],
    [
      'too few heights',
      { ...good, heightsMm: new Float64Array(14) },
      'x3p heightsMm: must hold nx * ny = 15 heights (got 14)',
    ],
    [
      'a NaN height',
      { ...good, heightsMm: Float64Array.from(good.heightsMm, (h, k) => (k === 7 ? Number.NaN : h)) },
      'x3p heightsMm: every height must be finite (index 7 is NaN)',
    ],
  ];
  for (const [name, grid, message] of cases)
    it(`${name}: a one-line message naming the field`, () => {
      expect(() => x3pBytes(grid, { date: DATE })).toThrow(message);
    });

  it('a comment with a character XML cannot hold, and an invalid date', () => {
    expect(() => x3pBytes(good, { date: DATE, comment: 'bell \u0007' })).toThrow(
      'x3p comment: the character U+0007 cannot be written in XML',
    );
    expect(() => x3pBytes(good, { date: new Date(Number.NaN) })).toThrow('x3p date: not a valid date');
  });
});

/** The exact parameters of samples, in 60-digit decimal arithmetic. */
function exactParameters(heights: ArrayLike<number>) {
  Decimal.set({ precision: 60 });
  const values = Array.from(heights, (h) => new Decimal(h));
  const n = values.length;
  const mean = values.reduce((s, v) => s.plus(v), new Decimal(0)).div(n);
  const d = values.map((v) => v.minus(mean));
  const moment = (f: (x: Decimal) => Decimal) => d.reduce((s, x) => s.plus(f(x)), new Decimal(0)).div(n);
  const sq = moment((x) => x.pow(2)).sqrt();
  const max = Decimal.max(...values);
  const min = Decimal.min(...values);
  return {
    meanMm: mean.toNumber(),
    saMm: moment((x) => x.abs()).toNumber(),
    sqMm: sq.toNumber(),
    spMm: max.minus(mean).toNumber(),
    svMm: mean.minus(min).toNumber(),
    szMm: max.minus(min).toNumber(),
    ssk: moment((x) => x.pow(3))
      .div(sq.pow(3))
      .toNumber(),
    sku: moment((x) => x.pow(4))
      .div(sq.pow(4))
      .toNumber(),
  };
}

describe('arealSampled', () => {
  it('seed 29101: agrees with 60-digit arithmetic on random samples, tiny to large, near and far from zero', () => {
    const rand = seededRandom(29101);
    for (let n = 0; n < 60; n++) {
      const count = 1 + Math.floor(rand() * 400);
      const scale = 10 ** (-8 + 9 * rand());
      const offset = rand() < 0.5 ? 0 : (rand() - 0.5) * 10 ** (3 * rand()) * 100 * scale;
      const skew = 1 + 3 * rand();
      const heights = Float64Array.from({ length: count }, () => offset + scale * (rand() ** skew - 0.3));
      const got = arealSampled(heights);
      const want = exactParameters(heights);
      const label = `set ${n}: ${count} samples, scale ${scale.toExponential(2)}, offset ${offset.toExponential(2)}`;
      expect(got.count).toBe(count);
      // Within a few roundings of the mean's magnitude (the reference every parameter is measured from).
      const ulp = (Math.abs(want.meanMm) + scale) * 2 ** -50;
      for (const key of ['meanMm', 'saMm', 'sqMm', 'spMm', 'svMm', 'szMm'] as const)
        expect(Math.abs(got[key] - want[key]), `${label}: ${key}`).toBeLessThanOrEqual(ulp);
      if (want.sqMm > 1e-6 * scale) {
        expect(got.ssk as number, `${label}: Ssk`).toBeCloseTo(want.ssk, 9);
        expect(got.sku as number, `${label}: Sku`).toBeCloseTo(want.sku, 9);
      }
    }
  });

  it('on the analytic grids: the mean is the constant and Sq is sqrt(sum a^2 / 2), to a few roundings', () => {
    for (const c of GRID_CASES) {
      const got = arealSampled(gridOf(c).heightsMm);
      const size = Math.abs(c.constantMm) + c.waves.reduce((s, w) => s + w.amplitudeMm, 0);
      expect(Math.abs(got.meanMm - c.constantMm), c.name).toBeLessThanOrEqual(size * 1e-14);
      expect(Math.abs(got.sqMm - analyticSqMm(c)), c.name).toBeLessThanOrEqual(size * 1e-14);
    }
  });

  it('one cosine over whole periods through its crests: Sz = 2a, Ssk = 0, Sku = 3/2', () => {
    const n = 48;
    const heights = Float64Array.from({ length: n }, (_, i) => 0.25 + 0.003 * Math.cos((2 * Math.PI * 3 * i) / n));
    const got = arealSampled(heights);
    expect(got.szMm).toBeCloseTo(0.006, 15);
    expect(got.ssk as number).toBeCloseTo(0, 12);
    expect(got.sku as number).toBeCloseTo(1.5, 12);
  });

  it('a flat surface: every height parameter 0, no skewness or kurtosis (undefined, never NaN)', () => {
    const got = arealSampled(new Float64Array(12).fill(0.7));
    expect([got.meanMm, got.saMm, got.sqMm, got.spMm, got.svMm, got.szMm]).toEqual([0.7, 0, 0, 0, 0, 0]);
    expect(got.ssk).toBeUndefined();
    expect(got.sku).toBeUndefined();
  });

  it('refuses no samples and a non-finite one, naming the constraint', () => {
    expect(() => arealSampled([])).toThrow('areal parameters: need at least one height sample (got 0)');
    expect(() => arealSampled([0, 1, Number.POSITIVE_INFINITY])).toThrow(
      'areal parameters: every height must be finite (index 2 is Infinity)',
    );
  });
});
