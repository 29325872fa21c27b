/**
 * The finish box's worker messages and own sentences in Japanese (issue 30): each refusal of a
 * finish field from its data (the field's name as the page gives it, the bound in the user's unit,
 * what was typed), as the English ones do (core/finish/finishInput.ts); the areal parameters'
 * names as JIS B 0681-2 (ISO 25178-2) gives them. Part of ja.ts.
 */
import type { Catalogue, FinishErrorText } from './catalogue';

const gotOf = (t: FinishErrorText) => `（入力：${t.got}）`;
const what = (part: 'marks' | 'areal') => (part === 'areal' ? '面の粗さパラメータ' : '送りマーク');
const ONLY = '計算できるのは平面（任意の前傾角・傾斜角、片方向または往復）と 3 軸加工の傾斜した平面だけです。';

export const JA_FINISH: Catalogue['finishText'] = {
  errors: {
    missing: (t) => `${t.label}が未入力です。数値を入力してください。`,
    'not-a-number': (t) => `${t.label}は数値にしてください（入力：「${t.got}」）。`,
    'not-finite': (t) => `${t.label}は有限の数値にしてください${gotOf(t)}。`,
    'not-an-integer': (t) => `${t.label}は 1 から ${t.maxFlutes} までの整数の刃数にしてください${gotOf(t)}。`,
    'not-positive': (t) => `${t.label}は 0${t.unit === '' ? '' : ` ${t.unit}`} より大きくしてください${gotOf(t)}。`,
    negative: (t) => `${t.label}は 0${t.unit === '' ? '' : ` ${t.unit}`} 以上にしてください${gotOf(t)}。`,
    'too-small': (t) => `${t.label}は ${t.limit} 以上にしてください${gotOf(t)}。`,
    'too-large': (t) =>
      t.field === 'fz'
        ? `${t.label}は工具半径 R = ${t.limit} 以下にしてください${gotOf(t)}。`
        : t.field === 'runout'
          ? `${t.label}は R/10 = ${t.limit} 以下にしてください${gotOf(t)}。`
          : `${t.label}は ${t.limit} 以下にしてください${gotOf(t)}。`,
    'out-of-range': (t) => `${t.label}は 0 以上 1 未満（送り周期に対する割合）にしてください${gotOf(t)}。`,
    'both-feeds': () => '一刃送り fz か、送り速度 F と主軸回転数 n のどちらか一方を入力してください（両方は不可）。',
    'rate-too-small': (t) => `一刃送り fz = F / (n z) = ${t.rateFz} は ${t.limit} 以上にしてください。`,
    'rate-too-large': (t) => `一刃送り fz = F / (n z) = ${t.rateFz} は工具半径 R = ${t.limit} 以下にしてください。`,
    'not-computed-here': () => `この面では送りマークはまだ計算しません。${ONLY}`,
  },
  failure: (kind, part) =>
    kind === 'not-converged'
      ? `この送りでは${what(part)}を計算できません：刃の切削点の探索が収束しませんでした。より小さい fz を試してください。`
      : `ここでは${what(part)}が定まりません：パスの間の細い部分をどの刃も削りません（底刃が届きません）。より小さいピックフィードを試してください。`,
  scope: (kind) =>
    `${
      kind === 'cylinder'
        ? '円筒'
        : kind === 'doublyCurved'
          ? '複曲面上の点'
          : kind === 'waterlineRevolution'
            ? '回転面の等高線パス'
            : 'この面'
    }では送りマークはまだ計算しません。${ONLY}`,
  worker: (gaveUp, reason) =>
    gaveUp
      ? `仕上げ面なし：計算用ワーカーが停止しました（${reason}）。`
      : `仕上げ面の計算用ワーカーを再起動しました（${reason}）。再計算中…`,
  targetSa: {
    runout: '目標 Sa は振れなしで計算します：最適な組み合わせを求めるには振れ e を 0 にしてください（または空欄）。',
    tooLong:
      'この目標 Sa の探索は途中で止めました（数分かかるため）：組み合わせの送りが大きすぎるか、パスが多すぎます。代わりにピックフィードと送りを与えて仕上げ面を求めてください。',
    worker: (gaveUp, reason) =>
      gaveUp
        ? `組み合わせなし：計算用ワーカーが停止しました（${reason}）。`
        : `目標 Sa の計算用ワーカーを再起動しました（${reason}）。再計算中…`,
  },
  areal: {
    Sq: '二乗平均平方根高さ',
    Sz: '最大高さ（最も高い山頂から最も深い谷底まで）',
    Sp: '最大山高さ',
    Sv: '最大谷深さ',
    Ssk: 'スキューネス',
    Sku: 'クルトシス',
  },
  mapLabel: '1 周期のセルの高さ：最も低い点（青）から最も高い点（橙）まで色分け',
  mapScale: (period, across, sz) =>
    `1 周期のセル：送り方向（右）に ${period}、直角方向（下）に ${across}。青が最も低く、橙が最も高い点：その差 Sz = ${sz}。正方形に描画、縮尺は一致しません。`,
  x3pComputing: 'ワーカーで面を計算中…',
  x3pNone: (reason) => (reason === null ? 'x3p ファイルなし。' : `x3p ファイルなし：${reason}`),
  x3pGaveUp: (reason) => `x3p ファイルなし：計算用ワーカーが停止しました（${reason}）。`,
  x3pSaved: (fileName, size) => `${fileName} を保存しました：1 周期のセルの ${size} × ${size} 点の高さ。`,
};
