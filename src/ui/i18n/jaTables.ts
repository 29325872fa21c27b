/**
 * The paper's tables view in Japanese (issue 30): its notes, captions, head and the names of its
 * boxes and rows, in the terms of ja.ts (論文, 断面, 単一接触, 厳密解); the column symbols and the
 * paper's numbers kept. Part of ja.ts.
 */
import type { TableWords } from './teachWords';

export const JA_TABLES: TableWords = {
  note: '各セル：論文の値 / 再計算値（どちらの単位でも、論文と同じく mm）。強調表示：再計算値を丸めても論文の桁にならないもの。表 4〜5 は、論文と同じく、論文の 3D の L/2 で式 (12)〜(13) を評価します。条件をクリックすると計算機に読み込みます。',
  why: '論文の 3D の列が 0.0005〜0.013 mm 小さい理由：論文の図 1 は、式 (2) の eta を正規化するかどうかと、ステップ 15〜16 の探索をどこまで進めるかの 2 点を決めておらず、その探索範囲は真の最大値の手前で止まることがあります。もっともらしい読み方の一つ（式 (2) を印刷どおりに使い、範囲を単一接触の断面からその P_hp の角度までとする）では、R = 3、Rcr = 1、rho = 5、h = 0.10 で論文の 1.879 mm が得られますが、真の最大値は 1.892 mm です。ここでの厳密解は、トーラス面を細かく総当たりでサンプリングした値とも、論文自身の手順を収束まで進めた結果（段階表示）とも一致します。論文の列に合わせて調整したものではありません。',
  halfCaption: '表 2〜3：h に対する L/2 [mm]',
  heightCaption: '表 4〜5：論文の 3D の L/2 での h [mm]',
  halfName: '表 2〜3',
  heightName: '表 4〜5',
  region: (name) => `${name}（画面より広いときは横にスクロールします）`,
  table: '表',
  printedHalf: 'L/2（3D）[mm]',
  load: 'この条件を計算機に読み込む',
};
