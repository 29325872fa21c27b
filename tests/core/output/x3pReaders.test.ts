/**
 * The proof by other people's software (issue 29): the calculator's x3p files, written from
 * analytic grids (odd and even sizes, dx != dy, sub-nanometre to millimetre heights, the default
 * 1024 x 1024), are read by two Python packages no one here wrote, x3pio and surfalize
 * (installed by tests/support/ensure-python-x3p.mjs, which `npm test` runs first; called here too,
 * so the file also runs alone). One Python process reads every file (tests/support/x3p_read.py).
 * Checked: both readers accept the file (x3pio verifies the MD5 of main.xml and of the heights,
 * surfalize that of main.xml), x3pio gets the grid size, the increments and offsets in metres,
 * the axes' directions, the metadata, and the heights bit for bit; surfalize gets the size, the
 * spacing, and its Sa, Sq, Sz (and Sp, Sv, Ssk, Sku) of the file as loaded (no levelling, no
 * filter) agree with arealSampled.ts within 1e-9 mm.
 */
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { arealSampled } from '../../../src/core/output/arealSampled';
import { x3pBytes } from '../../../src/core/output/x3p';
import { GRID_CASES, gridOf } from './x3pGrids';

const ENSURE = fileURLToPath(new URL('../../support/ensure-python-x3p.mjs', import.meta.url));
const READ = fileURLToPath(new URL('../../support/x3p_read.py', import.meta.url));
const DATE = new Date(Date.UTC(2026, 11, 7, 6, 45, 0, 500));
const COMMENT = 'flutes 4, fz 0.08 mm <along> & "across"';
/** Not ASCII: main.xml is UTF-8. */
const CREATOR = 'Jörg Müller – Werkstatt 3 (µm)';
/** The versions ensure-python-x3p.mjs pins. */
const VERSIONS = { x3pio: '2.0.0', surfalize: '0.19.2' };

interface X3pioView {
  error?: string;
  type: string;
  revision: string;
  layers: number;
  shape: [number, number];
  dtype: string;
  xIncrement: number;
  yIncrement: number;
  zIncrement: number;
  zDataType: string;
  xAxisType: string;
  offset: [number, number, number];
  point00: [number, number, number];
  point01: [number, number, number] | null;
  point10: [number, number, number] | null;
  creator: string | null;
  comment: string | null;
  date: string;
  probingType: string;
  instrumentModel: string;
}
interface SurfalizeView {
  error?: string;
  shape: [number, number];
  stepXUm: number;
  stepYUm: number;
  parametersUm: Record<'Sa' | 'Sq' | 'Sz' | 'Sp' | 'Sv' | 'Ssk' | 'Sku', number>;
  sa: number;
  sq: number;
  sz: number;
}
interface Report {
  versions: { x3pio: string; surfalize: string };
  stubbed: string[];
  files: { path: string; x3pio: X3pioView; surfalize: SurfalizeView }[];
}

const dir = mkdtempSync(join(tmpdir(), 'x3p-readers-'));
const paths = GRID_CASES.map((_, n) => join(dir, `case${n}.x3p`));
let report: Report;

beforeAll(() => {
  const lines = execFileSync(process.execPath, [ENSURE, '--json'], { encoding: 'utf8' }).trim().split('\n');
  const python = JSON.parse(lines[lines.length - 1] as string) as { python: string; env: Record<string, string> };
  GRID_CASES.forEach((c, n) => {
    writeFileSync(paths[n] as string, x3pBytes(gridOf(c), { date: DATE, creator: CREATOR, comment: COMMENT }));
  });
  const out = execFileSync(python.python, [READ, ...paths], {
    encoding: 'utf8',
    env: { ...process.env, ...python.env },
    maxBuffer: 64 << 20,
  });
  report = JSON.parse(out) as Report;
}, 600_000);

afterAll(() => rmSync(dir, { recursive: true, force: true }));

/** The float64 values of a file. */
function float64s(path: string): Float64Array {
  const bytes = readFileSync(path);
  return new Float64Array(bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength));
}

