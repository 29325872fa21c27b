/**
 * The five-axis comparison charts in Japanese (issue 30): captions, axis titles, legends and notes
 * in the terms of ja.ts (ピックフィード, 前傾角, 傾斜角); the procedures' names kept. Part of ja.ts.
 */
import type { ChartWords } from './catalogue';

export const JA_CHART: ChartWords = {
  leadTitle: (u, rho) => `前傾角 rho [°] に対する L [${u}]（R、Rcr、beta、h は固定。破線：現在の rho = ${rho}）`,
  errorTitle: (u) => `前傾角に沿った各近似の厳密解からの誤差（符号付き）[${u}]`,
  tiltTitle: (u, beta) => `傾斜角 beta [°] に対する L [${u}]（R、Rcr、rho、h は固定。破線：現在の beta = ${beta}）`,
  leadAxis: '前傾角 rho [°]',
  tiltAxis: '傾斜角 beta [°]',
  errorAxis: (u) => `誤差 [${u}]`,
  description: (title) => `${title}。現在の角度での値をグラフの横に示します。`,
  legendHead: (angle, deg) => `${angle} = ${deg}° での値：`,
  leadOnly: '（前傾のみ）',
  seeBelow: '答えなし（下記参照）',
  none: '答えなし',
  errorIn: { pct: '誤差を % で', length: '誤差を長さで', name: '誤差の単位' },
  rhoScale: { log: 'rho 軸：対数', linear: 'rho 軸：線形', name: '前傾角の軸' },
  summary: (rho, beta, values) => `rho = ${rho}°、beta = ${beta}° での L：${values}。`,
  noSummary: '現在の姿勢はグラフの範囲外です。',
  cylinder: (concave, axis) =>
    `この${concave ? '凹' : '凸'}の円筒（軸は${axis === 'feed' ? '送り方向' : '送りに直交'}）では、厳密解の曲線は円筒のものです（姿勢が面に食い込むところや h がフランクを超えるところにはありません）。近似は表と同じく平面として扱います。`,
  gap: (names, angle, from, to) =>
    `${to === null ? `${angle} = ${from}° 付近` : `${angle} = ${from}°〜${to}° 付近`}では ${names} の答えがありません：`,
  reasons: {
    exact: 'h がこの姿勢で残せる最大のカスプ高さ以上です（それを超えると工具はカスプではなく壁を残します）',
    sekineRhoZero: 'rho = 0 では投影した楕円が線分に退化します（長半径 Rshort/sin(rho) が無限大）',
    sekineShort: '楕円の短半径が 0 です',
    redonnetRhoZero: 'rho = 0 では有効半径 Rb/sin(rho) + Rcr が無限大です',
    bediRhoZero: 'rho = 0 では楕円（半軸 Rlong、Rlong sin(rho)）が平らになり、式 (11) が 0 で割ることになります',
    overflow:
      '有効半径があふれます（rho が 0 に近すぎて 1/sin(rho) が大きすぎます）。このモデルはここでは答えを出せません',
    flatBottom:
      '工具底の平らな部分が平面に乗っています（傾斜なしで rho = 0、または前傾角と傾斜角が小さすぎる）。そのため接触点の曲率半径は無限大です',
    sharpEdge: '接触点が鋭い角（Rcr = 0）で、半径 0 の円です',
    flatEnd: 'フラットエンドミル（Rcr = 0）にはコーナ半径の球がありません',
  },
  widest: (shape, symbol) =>
    `h がその${shape === 'circle' ? '円' : '楕円'}の最も幅の広い点より上にあります（${shape === 'circle' ? '半径' : '高さ'} ${symbol} が h より小さい）`,
};
