/**
 * The lookup table's file (lookupDownload.ts): its name and the status line's summary of it. Loaded
 * with the grid's code on the first click, not with the first result.
 */
import { formatInputNumber, fromMm, unitSymbol } from '../core/input/units';
import type { TableReply, TableRequest } from '../worker/protocol';
import type { Catalogue } from './i18n/catalogue';
import { localDecimal } from './i18n/langChoice';

/**
 * The file name of a table: its tool, pattern and surface, then its unit, lengths in that unit:
 * `step-over-table_5-axis_R3_Rcr1_one-way_plane_mm.csv` (the machine first: the grid spans the
 * five-axis lead and tilt), on a cylinder `..._one-way_Rs-30_cross_mm.csv`
 * (the signed radius, negative for a concave cylinder, and the axis, as the CSV's columns give
 * them); in inches `step-over-table_5-axis_R0.25_Rcr0.0625_one-way_plane_in.csv`. Three-axis:
 * `step-over-table_3-axis_R3_Rcr1_raster30_plane_mm.csv`, `..._waterline_plane_mm.csv`, on a
 * surface of revolution `..._waterline_Rf50_Rc-20_mm.csv` (the grid spans the slope).
 */
export function tableFileName(request: TableRequest): string {
  const unit = request.unit ?? 'mm';
  const n = (mm: number) => formatInputNumber(fromMm(mm, unit));
  const t = request.tool;
  const s = t.surface;
  const r = request.radii;
  const x = request.threeAxis?.case;
  if (x !== undefined) {
    const passes = x.passes === 'raster' ? `raster${formatInputNumber(x.rasterAngleDeg ?? 0)}` : 'waterline';
    const rev = x.revolution;
    const surface =
      rev === null
        ? 'plane'
        : `Rf${rev.feedRadiusMm === null ? 'straight' : n(rev.feedRadiusMm)}_Rc${rev.crossRadiusMm === null ? 'straight' : n(rev.crossRadiusMm)}`;
    return `step-over-table_3-axis_R${n(x.toolRadiusMm)}_Rcr${n(x.cornerRadiusMm)}_${passes}_${surface}_${unitSymbol(unit)}.csv`;
  }
  const surface =
    r !== undefined
      ? `Rf${n(r.feedRadiusMm)}_Rc${n(r.crossRadiusMm)}`
      : s.kind === 'cylinder'
        ? `Rs${n(s.radiusMm)}_${s.axis}`
        : 'plane';
  return `step-over-table_5-axis_R${n(t.toolRadiusMm)}_Rcr${n(t.cornerRadiusMm)}_${t.pattern}_${surface}_${unitSymbol(unit)}.csv`;
}

/** What the status line says about a table saved, in `c`'s language (null: English). */
export function tableSummary(reply: Extract<TableReply, { ok: true }>, c: Catalogue | null = null): string {
  const g = reply.request.grid;
  const unit = reply.request.unit ?? 'mm';
  if (c !== null) {
    const ends = (v: readonly number[]) =>
      [localDecimal(formatInputNumber(v[0] ?? 0), c), localDecimal(formatInputNumber(v.at(-1) ?? 0), c)] as const;
    const x = reply.request.threeAxis;
    return c.said.tableSaved(
      tableFileName(reply.request),
      reply.rows,
      ends(g.scallopHeightsMm.map((mm) => fromMm(mm, unit))),
      unitSymbol(unit),
      x !== undefined
        ? { kind: 'three-axis', slope: ends(x.slopesDeg), step: x.case.passes === 'raster' ? 'Lxy' : 'dz' }
        : { kind: 'five-axis', lead: ends(g.leadAnglesDeg), tilt: ends(g.tiltAnglesDeg) },
      reply.emptyCells,
    );
  }
  const range = (v: readonly number[]) => `${formatInputNumber(v[0] ?? 0)} to ${formatInputNumber(v.at(-1) ?? 0)}`;
  const h = g.scallopHeightsMm.map((mm) => fromMm(mm, unit));
  const axes =
    reply.request.threeAxis !== undefined
      ? `x slope ${range(reply.request.threeAxis.slopesDeg)} deg, the programmed step (${reply.request.threeAxis.case.passes === 'raster' ? 'Lxy' : 'dz'}) in each row; `
      : `x lead ${range(g.leadAnglesDeg)} deg x tilt ${range(g.tiltAnglesDeg)} deg; `;
  return (
    `Saved ${tableFileName(reply.request)}: ${reply.rows} rows, h ${range(h)} ${unitSymbol(unit)} ` +
    axes +
    `${reply.emptyCells} cells outside the valid domain are left empty, the reason in the error column.`
  );
}
