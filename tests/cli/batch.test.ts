import { describe, expect, it } from 'vitest';
import {
  batchRow,
  csvNumber,
  HEADER_RULE,
  type Layout,
  outputHeader,
  parseHeader,
  RESULT_COLUMNS,
} from '../../src/cli/batch';
import { parseCsv } from '../../src/cli/csv';
import {
  APPROXIMATION_KEYS,
  compareForward,
  PASS_PATTERNS,
  scallopHeightLimits,
  validateForward,
} from '../../src/core/index';
import { pick, random, randomHeight, randomTool } from './helpers';

function layoutOf(header: string): Layout {
  const [record] = parseCsv(header);
  if (!record) throw new Error('no header');
  const h = parseHeader(record);
  if (!h.ok) throw new Error(h.error);
  return h.layout;
}

function row(layout: Layout, line: string): string[] {
  const [record] = parseCsv(line);
  if (!record) throw new Error('no record');
  const [out] = parseCsv(batchRow(record, layout));
  return out?.fields ?? [];
}

describe('batch header', () => {
  it('R,Rcr,rho,h in any order, optionally tilt and pattern; echoed in the order R,Rcr,rho,h,tilt,pattern', () => {
    expect(outputHeader(layoutOf('R,Rcr,rho,h'))).toBe(`R,Rcr,rho,h,${RESULT_COLUMNS.join(',')}\n`);
    expect(outputHeader(layoutOf(' pattern ,h,"tilt",rho,Rcr,R'))).toBe(
      `R,Rcr,rho,h,tilt,pattern,${RESULT_COLUMNS.join(',')}\n`,
    );
    expect(outputHeader(layoutOf('R,Rcr,rho,h'))).toMatch(
      /^R,Rcr,rho,h,exact,sekine,redonnet,bedi,interval,halfWidthRight,halfWidthLeft,contactOffset,otherCuspHeight,osculating,cornerBall,note,error\n$/,
    );
  });

  it('the output columns may be read back: they are ignored and computed again (a batch output, a lookup table)', () => {
    const output = outputHeader(layoutOf('R,Rcr,rho,h,surfaceRadius')).trimEnd();
    expect(outputHeader(layoutOf(output)).trimEnd()).toBe(output);
    const layout = layoutOf('exact,R,Rcr,error,rho,h,note');
    expect(outputHeader(layout)).toBe(`R,Rcr,rho,h,${RESULT_COLUMNS.join(',')}\n`);
    expect(row(layout, '99,3,1,stale,5,0.05,x')).toEqual(row(layoutOf('R,Rcr,rho,h'), '3,1,5,0.05'));
  });

  it.each([
    ['R,Rcr,rho,h,exact,exact', /column exact appears twice/],
    ['R,Rcr,rho', /missing h \(or Ra or L\)/],
    ['R,Rcr,rho,h,Ra', /give one of h, Ra and L, not h and Ra/],
    ['R,Rcr,Ra,surfaceradius', /missing rho; unknown column "surfaceradius"/],
    ['R,Rcr,rho,Ra,surfaceAxis,surfaceAxis', /column surfaceAxis appears twice/],
    ['R,Rcr,rho,h,tlit', /unknown column "tlit"/],
    ['R,Rcr,rho,h,id', /unknown column "id"/],
    ['R,Rcr,rho,h,R', /column R appears twice/],
    ['r,rcr,rho,h', /missing R, Rcr; unknown column "r"; unknown column "rcr"/],
    ['R,Rcr,rho,"h', /never closed/],
  ])('header %j is refused: %s', (header, message) => {
    const [record] = parseCsv(header);
    if (!record) throw new Error('no header');
    const h = parseHeader(record);
    expect(h.ok).toBe(false);
    if (!h.ok) {
      expect(h.error.startsWith(`${HEADER_RULE} `) || h.error.startsWith(`${HEADER_RULE};`)).toBe(true);
      expect(h.error).toMatch(
        /^the CSV header must be R,Rcr,rho,h \(or Ra, or the step-over L, in place of h\) in any order/,
      );
      expect(h.error).toMatch(message);
    }
  });
});

