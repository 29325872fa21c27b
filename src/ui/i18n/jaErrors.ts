/**
 * The input errors in Japanese (issue 30): one sentence per error code, naming the constraint and
 * its limit in the user's unit, as the English ones do (core/input/inputErrors.ts). Part of ja.ts.
 */
import { MAX_SURFACE_RADIUS_MM, MIN_SURFACE_RADIUS_MM } from '../../core/input/limits';
import type { Catalogue } from './catalogue';
import { type ErrorText, radiusGougingParts } from './errorText';

const gotOf = (t: ErrorText) => `（入力：${t.got}）`;
const side = (s: 'right' | 'left' | undefined) => (s === 'left' ? '左' : '右');

/** A radius-gouging error (a doubly curved point): what this radius must be, or the other. */
function radiusGouging(t: ErrorText): string {
  const { me, them, held: heldRadius, mag, kind, other: o } = radiusGougingParts(t);
  const held = heldRadius === null ? `${them} を直線` : `${them} = ${heldRadius}`;
  const need =
    kind === 'concave-at-least'
      ? `${t.label}：${held}のままでは、この工具と姿勢で凹の ${me} は ${mag} 以上必要です${gotOf(t)}`
      : kind === 'convex-at-most'
        ? `${t.label}：${held}のままでは、この工具と姿勢で ${me} は凸で ${mag} 以下にしてください${gotOf(t)}`
        : kind === 'not-concave'
          ? `${t.label}：${held}のままでは、この工具と姿勢で ${me} は直線か凸にしてください${gotOf(t)}。凹ではどの半径でも食い込みます`
          : `この工具は ${held}のまま、どの半径の ${me} でもこの点に食い込みます${gotOf(t)}`;
  const other =
    o?.kind === 'concave-at-least' && o.radius !== null
      ? `。または ${me} をそのままにして、凹の ${them} を ${o.radius} 以上に`
      : o?.kind === 'convex-at-most' && o.radius !== null
        ? `。または ${me} をそのままにして、凸の ${them} を ${o.radius} 以下に`
        : o?.kind === 'not-concave'
          ? `。または ${me} をそのままにして、${them} を直線か凸に`
          : o?.kind === 'none'
            ? `。${me} をそのままにすると、どの ${them} でも解消しません`
            : '';
  return `${need}${other}（工具が接触点から離れた所で面の下に入り込みます）。`;
}

/** The shank's lean and what would help, for a shank-gouging error. */
function shankHelp(t: ErrorText): { lean: string; help: string } {
  const lean = t.angle(t.e.shankLean?.leanDeg ?? 45);
  const help =
    t.e.shankLean?.axis === 'cross'
      ? '前傾角を小さくすると改善します（円筒の軸方向から見るとシャンクは前傾角だけ傾き、傾斜角は関係しません）。'
      : '傾斜角か前傾角を小さくすると改善します。';
  return { lean, help };
}

