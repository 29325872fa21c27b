/**
 * The three-axis errors in Japanese (issue 30): one sentence per error code of the three-axis
 * validation and solvers (core/threeAxis), naming the constraint and its limit in the user's unit,
 * as the English ones do. Part of ja.ts.
 */
import type { Catalogue, ThreeAxisText } from './catalogue';

const gotOf = (t: ThreeAxisText) => `（入力：${t.got}）`;

function outOfRange(t: ThreeAxisText): string {
  switch (t.e.field) {
    case 'R':
      return `${t.label}は ${t.toolRange[0]} から ${t.toolRange[1]} までにしてください${gotOf(t)}。`;
    case 'Rcr':
      return `${t.label}は 0 から工具半径 R${t.limit === '' ? '' : `（${t.limit}）`}までにしてください${gotOf(t)}。Rcr = R はボールエンドミルです。`;
    case 'slope':
      return `${t.label}は ${t.waterline ? '0° より大きく 90° 以下' : '0° から 90° まで'}にしてください${gotOf(t)}。`;
    case 'rasterAngle':
      return `${t.label}は最大傾斜線から 0° から 90° までにしてください${gotOf(t)}。`;
    case 'feedRadius':
    case 'crossRadius':
      return `${t.label}は ${t.radiusRange[0]} から ${t.radiusRange[1]} までの半径（凹は負）にするか、直線なら空欄にしてください${gotOf(t)}。`;
    case 'stepDown':
      if (!t.waterline) return `${t.label}は等高線パスのピッチです。走査線パスには水平ピック Lxy を指定してください。`;
      return `${t.label}は ${t.minLength} 以上にしてください${gotOf(t)}。`;
    default:
      return t.isLength
        ? `${t.label}は ${t.minLength} 以上にしてください${gotOf(t)}。`
        : `${t.label}は範囲外です${gotOf(t)}。`;
  }
}

export const JA_THREE_AXIS: Catalogue['threeAxis'] = {
  'out-of-range': outOfRange,
  'too-small': (t) => `${t.label}は ${t.limit} 以上にしてください${gotOf(t)}。`,
  'vertical-wall': (t) =>
    `${t.label} 90° は垂直な壁です。垂直な工具の側面が平らに削るので、どのピッチでもカスプはできず、求めるピッチがありません。`,
  'needs-slope': (t) =>
    `等高線パスでは${t.label}を 0° より大きくしてください。平らな底面ではどの段も同じ高さになり、Z ピッチがありません。`,
  'shank-cuts': (t) =>
    t.noLimit
      ? `この勾配では${t.label}を求められません${gotOf(t)}。どのピッチでもコーナではなくシャンク（工具の円筒側面）がカスプを作り、カスプではなく段差が残ります。`
      : `${t.label}はこの勾配で ${t.limit} 未満にしてください${gotOf(t)}。それを超えるとコーナではなくシャンク（工具の円筒側面）がカスプを作ります。`,
  'flank-wall': (t) =>
    t.noLimit
      ? `どの勾配でも${t.label}を求められません${gotOf(t)}。フランクまたはシャンクが壁を残し、カスプになりません。`
      : `${t.label}はこの勾配で ${t.limit} 未満にしてください${gotOf(t)}。それ以上ではプロファイルのフランクが壁を残し、カスプになりません。`,
  'wall-only': (t) =>
    `フラットエンド（Rcr = 0）ではこの条件の${t.label}を求められません。工具の側面が接触点から垂直に立ち上がるので、どの間隔でもカスプではなく段差を削ります。コーナ半径を付けてください。`,
  'beyond-step': (t) =>
    `${t.label}は ${t.limit} 未満にしてください${gotOf(t)}。この勾配でカスプを残す最大のピッチで、それを超えると隣り合うパスの間に壁（平らな底面では削り残しの稜線）が残ります。`,
  'past-surface': (t) =>
    t.e.limit === null
      ? `${t.label}はここでは大きすぎます${gotOf(t)}。上のパスが回転軸の向こうに出ます。`
      : t.noLimit
        ? `ここでは${t.label}を求められません${gotOf(t)}。次のパスが面の使える部分の外（張り出し、底、回転軸の向こう）に出ます。`
        : `${t.label}はここでは ${t.limit} 未満にしてください${gotOf(t)}。それ以上では次のパスが面の使える部分の外（張り出し、底、回転軸の向こう）に出ます。`,
  gouging: (t) =>
    // The core's one gouging error with no radius to name: both radii together (waterlineErrors.ts).
    /together/.test(t.e.message)
      ? `${t.label}と送り方向の半径 Rf を合わせると、この工具には急すぎます。どちらか一方をどれだけ大きくしても、工具が接触点から離れた所で面に食い込みます。`
      : t.limit === ''
        ? `${t.label}はこの工具には急すぎます${gotOf(t)}。直線（半径なし）にしないと工具が面に食い込みます。`
        : `${t.label}はこの工具には急すぎます${gotOf(t)}。半径の大きさは ${t.limit.replace(/^-/, '')} 以上必要で、それより小さいと工具が接触点から離れた所で面に食い込みます。`,
  missing: (t) => `${t.label}を入力してください。`,
  'not-a-number': (t) => `${t.label}は有限の数にしてください${gotOf(t)}。`,
  'not-a-strategy': (t) => `${t.label}は走査線か等高線にしてください${gotOf(t)}。`,
  'not-with': (t) =>
    t.e.field === 'horizontalStep'
      ? `${t.label}は走査線パスのピッチです。等高線パスは Z ピッチ dz で指定します。`
      : t.e.field === 'stepDown'
        ? `${t.label}は等高線パスのピッチです。走査線パスは水平ピック Lxy で指定します。`
        : `${t.label}はこのパスの方式には指定できません${gotOf(t)}。`,
};
