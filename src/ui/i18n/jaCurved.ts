/**
 * A doubly curved point's refusals in Japanese (issue 30), worded from the worker's data by
 * curvedText.ts in the terms of ja.ts and the glossary (食い込み, 側面, シャンク, カスプ). Part of ja.ts.
 */
import type { CurvedWords } from './catalogue';

const gotOf = (g: string) => `入力：${g}`;
const gouged = '工具が接触点以外で面に食い込みます';

export const JA_CURVED: CurvedWords = {
  beyondMax: (l, max, g) =>
    `${l}はこの点では ${max} 未満にしてください（${gotOf(g)}）。これ以上離れたパスは壁を残します。`,
  aboveLimit: (l, limit, g, shank, right) =>
    `${l}はこの点では ${limit} 未満にしてください（${gotOf(g)}）。それを超えると${
      shank
        ? `コーナ半径ではなくシャンク（${right ? '右' : '左'}側）がカスプを作ります`
        : `${right ? '右' : '左'}の側面がカスプではなく壁を残します`
    }。`,
  outOfRange: (l, from, to, g) =>
    `${l}は ${from} から ${to} までの半径にしてください（${gotOf(g)}）。曲率なしには「直線」を選んでください。`,
  held: (other, r) => (r === null ? `${other} は直線` : `${other} = ${r} は固定`),
  gouging: (kind, l, r, held, g) =>
    kind === 'concave-at-least'
      ? `${l}は凹のとき ${r} 以上にしてください（${held}、${gotOf(g)}）。それより小さいと${gouged}。`
      : kind === 'convex-at-most'
        ? `${l}は凸で ${r} 以下にしてください（${held}、${gotOf(g)}）。それより平らだと${gouged}。`
        : kind === 'not-concave'
          ? `${l}は凸または直線にしてください（${held}、${gotOf(g)}）。凹ではどの半径でも食い込みます。`
          : `${l}：どの半径でも工具が面に食い込みます（${held}、${gotOf(g)}）。もう一方の半径、工具またはその姿勢を変えてください。`,
  missing: (l) => `${l}が空です：半径を入力するか、「直線」を選んでください。`,
  notNumber: (l, g) => `${l}は数値にしてください（${gotOf(`"${g}"`)}）。`,
  positive: (l, g) => `${l}は正の数にしてください。凸か凹かは横で選びます（${gotOf(g)}）。`,
  atPoint: ['この面', 'この点'],
};
