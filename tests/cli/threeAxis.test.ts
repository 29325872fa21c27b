/**
 * Issue 20's command line: three-axis machining (--slope), run through main() (the same code as
 * the process, without a process start per case). Independent references: the ball end's closed form
 * `L = 2 sqrt(2 R h - h^2)` at every slope and direction; the upright tool on a flat floor (the
 * five-axis command line at --rho 0); the horizontal step and the step-down computed here from 3D
 * vectors (the two CC paths on the sloped plane and their vertical planes); the shank's height
 * `Rcr (1 - sin alpha)` for waterline on a plane (the notes, section 2a).
 */
import { describe, expect, it } from 'vitest';
import { random, run, runMain } from './helpers';

interface ThreeAxisJson {
  machine: string;
  input: Record<string, number | string>;
  exact: { interval: number; horizontalStep?: number; stepDown?: number; scallopHeight: number; noScallop: boolean };
  posture: { lead: number; tilt: number };
}

async function json(args: readonly string[]): Promise<ThreeAxisJson> {
  const r = await runMain([...args, '--json']);
  if (r.code !== 0) throw new Error(`${args.join(' ')}: ${r.stderr}`);
  return JSON.parse(r.stdout) as ThreeAxisJson;
}

const deg = Math.PI / 180;

/** The horizontal step and the height between two adjacent CC paths L apart on a plane of slope alpha, raster angle psi (3D vectors). */
function stepsFromVectors(L: number, alphaDeg: number, psiDeg: number): { lxy: number; dz: number } {
  const a = alphaDeg * deg;
  const p = psiDeg * deg;
  // World frame: z up, the fall line's plan direction +y (uphill), the plane z = y tan(alpha).
  const normal = [0, -Math.sin(a), Math.cos(a)];
  // The pass direction: plan direction at psi to the fall line, lifted onto the plane.
  const t0 = [Math.sin(p), Math.cos(p), Math.cos(p) * Math.tan(a)];
  const tn = Math.hypot(t0[0] as number, t0[1] as number, t0[2] as number);
  const t = t0.map((v) => v / tn) as [number, number, number];
  // The step direction on the plane, across the passes: normal x t.
  const [nx, ny, nz] = normal as [number, number, number];
  const m = [ny * t[2] - nz * t[1], nz * t[0] - nx * t[2], nx * t[1] - ny * t[0]] as [number, number, number];
  // The horizontal normal of the vertical plane holding a pass.
  const kn = Math.hypot(t[0], t[1]);
  const k = [-t[1] / kn, t[0] / kn, 0];
  return {
    lxy: Math.abs(L * (m[0] * (k[0] as number) + m[1] * (k[1] as number))),
    dz: Math.abs(L * m[2]),
  };
}

