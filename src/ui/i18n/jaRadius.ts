/**
 * A doubly curved point's charts in Japanese (issue 30): L against each principal radius, in the
 * terms of ja.ts (凸, 凹, 直線, 食い込み); symbols kept. Part of ja.ts.
 */
import type { RadiusWords } from './catalogue';

const KIND = { convex: '凸', concave: '凹', straight: '直線' } as const;

export const JA_RADIUS: RadiusWords = {
  radius: (kind, size) => (kind === 'straight' ? '直線' : `${KIND[kind]} ${size}`),
  title: (u, self, other, held, current) =>
    `|${self}| [${u}] に対する L [${u}]、対数軸（${other} は ${held} で固定。R、Rcr、姿勢、h は固定。破線：現在の ${self} = ${current}）`,
  xLabel: (self, u) => `|${self}| [${u}]（対数）`,
  description: (title) => `${title}。現在の半径での値をグラフの横に示します。`,
  band: { gouging: '食い込み', limit: 'h が限界以上' },
  legendHead: (self, current) => `${self} ${current} での値：`,
  branch: (self, kind) => `${self} ${KIND[kind]}`,
  seeBelow: '答えなし（下記参照）',
  summary: (rf, rc, L, rfStraight, rcStraight) =>
    `Rf ${rf}、Rc ${rc} で L = ${L}。Rf を直線にすると ${rfStraight}、Rc を直線にすると ${rcStraight}。`,
  gap: (side, self, from, to, other, held, reason) =>
    `${to === null ? `|${self}| = ${from} 付近` : `|${self}| = ${from}〜${to} 付近`}では${side === 'concave' ? '凹' : '凸'}の L がありません（${other} は ${held} で固定）：${reason === 'gouging' ? 'この姿勢では工具が面に食い込みます' : 'そこでは h がフランクまたはシャンクの限界以上です'}。`,
};
