/**
 * The page's three-axis lookup table (issue 28 point 2) read back by the command line: the table
 * of the question on screen (slopes x scallop heights, the programmed step) fed to `--batch` is
 * answered row for row with the same numbers (in mm the very same rows; in inches, with
 * `--unit inch`, the same numbers); The programmed steps
 * are checked against the sloped-plane solver's closed form Lxy = L sqrt(cos^2 psi + cos^2 alpha
 * sin^2 psi), dz = L sin alpha.
 */
import { describe, expect, it } from 'vitest';
import { parseCsv } from '../../src/cli/csv';
import { buildRequest } from '../../src/ui/request';
import { parseUrl } from '../../src/ui/state';
import { tableRequestOf } from '../../src/ui/tableRequest';
import { table } from '../../src/worker/jobs/table';
import { run } from './helpers';

function pageTable(query: string) {
  const built = buildRequest(parseUrl(query).state);
  if (!built.ok || built.request.mode !== 'three-axis') throw new Error('a three-axis question');
  const request = tableRequestOf(built.request, parseUrl(query).state.unit);
  const reply = table(request);
  if (!reply.ok) throw new Error(`no table: ${reply.reason}`);
  return { request, reply };
}

/** Rows as maps from the column (its unit suffix dropped) to the field. */
function rowsOf(csv: string): Array<Map<string, string>> {
  const [head, ...rows] = parseCsv(csv).filter((r) => !r.blank);
  const names = (head?.fields ?? []).map((f) => f.replace(/_(mm|in|deg)$/, ''));
  return rows.map((r) => new Map(names.map((n, i) => [n, r.fields[i] ?? ''])));
}

const RAD = Math.PI / 180;

/** A CSV's rows without its header. */
const body = (csv: string) => csv.slice(csv.indexOf('\n') + 1);

describe('three-axis lookup table read back by --batch', () => {
  it('raster at 30 degrees on a plane (mm): the same file back; Lxy = L D at every slope', async () => {
    const { reply } = pageTable('?machine=3axis&R=3&Rcr=1&slope=30&rasterAngle=30&h=0.01&unit=mm');
    const rows = rowsOf(reply.csv);
    expect(reply.csv.split('\n')[0]).toBe(
      'R_mm,Rcr_mm,h_mm,slope_deg,passes,rasterAngle_deg,interval_mm,horizontalStep_mm,stepDown_mm,lead_deg,tilt_deg,note,error',
    );
    expect(new Set(rows.map((r) => r.get('slope'))).size).toBe(18);
    let answered = 0;
    for (const r of rows) {
      if (r.get('error') !== '') continue;
      const a = Number(r.get('slope')) * RAD;
      const D = Math.sqrt(Math.cos(30 * RAD) ** 2 + Math.cos(a) ** 2 * Math.sin(30 * RAD) ** 2);
      expect(Number(r.get('horizontalStep'))).toBeCloseTo(Number(r.get('interval')) * D, 12);
      answered++;
    }
    expect(answered).toBeGreaterThan(reply.rows * 0.9);
    const back = await run(['--batch'], reply.csv);
    expect(back.stderr).toBe('');
    expect(back.code).toBe(0);
    // The batch writes the plain column names; every row the very same.
    expect(body(back.stdout)).toBe(body(reply.csv));
  });

  it('waterline on a surface of revolution (mm): its radii read back, the same file; dz = L sin alpha on a plane', async () => {
    const { reply } = pageTable(
      '?machine=3axis&R=3&Rcr=1&slope=40&passes=waterline&feedRadius=50&crossRadius=50&h=0.02&unit=mm',
    );
    const back = await run(['--batch'], reply.csv);
    expect(back.code).toBe(0);
    expect(body(back.stdout)).toBe(body(reply.csv));
    expect(rowsOf(reply.csv).filter((r) => r.get('stepDown') !== '').length).toBeGreaterThan(100);
    const plane = pageTable('?machine=3axis&R=3&Rcr=1&slope=40&passes=waterline&h=0.02&unit=mm').reply;
    for (const r of rowsOf(plane.csv).filter((x) => x.get('error') === ''))
      expect(Number(r.get('stepDown'))).toBeCloseTo(
        Number(r.get('interval')) * Math.sin(Number(r.get('slope')) * RAD),
        12,
      );
  });

  it('inches: every column names its unit; --batch --unit inch gives the same numbers', async () => {
    const { reply } = pageTable('?machine=3axis&R=0.25&Rcr=0.03&slope=30&rasterAngle=30&h=0.0004&unit=in');
    expect(reply.csv.split('\n')[0]).toBe(
      'R_in,Rcr_in,h_in,slope_deg,passes,rasterAngle_deg,interval_in,horizontalStep_in,stepDown_in,lead_deg,tilt_deg,note,error',
    );
    const back = await run(['--batch', '--unit', 'inch'], reply.csv);
    expect(back.stderr).toBe('');
    expect(back.code).toBe(0);
    const mine = rowsOf(reply.csv);
    const theirs = rowsOf(back.stdout);
    expect(theirs.length).toBe(mine.length);
    expect(
      mine.filter((r) =>
        /must be below [\d.]+ in at this slope and raster angle \(got [\d.]+\)/.test(r.get('error') ?? ''),
      ).length,
    ).toBeGreaterThan(0);
    mine.forEach((row, i) => {
      // The reasons too, worded in inches as the batch words them.
      expect(theirs[i]?.get('error'), `${i} error`).toBe(row.get('error'));
      for (const column of ['h', 'slope', 'interval', 'horizontalStep', 'lead', 'tilt']) {
        const a = row.get(column) ?? '';
        const b = theirs[i]?.get(column) ?? '';
        if (a === '' || b === '') expect(b, `${i} ${column}`).toBe(a);
        else expect(Math.abs(Number(a) - Number(b)), `${i} ${column}`).toBeLessThanOrEqual(1e-12 * Math.abs(Number(a)));
      }
    });
  });
});