describe('the issue examples', () => {
  it('--slope with --h: the table leads with the programmed step, then L along the surface, lead and tilt', async () => {
    const r = await run(['--R', '3', '--Rcr', '1', '--slope', '30', '--raster-angle', '45', '--h', '0.01']);
    expect(r.code, r.stderr).toBe(0);
    expect(r.stderr).toBe('');
    const keys = r.stdout
      .split('\n')
      .map((l) => /^ {2}(\S+) /.exec(l)?.[1])
      .filter((k) => k !== undefined);
    expect(keys).toEqual(['Lxy', 'L', 'lead', 'tilt', 'h']);
    expect(r.stdout).toContain('(as programmed)');
    const w = await run(['--R', '3', '--Rcr', '1', '--slope', '30', '--passes', 'waterline', '--h', '0.01']);
    expect(w.code, w.stderr).toBe(0);
    const wKeys = w.stdout
      .split('\n')
      .map((l) => /^ {2}(\S+) /.exec(l)?.[1])
      .filter((k) => k !== undefined);
    expect(wKeys.slice(0, 2)).toEqual(['dz', 'L']);
    expect(wKeys).toContain('lead');
    expect(wKeys).toContain('tilt');
  });

  it('--json: exact.interval, exact.horizontalStep (raster) or exact.stepDown (waterline), posture {lead, tilt}', async () => {
    const r = await run(['--R', '3', '--Rcr', '1', '--slope', '30', '--h', '0.01', '--json']);
    expect(r.code, r.stderr).toBe(0);
    const j = JSON.parse(r.stdout) as ThreeAxisJson;
    expect(j.machine).toBe('3axis');
    expect(j.exact.interval).toBeGreaterThan(0);
    expect(j.exact.horizontalStep).toBeGreaterThan(0);
    expect(j.exact.stepDown).toBeUndefined();
    // psi = 0 (passes along the fall line): lead = alpha, no tilt.
    expect(j.posture.lead).toBeCloseTo(30, 12);
    expect(j.posture.tilt).toBe(0);
    const w = await run(['--R', '3', '--Rcr', '1', '--slope', '30', '--passes', 'waterline', '--h', '0.01', '--json']);
    const jw = JSON.parse(w.stdout) as ThreeAxisJson;
    expect(jw.exact.stepDown).toBeGreaterThan(0);
    expect(jw.exact.horizontalStep).toBeUndefined();
    // Waterline: the contour direction, no lead, tilt = alpha.
    expect(jw.posture.lead).toBe(0);
    expect(jw.posture.tilt).toBeCloseTo(30, 12);
  });

  it('the inverse: --horizontal-step and --step-down give back the cusp height that step leaves', async () => {
    const cases: [string[], 'horizontalStep' | 'stepDown', string][] = [
      [['--raster-angle', '60'], 'horizontalStep', '--horizontal-step'],
      [['--passes', 'waterline'], 'stepDown', '--step-down'],
      [['--passes', 'waterline', '--feed-radius', '40', '--cross-radius', '25'], 'stepDown', '--step-down'],
      [['--passes', 'waterline', '--cross-radius', '-30'], 'stepDown', '--step-down'],
    ];
    for (const [extra, key, flag] of cases) {
      const base = ['--R', '5', '--Rcr', '1.5', '--slope', '40', ...extra];
      const f = await json([...base, '--h', '0.004']);
      const step = f.exact[key] as number;
      const r = await run([...base, flag, String(step), '--json']);
      expect(r.code, r.stderr).toBe(0);
      const back = JSON.parse(r.stdout) as ThreeAxisJson;
      expect(Math.abs(back.exact.scallopHeight - 0.004), `${extra.join(' ')}`).toBeLessThan(1e-9);
      expect(back.exact.interval).toBeCloseTo(f.exact.interval, 9);
    }
  });
});

describe('independent references', () => {
  it('a ball end leaves L = 2 sqrt(2 R h - h^2) at every slope and direction (seed 20)', async () => {
    const rand = random(20);
    for (let i = 0; i < 40; i++) {
      const R = 0.5 + 9.5 * rand();
      const alpha = 0.5 + 84 * rand();
      // Below the shank's height on the uphill side, R (1 - sin alpha) at most (waterline).
      const h = Math.min(R * 10 ** (-5 + 4 * rand()), 0.5 * R * (1 - Math.sin(alpha * deg)));
      const waterline = i % 2 === 1;
      const args = ['--R', String(R), '--Rcr', String(R), '--slope', String(alpha), '--h', String(h)];
      if (waterline) args.push('--passes', 'waterline');
      else args.push('--raster-angle', String(90 * rand()));
      const j = await json(args);
      const closed = 2 * Math.sqrt(2 * R * h - h * h);
      expect(Math.abs(j.exact.interval - closed), args.join(' ')).toBeLessThan(1e-9 * Math.max(1, closed));
    }
  });

  it('alpha = 0 is the upright tool on a flat floor: the five-axis answer at --rho 0, any raster angle', async () => {
    for (const [R, Rcr, h] of [
      [3, 1, 0.01],
      [5, 0.5, 0.002],
      [2, 2, 0.05],
      [6, 0, 0.01],
    ] as const) {
      const five = await runMain(['--R', String(R), '--Rcr', String(Rcr), '--rho', '0', '--h', String(h), '--json']);
      const L0 = (JSON.parse(five.stdout) as { exact: { interval: number } }).exact.interval;
      for (const psi of ['0', '30', '90']) {
        const j = await json([
          '--R',
          String(R),
          '--Rcr',
          String(Rcr),
          '--slope',
          '0',
          '--raster-angle',
          psi,
          '--h',
          String(h),
        ]);
        expect(j.exact.interval, `${R} ${Rcr} ${psi}`).toBe(L0);
        expect(j.exact.horizontalStep).toBe(L0);
        expect([j.posture.lead, j.posture.tilt]).toEqual([0, 0]);
      }
    }
  });

  it('Lxy and dz against the two CC paths in 3D (their vertical planes, their heights) (seed 21)', async () => {
    const rand = random(21);
    for (let i = 0; i < 40; i++) {
      const alpha = 1 + 80 * rand();
      const waterline = i % 3 === 0;
      const psi = waterline ? 90 : 90 * rand();
      const args = ['--R', '4', '--Rcr', '1', '--slope', String(alpha), '--h', '0.003'];
      if (waterline) args.push('--passes', 'waterline');
      else args.push('--raster-angle', String(psi));
      const j = await json(args);
      const want = stepsFromVectors(j.exact.interval, alpha, psi);
      if (waterline) expect(Math.abs((j.exact.stepDown as number) - want.dz), args.join(' ')).toBeLessThan(1e-12);
      else expect(Math.abs((j.exact.horizontalStep as number) - want.lxy), args.join(' ')).toBeLessThan(1e-12);
    }
  });
});