describe('batch rows', () => {
  const layout = layoutOf('R,Rcr,rho,h,tilt,pattern');
  const width = 6 + RESULT_COLUMNS.length;

  it('an empty tilt or pattern field takes the default (0, one-way)', () => {
    expect(row(layout, '3,1,5,0.05,,').slice(6)).toEqual(row(layoutOf('R,Rcr,rho,h'), '3,1,5,0.05').slice(4));
  });

  it('numbers in full precision (shortest round trip), never -0', () => {
    expect(csvNumber(0.1 + 0.2)).toBe('0.30000000000000004');
    expect(csvNumber(-0)).toBe('0');
    expect(csvNumber(1e-320)).toBe('1e-320');
    const r = row(layout, '3,1,5,0.05,-5,one-way');
    expect(Number(r[13])).toBeLessThan(0); // contactOffset is signed with the tilt
  });

  it('echoed text that a spreadsheet would evaluate gets a leading quote; numbers are echoed as typed', () => {
    const r = row(layout, '=1+2,-1,@x,+5,-3e0,=zigzag');
    expect(r.slice(0, 6)).toEqual(["'=1+2", '-1', "'@x", '+5', '-3e0', "'=zigzag"]);
    // A sign before text that is no number is a formula too.
    expect(row(layout, '-x,+y,3,-h,+1e,-zigzag').slice(0, 6)).toEqual(["'-x", "'+y", '3', "'-h", "'+1e", "'-zigzag"]);
    expect(r).toHaveLength(width);
    expect(r[width - 1]).toMatch(/Tool radius R must be a number/);
  });

  it('wrong field counts and syntax errors name the line', () => {
    const [bad] = parseCsv('1,2\n');
    if (!bad) throw new Error('no record');
    expect(parseCsv(batchRow({ ...bad, line: 7 }, layout))[0]?.fields[width - 1]).toBe(
      'line 7: expected 6 values (R,Rcr,rho,h,tilt,pattern), got 2',
    );
  });

  const seed = 31337;
  const N = 3000;
  it(`rows carry the core's values, warnings included (seed ${seed}, ${N} random valid cases)`, () => {
    const rand = random(seed);
    let checked = 0;
    let warned = 0;
    for (let k = 0; k < N; k++) {
      const t = randomTool(rand);
      const tool = { toolRadiusMm: t.R, cornerRadiusMm: t.Rcr, leadAngleDeg: t.rho, tiltAngleDeg: t.tilt };
      const pattern = pick(rand, PASS_PATTERNS);
      const h = randomHeight(rand, scallopHeightLimits(tool).limitMm);
      const raw = {
        R: String(t.R),
        Rcr: String(t.Rcr),
        rho: String(t.rho),
        tilt: String(t.tilt),
        pattern,
        h: String(h),
      };
      const v = validateForward(raw);
      if (!v.ok) continue;
      checked++;
      const c = compareForward(v.value);
      const r = row(layout, [raw.R, raw.Rcr, raw.rho, raw.h, raw.tilt, raw.pattern].join(','));
      const half = (key: (typeof APPROXIMATION_KEYS)[number]) => {
        const a = c.approximations[key];
        return a.ok ? String(a.halfIntervalMm) : '';
      };
      const e = c.exact;
      expect(r.slice(6)).toEqual([
        csvNumber(e.halfIntervalMm),
        half('sekine'),
        half('redonnet'),
        half('bedi'),
        csvNumber(e.intervalMm),
        csvNumber(e.halfWidthRightMm),
        csvNumber(e.halfWidthLeftMm),
        csvNumber(e.contactOffsetMm),
        e.otherCuspHeightMm === null ? '' : csvNumber(e.otherCuspHeightMm),
        half('osculating'),
        half('cornerBall'),
        expect.any(String),
        '',
      ]);
      const note = r[6 + 11] as string;
      for (const key of APPROXIMATION_KEYS) {
        const a = c.approximations[key];
        if (a.ok && a.warning !== null) {
          warned++;
          expect(note).toContain(a.warning);
        }
      }
      const warnings = APPROXIMATION_KEYS.filter((key) => {
        const a = c.approximations[key];
        return a.ok && a.warning !== null;
      }).length;
      expect(note.split('leave a wall.').length - 1).toBe(warnings);
    }
    expect(checked).toBeGreaterThan(0.75 * N);
    expect(warned).toBeGreaterThan(50);
  });

  const cylinderSeed = 5150;
  const M = 400;
  it(`cylinder rows: the warnings are the core's for that surface (seed ${cylinderSeed}, ${M} random cases)`, () => {
    const layout = layoutOf('R,Rcr,rho,h,tilt,pattern,surfaceRadius,surfaceAxis');
    const rand = random(cylinderSeed);
    let warned = 0;
    let checked = 0;
    for (let k = 0; k < M; k++) {
      const R = 0.5 + 10 * rand();
      const t = {
        toolRadiusMm: R,
        cornerRadiusMm: R * rand(),
        leadAngleDeg: 30 * rand(),
        tiltAngleDeg: 10 * (rand() - 0.5),
      };
      const pattern = pick(rand, PASS_PATTERNS);
      const surface = {
        kind: 'cylinder' as const,
        radiusMm: (rand() < 0.5 ? -1 : 1) * R * (1.5 + 20 * rand()),
        axis: pick(rand, ['feed', 'cross'] as const),
      };
      let limit = 0;
      try {
        limit = scallopHeightLimits(t, surface).limitMm;
      } catch {
        continue;
      }
      const h = limit * pick(rand, [0.5, 0.9, 0.99, rand()]);
      const fields = [R, t.cornerRadiusMm, t.leadAngleDeg, h, t.tiltAngleDeg, pattern, surface.radiusMm, surface.axis];
      const v = validateForward({
        R,
        Rcr: t.cornerRadiusMm,
        rho: t.leadAngleDeg,
        tilt: t.tiltAngleDeg,
        pattern,
        h,
        surfaceRadius: surface.radiusMm,
        surfaceAxis: surface.axis,
      });
      if (!v.ok) continue;
      checked++;
      const c = compareForward(v.value);
      const note = row(layout, fields.join(','))[8 + 11] as string;
      const warnings = APPROXIMATION_KEYS.flatMap((key) => {
        const a = c.approximations[key];
        return a.ok && a.warning !== null ? [a.warning] : [];
      });
      warned += warnings.length;
      for (const w of warnings) expect(note).toContain(w);
      expect(note.split('leave a wall.').length - 1).toBe(warnings.length);
    }
    expect(checked).toBeGreaterThan(0.5 * M);
    expect(warned).toBeGreaterThan(20);
  });
});