export const JA_ERRORS: Catalogue['errors'] = {
  missing: (t) => `${t.label}が未入力です。数値を入力してください。`,
  'not-a-number': (t) => `${t.label}は数値で入力してください（入力：「${t.got}」）。`,
  'not-finite': (t) => `${t.label}は有限の数値で入力してください${gotOf(t)}。`,
  'not-positive': (t) => `${t.label}は 0 ${t.unit} より大きくしてください${gotOf(t)}。`,
  negative: (t) => `${t.label}は 0 ${t.unit} 以上にしてください${gotOf(t)}。`,
  'too-small': (t) => `${t.label}は ${t.limit} 以上にしてください${gotOf(t)}。`,
  'too-large': (t) => `${t.label}は ${t.limit} 以下にしてください${gotOf(t)}。`,
  'out-of-range': (t) =>
    t.e.field === 'surfaceRadius' || t.e.field === 'feedRadius' || t.e.field === 'crossRadius'
      ? `${t.label}は ${t.length(MIN_SURFACE_RADIUS_MM)} から ${t.length(MAX_SURFACE_RADIUS_MM)} の半径にしてください${gotOf(t)}。`
      : t.e.field === 'rho'
        ? `${t.label}は 0 度以上 90 度未満にしてください${gotOf(t)}。`
        : `${t.label}は -90 度より大きく 90 度未満にしてください${gotOf(t)}。`,
  'not-a-pattern': (t) => `${t.label}は片方向（one-way）か往復（zigzag）にしてください（入力：「${t.got}」）。`,
  'not-an-axis': (t) => `${t.label}は送り方向（feed）か直交（cross）にしてください（入力：「${t.got}」）。`,
  gouging: (t) =>
    t.e.limit === undefined || !Number.isFinite(t.e.limit)
      ? `この工具はこの軸と姿勢では、どの半径の凹円筒にも食い込みます${gotOf(t)}：前傾のない平らな底面が接触点の両側で面の下に入ります。前傾角か傾斜角を付けるか、ボールエンドミルを使ってください。`
      : `${t.label}：この工具と姿勢では、凹円筒の半径は ${t.length(Math.abs(t.e.limit))} 以上必要です${gotOf(t)}。それより小さいと工具が接触点から離れた所で面の下に入り込みます。`,
  'shank-gouging': (t) => {
    const { lean, help } = shankHelp(t);
    return t.e.limit === undefined || !Number.isFinite(t.e.limit)
      ? `この工具のシャンクは、この軸と姿勢ではどの半径の凹円筒の壁とも交わります${gotOf(t)}：円筒の軸方向から見て面の法線から ${lean} 度傾いており、45 度以上では軸の高さより下で壁に当たります。${help}`
      : `${t.label}：この工具と姿勢では、凹円筒の半径は ${t.length(Math.abs(t.e.limit))} 以上必要です${gotOf(t)}。それより小さいとシャンク（工具の円筒側面。円筒の軸方向から見て面の法線から ${lean} 度傾く）が軸の高さより下で面と交わります。${help}`;
  },
  'corner-exceeds-radius': (t) =>
    t.diameter
      ? `${t.label}は D/2 = ${t.limit} 以下にしてください${gotOf(t)}。Rcr = D/2 はボールエンドミルです。`
      : `${t.label}は工具半径 R = ${t.limit} を超えられません${gotOf(t)}。Rcr = R はボールエンドミルです。`,
  'flank-wall': (t) =>
    t.e.side === undefined
      ? `${t.label}は輪郭の全高 (R - Rcr) sin(rho) + Rcr = ${t.limit} 未満にしてください${gotOf(t)}。それ以上では工具の側面がカスプではなく壁を残します。`
      : `${t.label}は${side(t.e.side)}側の最も広い点の高さ ${t.limit} 未満にしてください${gotOf(t)}。それ以上ではその側がカスプではなく壁を残します。`,
  'shank-cuts': (t) =>
    `${t.label}は ${t.limit} 未満にしてください${gotOf(t)}。それを超えると、傾斜で${side(t.e.side)}へ傾いたシャンク（工具の円筒側面）が面を削ります。`,
  'beyond-diameter': (t) =>
    `${t.label}は工具直径 ${t.diameter ? 'D' : '2R'} = ${t.limit} 未満にしてください${gotOf(t)}。それ以上では隣り合うパスが壁を残します。`,
  'beyond-interval': (t) =>
    `${t.label}は ${t.limit} 未満にしてください${gotOf(t)}。これがこの側面で取れる最大のピックフィードで、それ以上では隣り合うパスがカスプではなく壁を残します。`,
  'beyond-max-ra': (t) =>
    t.e.limit === undefined || !(t.e.limit > 0)
      ? `${t.label}には届きません${gotOf(t)}：この姿勢の工具はカスプを残しません（平らな底面が面に接する）ので、直径までのどのピックフィードでも Ra = 0 です。`
      : `${t.label}は ${t.limit} 未満にしてください${gotOf(t)}。これがこの工具・姿勢・パスでこの面に残る最大の Ra で、パスをそれ以上離すとカスプではなく壁が残ります。`,
  'wall-only': (t) =>
    `${t.label}には答えられません${gotOf(t)}：この姿勢では、どのピックフィードでも工具が段差を削ります（傾いたフラットエンドのように側面かシャンクが接触点から垂直に立ち上がる）ので、カスプができません。コーナ半径か前傾角を付けるか、傾斜角を小さくしてください。`,
  'radius-gouging': radiusGouging,
};