describe('x3p files read by x3pio and surfalize', () => {
  it('the pinned readers ran, surfalize with only its plotting and fitting imports stubbed', () => {
    expect(report.versions).toEqual(VERSIONS);
    for (const name of report.stubbed)
      expect(['matplotlib', 'mpl_toolkits', 'scipy', 'pandas', 'tqdm']).toContain(name);
    expect(report.files.map((f) => f.path)).toEqual(paths);
  });

  GRID_CASES.forEach((c, n) => {
    describe(c.name, () => {
      const grid = gridOf(c);
      const entry = () => report.files[n] as Report['files'][number];

      it('x3pio: accepts it (both MD5s verified): one surface layer, ny rows of nx float64 heights', () => {
        const x = entry().x3pio;
        expect(x.error).toBeUndefined();
        expect([x.type, x.revision, x.layers]).toEqual(['Surface', 'ISO25178-72:2017/DAM1', 1]);
        expect([x.shape, x.dtype]).toEqual([[c.ny, c.nx], 'float64']);
        expect([x.xAxisType, x.zDataType, x.zIncrement]).toEqual(['I', 'D', 1]);
      });

      it('x3pio: the increments and offsets in metres, x along the columns and y along the rows', () => {
        const x = entry().x3pio;
        expect([x.xIncrement, x.yIncrement]).toEqual([c.dxMm / 1000, c.dyMm / 1000]);
        expect(x.offset).toEqual([c.dxMm / 2000, c.dyMm / 2000, 0]);
        expect(x.point00).toEqual([c.dxMm / 2000, c.dyMm / 2000, (grid.heightsMm[0] as number) / 1000]);
        if (x.point01) {
          expect(x.point01[0] - x.point00[0]).toBeCloseTo(c.dxMm / 1000, 18);
          expect(x.point01[1]).toBe(x.point00[1]);
          expect(x.point01[2]).toBe((grid.heightsMm[1] as number) / 1000);
        }
        if (x.point10) {
          expect(x.point10[0]).toBe(x.point00[0]);
          expect(x.point10[1] - x.point00[1]).toBeCloseTo(c.dyMm / 1000, 18);
          expect(x.point10[2]).toBe((grid.heightsMm[c.nx] as number) / 1000);
        }
      });

      it('x3pio: every height bit for bit (metres), in row-major order with x fastest', () => {
        const heightsM = float64s(`${paths[n]}.x3pio.bin`);
        expect(heightsM.length).toBe(c.nx * c.ny);
        let mismatches = 0;
        for (let k = 0; k < heightsM.length; k++)
          if (heightsM[k] !== (grid.heightsMm[k] as number) / 1000) mismatches++;
        expect(mismatches).toBe(0);
      });

      it('x3pio: the metadata (date, creator in UTF-8, comment with markup characters, a computed surface)', () => {
        const x = entry().x3pio;
        expect(new Date(x.date).getTime()).toBe(DATE.getTime());
        expect([x.creator, x.comment, x.probingType, x.instrumentModel]).toEqual([
          CREATOR,
          COMMENT,
          'Software',
          'path-interval',
        ]);
      });

      it('surfalize: accepts it (main.xml MD5 verified), the size and the spacing (micrometres)', () => {
        const s = entry().surfalize;
        expect(s.error).toBeUndefined();
        expect(s.shape).toEqual([c.ny, c.nx]);
        expect(s.stepXUm / (c.dxMm * 1000) - 1).toBeCloseTo(0, 14);
        expect(s.stepYUm / (c.dyMm * 1000) - 1).toBeCloseTo(0, 14);
        const heightsUm = float64s(`${paths[n]}.surfalize.bin`);
        let worst = 0;
        for (let k = 0; k < heightsUm.length; k++) {
          const h = grid.heightsMm[k] as number;
          worst = Math.max(worst, Math.abs((heightsUm[k] as number) / 1000 - h) / (Math.abs(h) + 1e-300));
        }
        expect(worst).toBeLessThan(1e-14);
      });

      it("surfalize: Sa, Sq, Sz (and Sp, Sv, Ssk, Sku) of the file as loaded agree with arealSampled's within 1e-9 mm", () => {
        const s = entry().surfalize;
        const ours = arealSampled(grid.heightsMm);
        expect(Math.abs(s.sa / 1000 - ours.saMm)).toBeLessThanOrEqual(1e-9);
        expect(Math.abs(s.sq / 1000 - ours.sqMm)).toBeLessThanOrEqual(1e-9);
        expect(Math.abs(s.sz / 1000 - ours.szMm)).toBeLessThanOrEqual(1e-9);
        const p = s.parametersUm;
        expect([p.Sa, p.Sq, p.Sz]).toEqual([s.sa, s.sq, s.sz]);
        expect(Math.abs(p.Sp / 1000 - ours.spMm)).toBeLessThanOrEqual(1e-9);
        expect(Math.abs(p.Sv / 1000 - ours.svMm)).toBeLessThanOrEqual(1e-9);
        expect(Math.abs(p.Ssk - (ours.ssk as number))).toBeLessThanOrEqual(1e-9);
        expect(Math.abs(p.Sku - (ours.sku as number))).toBeLessThanOrEqual(1e-9);
        // Far inside the bound: relative agreement to a few roundings, even for sub-nanometre heights.
        expect(Math.abs(s.sa / 1000 / ours.saMm - 1)).toBeLessThan(1e-12);
      });
    });
  });
});
