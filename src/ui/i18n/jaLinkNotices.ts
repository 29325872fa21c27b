/**
 * A link notice's details in Japanese (issue 30; read back by linkNotices.ts): the parameters'
 * names and the values quoted kept as the link gives them. Part of ja.ts.
 */
import type { LinkNoticeWords } from './catalogue';

const list = (values: readonly string[]) => values.join('、');

export const JA_LINK_NOTICES: LinkNoticeWords = {
  separator: '',
  missing: (name, fallback) => `${name} がリンクにありません。既定値 ${fallback} を使います。`,
  notNumber: (quoted, then) =>
    `リンクの ${quoted} は数値ではありません。${
      then.kind === 'empty'
        ? '空欄にします。'
        : then.kind === 'default'
          ? `既定値 ${then.value} を使います。`
          : then.kind === 'plane'
            ? `平面を使います（円筒の半径の既定値は ${then.value}）。`
            : '直線（曲率なし）を使います。'
    }`,
  notUsed: (given, [a, b]) => `リンクに ${given} があるので、${a} と ${b} は使いません。`,
  both: (a, b, used) => `リンクに ${a} と ${b} の両方があります。${used} を使います（${b} は無視します）。`,
  surfaceBoth: (radius, rf, rc) =>
    `リンクに ${radius} と ${rf} または ${rc} の両方があります。${rf} と ${rc} を使います（リンクは面を一通りで与えます）。`,
  repeated: (name, times, first, ignored, more) =>
    `${name} がリンクに ${times} 回あります。最初の ${first} を使います（${list(ignored)}${more > 0 ? `、ほか ${more} 個` : ''} は無視します）。`,
  notOneOf: (quoted, values, then) =>
    `リンクの ${quoted} は ${list(values)} のいずれでもありません。${
      then === null
        ? ''
        : then.kind === 'using'
          ? `${then.value} を使います。`
          : then.kind === 'showing'
            ? `${then.value} で表示します。`
            : then.kind === 'system'
              ? 'システムの配色に従います。'
              : 'プレゼンテーションモードはオフです。'
    }`,
};