describe('the batch', () => {
  const csv = [
    'R,Rcr,h,slope,passes,rasterAngle,feedRadius,crossRadius',
    '3,1,0.01,30,,,,',
    '3,1,0.01,30,raster,45,,',
    '3,1,0.01,30,waterline,,,',
    '3,1,0.01,30,waterline,,50,50',
    '3,1,0.01,90,,,,',
    '',
  ].join('\n');

  it('writes horizontalStep, stepDown, lead, tilt beside interval; its output reads back to itself', async () => {
    const r = await run(['--batch'], csv);
    expect(r.code, r.stderr).toBe(0);
    const lines = r.stdout.trim().split('\n');
    expect(lines[0]).toBe(
      'R,Rcr,h,slope,passes,rasterAngle,feedRadius,crossRadius,interval,horizontalStep,stepDown,lead,tilt,note,error',
    );
    // Each row is the single case's answer.
    const row = (lines[2] as string).split(',');
    const j = await json(['--R', '3', '--Rcr', '1', '--slope', '30', '--raster-angle', '45', '--h', '0.01']);
    expect(row.slice(8, 13).map(Number)).toEqual([
      j.exact.interval,
      j.exact.horizontalStep,
      0,
      j.posture.lead,
      j.posture.tilt,
    ]);
    expect(row[10]).toBe('');
    const w = (lines[3] as string).split(',');
    const jw = await json(['--R', '3', '--Rcr', '1', '--slope', '30', '--passes', 'waterline', '--h', '0.01']);
    expect(Number(w[10])).toBe(jw.exact.stepDown);
    expect(lines[5]).toContain('vertical wall');
    const again = await run(['--batch'], r.stdout);
    expect(again.stdout).toBe(r.stdout);
  });

  it('a header with slope needs no rho; a row with a slope and a lead or tilt is that row error', async () => {
    const r = await run(['--batch'], 'R,Rcr,h,slope,rho,tilt\n3,1,0.01,30,,\n3,1,0.01,30,5,\n3,1,0.01,30,,2\n');
    expect(r.code, r.stderr).toBe(0);
    const lines = r.stdout.trim().split('\n');
    expect(lines[1]?.endsWith(',')).toBe(true);
    expect(lines[2]).toMatch(/Lead angle rho does not go with a slope/);
    expect(lines[3]).toMatch(/Tilt angle beta does not go with a slope/);
  });
});

