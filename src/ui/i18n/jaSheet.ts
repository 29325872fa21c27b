/**
 * The shop sheet in Japanese (issue 30): the sheet's headings, lines, legend and buttons in the
 * shop's terms (ピックフィード, カスプ高さ, 前傾角, 水平ピック, Z ピッチ; as ja.ts); the symbols and the
 * marks' letters kept. Part of ja.ts.
 */
import type { Catalogue } from './catalogue';

const STEP = {
  interval: 'ピックフィード L（隣り合うパスの間隔、面に沿って）',
  horizontalStep: '水平ピック Lxy（隣り合う走査線パスの水平距離、CAM で指定する値）',
  stepDown: 'Z ピッチ dz（隣り合う等高線の段の高さの差、CAM で指定する値）',
} as const;

export const JA_SHEET: Catalogue['sheet'] = {
  title: (step, u) => `現場用シート：${step}（${u}）`,
  tool: (d, r, rcr) => `工具：D ${d}（R ${r}）、コーナ半径 Rcr ${rcr}`,
  fiveAxis: (tilt, pattern, surface) =>
    `5軸、傾斜角 ${tilt}°、${pattern === 'one-way' ? '片方向' : '往復'}のパス、加工面：${surface}`,
  threeAxis: (passes, angle, surface) =>
    `3軸、工具は垂直、${passes === 'raster' ? '走査線' : '等高線'}のパス${angle === null ? '' : `（最大傾斜線から ${angle}°）`}、加工面：${surface}`,
  surface: (s) => {
    if (s.kind === 'plane') return '平面';
    if (s.kind === 'sloped-plane') return '傾斜した平面';
    if (s.kind === 'cylinder')
      return `${s.concave ? '凹' : '凸'}の円筒、Rs ${s.radius}、軸は${s.axis === 'feed' ? '送り方向' : '送りに直交'}`;
    if (s.kind === 'doubly-curved') return `複曲面上の点、Rf ${s.feed}、Rc ${s.cross}（負は凹）`;
    return `回転面、Rf ${s.feed ?? '直線'}、Rc ${s.cross ?? '直線'}（負は凹）`;
  },
  axes: (u, columns, step) =>
    `行：カスプ高さ h（${u}）。列：${columns === 'lead' ? '前傾角 rho（°）' : '面の勾配（°）'}。値：${STEP[step]}（${u}）。`,
  made: (date) => `厳密解、ピックフィード計算機、${date}。`,
  region: 'ピックフィードの表',
  caption: (step, u, columns) =>
    `${step}（${u}）：行はカスプ高さ h（${u}）、列は${columns === 'lead' ? '前傾角' : '面の勾配'}（°）`,
  column: { lead: '前傾角', slope: '勾配' },
  deg: '°',
  yourH: '（指定の h）',
  where: (h, columns, deg) => `h ${h}、${columns === 'lead' ? '前傾角' : '勾配'} ${deg}°`,
  markLabel: (letter, where) => `${where} の ${letter}：理由を表示`,
  markReason: (letter, where) => `${where} の ${letter}：`,
  marks: {
    wall: 'h がこの姿勢の限界以上：フランクかシャンクが壁を残し、カスプになりません。',
    gouge: 'この姿勢では工具が面に食い込みます。',
    range: 'この工具ではここで扱える範囲の外です（前傾角、傾斜角または勾配）。',
  },
  noScallop: 'カスプなし：平らな底面にフラットエンドが密着し、2R までのどのピックフィードでも平らに削れます。',
  ownRow: (h) => `太字の行：指定のカスプ高さ h = ${h}。`,
  hintHover: '記号にポインタを重ねるかクリックすると理由を表示します。個々の条件は計算機で求められます。',
  hintTouch: '記号をタップすると理由を表示します。個々の条件は計算機で求められます。',
  heightsLabel: (u, max) => `カスプ高さ h（${u}）、${max} 個まで、空白で区切る（指定の h を追加）`,
  heightsError: (u, max, got) =>
    `カスプ高さ：0 ${u} より大きい値を 1〜${max} 個、空白で区切って入力してください${got === null ? '' : `（入力：${got}）`}。`,
  csv: 'CSV をダウンロード',
  print: '印刷',
  close: '閉じる',
  saved: (name) => `${name} を保存しました。`,
  refusals: {
    leadRange: '前傾角 rho は 0° 以上 90° 未満にしてください。',
    curvedGouge: 'この姿勢では工具がこの複曲面上の点に食い込みます。動く工具が接触点から離れた所で面の内側に入ります。',
    curvedWall: (limit, got) => `カスプ高さ h はこの点と姿勢では ${limit} 未満にしてください（入力：${got}）。`,
    noStepDown: 'ここでは等高線パスに Z ピッチがありません。',
  },
};
