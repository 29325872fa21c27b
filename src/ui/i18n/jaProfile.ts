/**
 * The cross-feed profile in Japanese (issue 30): the plot's name, the notes over a curved surface's
 * section, the scale line, the exaggeration's choice, the buttons, the legend's words (the
 * procedures' names kept), the arc and the height bar. Part of ja.ts.
 */
import type { Catalogue } from './catalogue';

const side = (s: 'convex' | 'concave') => (s === 'convex' ? '凸' : '凹');

export const JA_PROFILE: Catalogue['profile'] = {
  plotPlane: '隣り合う 3 パスの送り直交断面',
  plotCylinder: (s, axis) =>
    `${side(s)}の円筒上の隣り合う 3 パスの送り直交断面（軸は${axis === 'feed' ? '送り方向' : '送りに直交'}）`,
  plotCurved: (rf, rc) => `複曲面上の点での隣り合う 3 パスの送り直交断面（Rf ${side(rf)}、Rc ${side(rc)}）`,
  noteCylinder: (s, radius, axis) =>
    axis === 'feed'
      ? `半径 ${radius} の${side(s)}の円筒、軸は送り方向：各パスは平面と同じ断面を残し、次のパスは円筒の軸のまわりに L/|Rs| 回転します。L は円弧に沿って測ります。高さは面から半径方向。`
      : `半径 ${radius} の${side(s)}の円筒、軸は送りに直交：円筒の軸を含むこの断面では面は直線です。各パスは工具を軸のまわりに回転させた形（平面の断面とは異なる）で、次のパスは軸に沿って L ずれます。高さは面から半径方向。`,
  noteCurved: (rf, rc) =>
    `複曲面上の点（送り方向 Rf ${rf}、直交方向 Rc ${rc}）：送り直交断面は半径 |Rc| の円です。各パスは主軸から見た両フランクの断面を残し、次のパスはそのまわりに L/|Rc| 回転します。L は円弧に沿って測ります。印は平面の答え、各円筒の答え、曲率補正した手順が次のパスを置く位置です。高さは面から半径方向。`,
  heightsPlane: '高さ',
  heightsSurface: '面からの高さ',
  curvatureTrue: '。面の曲率は実寸',
  scale: (k, heights, auto, capped, curvature) => {
    const a = auto ? '（自動）' : '';
    const c = capped === null ? '' : `（${capped} 倍では谷が折り返します）`;
    return k === 1 ? `実寸${a}${c}` : `${heights}を ${k} 倍に拡大${a}${c}${curvature}`;
  },
  exaggeration: '高さ方向の倍率',
  auto: '高さ方向：自動',
  trueScale: '実寸',
  vertical: (k) => `高さ方向 ${k} 倍`,
  zoomIn: '拡大',
  zoomOut: '縮小',
  reset: '表示を戻す',
  cusp: 'カスプを拡大',
  approximations:
    '近似式の断面は厳密なピックフィード L（厳密解が置く各パス）で描き、形を厳密な断面と比べます。それぞれが与えるピックフィードは結果の表にあります。',
  ring: 'リング楕円（a = Rb、b）',
  nextPass: '：次のパス',
  cylinderAlong: '送り方向の円筒（Rf を無視）',
  cylinderAcross: '送りに直交する円筒（Rc を無視）',
  arc: '（円弧）',
  high: (length, k) => `高さ ${length}（${k} 倍で描画）`,
};