describe('usage errors and invalid inputs: one line naming the constraint', () => {
  const tool = ['--R', '3', '--Rcr', '1'];
  const usageCases: [string[], RegExp][] = [
    [[...tool, '--slope', '30', '--rho', '5', '--h', '0.01'], /--rho does not go with --slope/],
    [[...tool, '--slope', '30', '--tilt', '5', '--h', '0.01'], /--tilt does not go with --slope/],
    [[...tool, '--slope', '30', '--feed-radius', '50', '--h', '0.01'], /--feed-radius is for waterline/],
    [
      [...tool, '--slope', '30', '--passes', 'raster', '--cross-radius', '50', '--h', '0.01'],
      /--cross-radius is for waterline/,
    ],
    [[...tool, '--slope', '30', '--step-down', '0.1'], /--step-down is the step of waterline passes/],
    [
      [...tool, '--slope', '30', '--passes', 'waterline', '--horizontal-step', '0.1'],
      /--horizontal-step is the step of raster/,
    ],
    [[...tool, '--rho', '5', '--raster-angle', '10', '--h', '0.01'], /--raster-angle is for three-axis machining/],
    [
      [...tool, '--slope', '30', '--h', '0.01', '--horizontal-step', '1'],
      /--h and --horizontal-step do not go together/,
    ],
  ];

  it('combinations that do not exist are usage errors (exit 2)', async () => {
    for (const [args, message] of usageCases) {
      const r = await run(args);
      expect(r.code, args.join(' ')).toBe(2);
      expect(r.stdout).toBe('');
      expect(r.stderr.trim().split('\n')).toHaveLength(1);
      expect(r.stderr).toMatch(message);
    }
  });

  it('waterline with --raster-angle 90 (the contour) answers as without it, as a batch row does', async () => {
    const plain = await run([...tool, '--slope', '30', '--passes', 'waterline', '--h', '0.01', '--json']);
    const at90 = await run([
      ...tool,
      '--slope',
      '30',
      '--passes',
      'waterline',
      '--raster-angle',
      '90',
      '--h',
      '0.01',
      '--json',
    ]);
    expect(at90.code).toBe(0);
    expect(JSON.parse(at90.stdout).exact).toEqual(JSON.parse(plain.stdout).exact);
  });

  it('bad values name the constraint and its limit in mm or degrees; never NaN', async () => {
    const cases: [string[], RegExp][] = [
      [[...tool, '--slope', '95', '--h', '0.01'], /^error: --slope: Slope alpha must be from 0 to 90 degrees/],
      [[...tool, '--slope', 'abc', '--h', '0.01'], /^error: --slope: Slope alpha must be a number \(got "abc"\)\.\n$/],
      [[...tool, '--slope', '90', '--h', '0.01'], /vertical wall.*no scallop/],
      [
        [...tool, '--slope', '30', '--raster-angle', '91', '--h', '0.01'],
        /--raster-angle: Raster angle psi must be from 0 to 90/,
      ],
      [
        // Waterline passes follow the contour (psi = 90): another raster angle is refused by the core's
        // rule, as in a batch row (one rule for both).
        [...tool, '--slope', '30', '--passes', 'waterline', '--raster-angle', '10', '--h', '0.01'],
        /^error: --raster-angle: Raster angle psi must be 90 degrees or left empty for waterline passes \(got 10\)/,
      ],
      [
        [...tool, '--slope', '30', '--passes', 'spiral', '--h', '0.01'],
        /--passes: Pass strategy must be raster or waterline/,
      ],
      [
        [...tool, '--slope', '0', '--passes', 'waterline', '--h', '0.01'],
        /--slope: Slope alpha must be above 0 degrees/,
      ],
      [
        [...tool, '--slope', '30', '--passes', 'waterline', '--cross-radius', '0', '--h', '0.01'],
        /from 0.001 mm to 1000000 mm/,
      ],
      [[...tool, '--slope', '30', '--h', '-1'], /--h: Scallop height h must be at least 1e-9 mm/],
    ];
    for (const [args, message] of cases) {
      const r = await runMain(args);
      expect(r.code, args.join(' ')).toBe(2);
      expect(r.stderr.trim().split('\n'), r.stderr).toHaveLength(1);
      expect(r.stderr).toMatch(message);
      expect(r.stderr).not.toMatch(/NaN|Infinity/);
    }
  });

  it('waterline on a steep plane refuses h above the shank height Rcr (1 - sin alpha), naming it', async () => {
    const r = await run([...tool, '--slope', '80', '--passes', 'waterline', '--h', '0.5']);
    expect(r.code).toBe(2);
    const limit = Number(/below ([\d.e-]+) mm/.exec(r.stderr)?.[1]);
    expect(Math.abs(limit - (1 - Math.sin(80 * deg))), r.stderr).toBeLessThan(1e-8);
    expect(r.stderr).toMatch(/shank/);
  });
});
