/**
 * Validation of the three-axis inputs: a waterline row's raster angle (issue 26 point 13). Waterline
 * passes follow the contour, psi = 90 degrees by definition, so a batch with one rasterAngle column
 * for mixed rows gives its waterline rows 90 or nothing: both are accepted and answered exactly as
 * without the column; any other angle on a waterline row is refused, naming 90.
 */
import { describe, expect, it } from 'vitest';
import { solveThreeAxis } from '../../../src/core/threeAxis/solve';
import { validateThreeAxis } from '../../../src/core/threeAxis/validate';
import { runMain } from '../../cli/helpers';

const waterline = { R: '3', Rcr: '1', slope: '40', passes: 'waterline' } as const;

describe('a waterline row with a raster angle', () => {
  it('90 (as text or number, with spaces) or empty is accepted and answers as without it', () => {
    const bare = validateThreeAxis(waterline, 'h', '0.01');
    if (!bare.ok) throw new Error(JSON.stringify(bare.errors));
    const answer = solveThreeAxis(bare.value);
    for (const rasterAngle of ['90', ' 90 ', '90.0', 90, '', undefined]) {
      const v = validateThreeAxis({ ...waterline, rasterAngle }, 'h', '0.01');
      expect(v, String(rasterAngle)).toEqual(bare);
      if (v.ok) expect(solveThreeAxis(v.value)).toEqual(answer);
    }
    // On a surface of revolution too.
    const rev = { ...waterline, feedRadius: '40', crossRadius: '-20' };
    expect(validateThreeAxis({ ...rev, rasterAngle: '90' }, 'h', '0.01')).toEqual(validateThreeAxis(rev, 'h', '0.01'));
  });

  it('any other angle is refused with a message naming 90 and the value given', () => {
    for (const rasterAngle of ['0', '45', '89.999', '90.001', '-90', '270']) {
      const v = validateThreeAxis({ ...waterline, rasterAngle }, 'h', '0.01');
      expect(v.ok, rasterAngle).toBe(false);
      if (v.ok) continue;
      expect(v.errors).toHaveLength(1);
      expect(v.errors[0]).toMatchObject({ field: 'rasterAngle', code: 'not-with', got: rasterAngle, limit: 90 });
      expect(v.errors[0]?.message).toBe(
        `Raster angle psi must be 90 degrees or left empty for waterline passes (got ${rasterAngle}): they follow the contour, psi = 90; other raster angles are for raster passes.`,
      );
    }
    const text = validateThreeAxis({ ...waterline, rasterAngle: 'abc' }, 'h', '0.01');
    expect(!text.ok && text.errors.map((e) => [e.field, e.code])).toEqual([['rasterAngle', 'not-a-number']]);
  });

  it('raster rows keep their angle', () => {
    const v = validateThreeAxis({ R: '3', Rcr: '1', slope: '40', passes: 'raster', rasterAngle: '30' }, 'h', '0.01');
    expect(v.ok && v.value.case).toMatchObject({ passes: 'raster', rasterAngleDeg: 30 });
  });

  it('a batch of mixed rows with one rasterAngle column answers the waterline rows at 90 and refuses the others', async () => {
    const csv =
      'R,Rcr,slope,passes,rasterAngle,h\n3,1,40,raster,30,0.01\n3,1,40,waterline,90,0.01\n3,1,40,waterline,,0.01\n3,1,40,waterline,45,0.01\n';
    const r = await runMain(['--batch'], csv);
    expect(r.code).toBe(0);
    const [head, ...rows] = r.stdout.trimEnd().split('\n');
    const cols = (head as string).split(',');
    const error = cols.indexOf('error');
    const dz = cols.indexOf('stepDown');
    const cells = rows.map((row) => row.split(','));
    expect(cells.slice(0, 3).map((c) => c[error])).toEqual(['', '', '']);
    expect(cells[1]?.[dz]).toBe(cells[2]?.[dz]);
    expect(Number(cells[1]?.[dz])).toBeGreaterThan(0);
    expect(rows[3]).toContain('must be 90 degrees or left empty for waterline passes (got 45)');
  });
});
