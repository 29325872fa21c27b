/**
 * The three-axis chart "step against slope" in Japanese (issue 30): captions, axis titles, legends
 * and notes in the terms of ja.ts (水平ピック, Z ピッチ, 走査線, 等高線, 勾配); symbols kept. Part of ja.ts.
 */
import type { SlopeWords } from './catalogue';

/** Why a constant step leaves no cusp, by the core's code (core/threeAxis/errors.ts). */
const REFUSAL_WORDS: Readonly<Record<string, string>> = {
  'beyond-step': 'パスの間隔が広すぎて、カスプではなく壁が残ります',
  'shank-cuts': 'コーナではなく工具のシャンクがカスプを作ります',
  'flank-wall': 'パスが出会う前にフランクが壁になります',
  'wall-only': '側面が接触点から垂直に立ち上がり、どのピッチでもカスプはできません',
  'past-surface': '次のパスが面の使える部分の外に出ます',
  'needs-slope': '平らな底面では Z ピッチに意味がありません',
  gouging: '工具が面に食い込みます',
};

export const JA_SLOPE: SlopeWords = {
  stepTitle: (u, h, slope) =>
    `h = ${h} での勾配 [°] に対する CAM で指定するピッチ [${u}]（R、Rcr は固定。破線：現在の勾配 = ${slope}）`,
  cuspTitle: (u, constant, h) => `一定の ${constant} が残すカスプ高さ [${u}] と勾配 [°]（点線：h = ${h}）`,
  slopeAxis: '面の勾配 alpha [°]',
  stepAxis: (u) => `ピッチ [${u}]`,
  scallopAxis: (u) => `カスプ高さ [${u}]`,
  description: (title, sentence) => `${title}。${sentence}`,
  legendHead: (slope) => `勾配 = ${slope} での値：`,
  strategy: (passes, psi) => (passes === 'raster' ? `Lxy（走査線、psi = ${psi}）` : 'dz（等高線）'),
  floor: '平らな底面でのピッチ Lxy0',
  scallopOf: (constant) => `${constant} のカスプ高さ`,
  none: '答えなし',
  gap: 'h が限界以上',
  noStepAbove: (slope, h, revolution) =>
    `${slope} を超える勾配にはピッチがありません。そこでは h = ${h} が工具の残せる最大のカスプ（フランクまたはシャンク${revolution ? '、または面の端' : ''}）に達します。90° は垂直な壁です。`,
  crossing: (crossing, psi, h, both, revolution) => {
    const raster = `psi = ${psi} の走査線`;
    const where = revolution ? '（その勾配の平面で）' : '';
    if (crossing === null)
      return `カスプ高さ ${h} では等高線と${raster}は交わりません${where}。両方が有効などの勾配でも${raster}の方が大きなピッチになります。`;
    return `同じカスプ高さ ${h} では、${crossing} より急な勾配で等高線の方が${raster}より大きなピッチになり、それより緩い勾配では${raster}の方が大きくなります${both === null ? '' : `（${crossing} でどちらも ${both}）`}${where}。`;
  },
  refusal: (step, from, to, code) =>
    `${to === null ? `${from} 付近` : `${from}〜${to} 付近`}では一定の ${step} はカスプを残しません：${REFUSAL_WORDS[code] ?? '計算がこれを受け付けません'}。`,
};
