/**
 * The step-through of the paper's 3D procedure in Japanese (issue 30): its 31 steps' captions (the
 * boxes of the paper's Figure 1 as 図 1 のボックス), the counter, the gauge, the buttons and the notes,
 * in the terms of ja.ts and the README's glossary (フランク, 断面, リング角, h 擬似平面, 単一接触); the
 * paper's symbols (L, h, Rcr, d_s, gamma, P_hp, wR, wL) kept. Part of ja.ts.
 */
import type { StepperWords } from './teachWords';

export const JA_STEPPER: StepperWords = {
  step: (k, n) => `ステップ ${k}/${n}。`,
  side: (flank) => (flank === 'right' ? '右フランク（+Y）' : '左フランク（-Y）'),
  merged: (what, from, to, count) =>
    what === 'sections'
      ? `断面 ${from}〜${to} をまとめて示します（3D 表示とゲージで同じに見える ${count} 個の断面）。`
      : `探索パス ${from}〜${to} をまとめて示します（${count} 回のパス。どれも範囲をさらに狭めますが、その差は 3D 表示で見分けられません）。`,
  start: (side, gamma, ds, rcr) =>
    `${side}。図 1 のボックス 2（式 (1)）：リング角 gamma = ${gamma}° の断面から始めます。ここでリングは最下点より h/2 上にあります。d_s = ${ds}（Rcr = ${rcr} と比べる）。`,
  approach: (side, merged, gamma, ds, gap) =>
    `${side}。図 1 のボックス 6〜11：リングに沿って d_s = Rcr に向かって進みます。${merged}gamma = ${gamma}° の断面：d_s = ${ds}（Rcr - d_s = ${gap}）。`,
  single: (side, gamma) =>
    `${side}。図 1 のボックス 12〜14：gamma_scp = ${gamma}° の断面が h 擬似平面に 1 点で接します（d_s = Rcr）。この断面が探索範囲の端になります。`,
  noSingle: (side) => `${side}：どの断面も h 擬似平面と交わる（単一接触がない）ので、リングの半周全体を探索します。`,
  search: (side, sections, from, to, gamma, out, merged) =>
    `${side}。図 1 のボックス 16〜25：gamma = ${from}° から ${to}° までの ${sections} 個の断面と、それぞれが平面と交わる最も遠い点 P_hp[i]。最良：gamma = ${gamma}°、${out === null ? '交点なし' : `接触点から ${out} 外側`}。範囲をその両隣の間に狭めます。${merged}`,
  flankConverged: (side, width, out, gamma) => `${side}が収束：gamma* = ${gamma}° で ${width} = ${out}。`,
  closingUntilted: (half, exact) =>
    `図 1 のボックス 26：収束しました。各フランクで L/2 = ${half}。厳密解法では ${exact} です。`,
  closingTilted: (wR, wL, exactR, exactL) =>
    `図 1 のボックス 26：両フランクで収束しました。wR = ${wR}、wL = ${wL}。厳密解法では wR = ${exactR}、wL = ${exactL} です。`,
  same: {
    'single-contact':
      '3D 表示はほとんど変わりません。最後の接近断面がすでに単一接触の断面上にあり、このステップはそれを確かめて（d_s = Rcr）その点を示します。',
    search: '3D 表示はほとんど変わりません。探索は単一接触の点から始まります。',
    converged:
      '3D 表示は最後の探索パスを候補点なしで示します。探索はもう動かないので、その最良点がこのフランクの答えです。',
  },
  counter: (k, n) => `ステップ ${k}/${n}`,
  gaugeLabel: 'd_s / Rcr（0 からの線形目盛）：',
  noDs: ' ここには d_s はありません（探索：範囲の両端の間の断面）',
  ds: (ratio, ds, rcr) => ` ${ratio}：d_s = ${ds}、Rcr = ${rcr}`,
  play: '再生',
  playOne: '再生（1 ステップ）',
  pause: '一時停止',
  back: '< 戻る',
  forward: '進む >',
  names: {
    controls: 'ステップの操作',
    first: '最初のステップ',
    back: '1 ステップ戻る',
    forward: '1 ステップ進む',
    last: '最後のステップ',
  },
  intro:
    '3D 表示には、たどった各断面（紫）、各探索パスの候補点 P_hp[i]、見つかった点を、まず右フランク（+Y）、次に左フランクについて示します。同じに見えるステップは 1 つにまとめます。',
  motion:
    '「視差効果を減らす」設定が有効です。「再生」はステップをアニメーションせず、押すたびに次のステップを示します。',
  cylinder:
    '論文の 3D 手順（図 1）はトーラスの断面を h 擬似平面に対して探索するので、平面の場合にだけ示します。この円筒では厳密解法が円筒そのものを解きます（結果と送り直交断面を参照）。手順を順に見るには平面を選んでください。',
};
