/**
 * The formulas view in Japanese (issue 30): what each procedure assumes, the notes around the
 * equations and the three-axis posture's box, in the terms of ja.ts and the README's glossary
 * (ピックフィード, 前傾角, 傾斜角, リング楕円, 接触円, ラジアスエンドミル); the equations are the
 * paper's symbols. Part of ja.ts.
 */
import type { FormulaWords } from './teachWords';

export const JA_FORMULAS: FormulaWords = {
  assumes: {
    exact:
      '真の 3 次元形状：工具は X 方向に動くので、残る面は工具の X 方向への投影、すなわち Rcr だけオフセットしたリング楕円（傾斜角で回転）です。ボールエンドミルやフラットエンドミルを含め、どの姿勢でも成り立ちます。',
    sekine:
      '真円近似：工具中心の高さから求めた楕円を、半径 Reff の 1 つの円で置き換えます。実際の断面形状の曲率が変わるところを無視するため、前傾角が小さいと大きくずれます。',
    redonnet:
      '傾斜なしの最下点での接触円：h が 0 に近づく極限では厳密ですが、実際の断面形状のほうが速く立ち上がるため、L を大きく見積もります。',
    bedi: '楕円投影：半軸 Rlong と Rlong sin(rho) の 1 つの楕円で、オフセットした楕円を代用します。傾斜がなければ近い値ですが、オフセットした楕円は楕円ではなく、rho = 0 では成り立ちません。',
    osculating:
      'Redonnet らの考えを任意の姿勢に広げたもの：接触点で厳密な断面形状に接する接触円です。h が 0 に近づく極限では厳密ですが、左右対称なので傾斜による非対称は表せません。',
    cornerBall:
      'ラジアスエンドミルを半径 Rcr のボールエンドミルとして扱います（一部のオンライン計算機と同じ）。ボールエンドミルでだけ厳密で、前傾や傾斜で工具底の平らな部分が効くと、ピックフィードが小さすぎます。',
  },
  leadOnly: '前傾のみのモデル：前傾角だけで適用し、傾斜角は無視します。',
  maths: (name) => `${name}：数式（幅の広い式は横にスクロールします）`,
  cylinder: (radius, axis) =>
    `円筒上（Rs = ${radius}、軸は${axis === 'feed' ? '送り方向' : '送りに直交'}）では、厳密なピックフィードを平面の式ではなく円筒そのもので解きます（半径方向の高さ h での各フランクの到達点を、${axis === 'feed' ? '軸まわりの角度として' : '軸まわりに回転させた工具について'}求めます）。そのため平面の式は省きます。下の近似は平面と同じです。表の補正行は 1/rho = 1/Reff + 1/Rs を L = 2 sqrt(2 rho h - h^2) に代入します。`,
  notApplicable: (names) => `${names}：ここでは適用できません（結果の表の下の注を参照）。`,
  units: (unit, small) => `長さは ${unit}（小さい値は ${small}）、角度は度。各 L/2 は現在のカスプ高さ h での値です。`,
  postureTitle: '勾配から求める工具姿勢（3 軸）',
  postureIntro:
    '傾斜した平面上で垂直に立つ工具は、平面上でこの前傾角・傾斜角をとる工具と同じです。下の式はその姿勢での平面の式です。',
  postureLine: (label, formula, value) => `${label}：${formula}、よって ${value}`,
  postureLabels: {
    'Slope and raster angle': '勾配と走査角',
    D: 'D',
    Lead: '前傾角',
    Tilt: '傾斜角',
    'Programmed step': 'プログラム上のピッチ',
  },
  anglesFormula: 'alpha, psi（等高線：psi = 90）',
};
