/**
 * The Machined surface view in Japanese (issue 30): the simulation's lines, the heights' scale, the
 * comparison of the simulated with the exact cusp height (カスプ高さ), the profilometer trace
 * (Rz, Ra, Rq kept: JIS B 0601). Part of ja.ts.
 */
import type { Catalogue } from './catalogue';

export const JA_SURFACE: Catalogue['surface'] = {
  invalid: '古い表示：入力が無効なため、シミュレーションするものがありません。',
  failed: 'シミュレーションなし：ソルバが解を得られませんでした。入力を変えると再計算します。',
  pending: (percent) => `パスをシミュレーション中${percent === null ? '' : `：${percent} %`}…`,
  reasons: {
    'planes-only':
      'シミュレーションは平面のみ対象です。円筒でも上の厳密解はそのまま成り立ちますが、比べるシミュレーション面はありません。',
    'no-scallop': 'カスプなし：平らな底面が平面に密着して平らな面を残すため、シミュレーションするものがありません。',
    none: 'シミュレーションなし。',
  },
  exception: () => 'シミュレーションなし：計算中に予期しないエラーが発生しました。',
  exaggeration: (k, unit) =>
    `${k === null ? '高さは実寸' : `高さを ${k} 倍に拡大（高さ方向の誇張）`}。色：最も低い点からの高さ（${unit}）。`,
  comparison: (simulated, exact, diff, within, bound, cells, passes) =>
    `シミュレーションのカスプ高さ ${simulated}、厳密解 ${exact}：差 ${diff} は、示した分解能の限界 ${bound} ${within ? 'の範囲内' : 'を超えています'}（${cells.replace(' x ', ' × ')} セル、${passes} パス）。`,
  traceLabel: 'パスを横切る粗さ曲線（Rz、Ra、Rq を表示）',
  traceCaption: (passes, rz, ra, rq) =>
    `シミュレーションの粗さ曲線、${passes} パス。厳密解：Rz ${rz}、Ra ${ra}、Rq ${rq}`,
  meanLine: '平均線',
  sceneLabel: 'シミュレーションした加工面の 3D 表示（高さで色分け）',
};
