/**
 * The feed per tooth at which one pass's crest on its own CC path stands a given height above its
 * lowest point, in closed form from two points of the section (no runout). Lengths mm, angles radians.
 *
 * Derivation (envelope.ts, rowEnvelope.ts). On pass 0's CC path (local y = 0) the section curve is the
 * same at every feed; the teeth cut its point P at height z(P) where Phi(P) = psi(P) - omega w(P)
 * meets a level -omega x + j pitch (omega = pitch / fz, pitch = 2 pi / z). The crest of the line is
 * where the first events on either side of the section's lowest point are equally high: two points A
 * (right, w larger) and B (left) at the crest's height z_c, one level apart with the lowest point
 * between them. Where Phi falls along the lower arc from B to A (omega w outruns psi, the usual case),
 * Phi(A) - Phi(B) = -pitch:
 *
 *     (psi_A - psi_B) - (pitch / fz) (w_A - w_B) = -pitch,   fz = (w_A - w_B) / (1 + (psi_A - psi_B) / pitch).
 *
 * So the feed whose crest stands h above the lowest point follows from A and B at z_c = z_low + h.
 * It holds only while that pass alone shapes the line and Phi falls monotonically over the arc (no
 * other level met in between, psi not turning through the axis): a caller must check the feed marks
 * at the feed it returns (feedMarks.ts: balancedFeed does).
 */
import { bracketedRoot, type Objective } from '../math/rootFinder';
import { SectionPoint } from './bodySection';
import { PassRow } from './envelope';
import type { ToothModel } from './toothModel';

/** The height of the section's point at polar angle alpha, minus a target height. */
class HeightAtAngle implements Objective {
  readonly p = new SectionPoint();
  constructor(
    private readonly row: PassRow,
    private readonly targetMm: number,
  ) {}
  value(alpha: number): number {
    this.row.section.pointAt(this.row.cw, this.row.cz, alpha, this.p);
    return this.p.z - this.targetMm;
  }
}

/**
 * The feed per tooth (mm) at which pass 0's crest on its CC path stands `heightMm` above the
 * section's lowest point, by the closed form of the module comment, or NaN where it gives none (the
 * height not below the polar centre of the section, a denominator not positive). The model's own fz
 * is ignored (the section does not depend on it); its flutes give the pitch. A candidate only: the
 * caller checks the marks at the feed returned.
 */
export function crestFeedMm(m: ToothModel, heightMm: number): number {
  const row = new PassRow(m, 0);
  if (!row.reaches) return Number.NaN;
  const zc = row.zStar + heightMm;
  if (!(heightMm > 0 && zc < row.cz)) return Number.NaN;
  // On either side of the lowest point (alpha = -pi/2, C straight above it) the height rises
  // monotonically up to C's own height (alpha = 0 right, -pi left), below the section's top.
  const right = new HeightAtAngle(row, zc);
  const aRight = bracketedRoot(right, -Math.PI / 2, 0, -heightMm, row.cz - zc, 0);
  right.value(aRight);
  const left = new HeightAtAngle(row, zc);
  const aLeft = bracketedRoot(left, -Math.PI / 2, -Math.PI, -heightMm, row.cz - zc, 0);
  left.value(aLeft);
  const a = right.p;
  const b = left.p;
  let dpsi = a.psi - b.psi;
  dpsi -= 2 * Math.PI * Math.round(dpsi / (2 * Math.PI));
  const denominator = 1 + dpsi / m.toothPitchRad;
  const fz = (a.w - b.w) / denominator;
  return denominator > 0 && fz > 0 ? fz : Number.NaN;
}
