/**
 * The procedures' names in Japanese (issue 30): the authors' names and the paper's equation numbers
 * kept, the words around them in the terms of the README's glossary (厳密解, 接触円; et al. as ら, as
 * Japanese papers cite). Part of ja.ts.
 */
import type { CorrectedKey } from '../../core/procedures/procedures';
import type { ProcedureName, ProcedureNames } from './catalogue';

const NAMES: ProcedureNames['names'] = {
  exact: { label: '厳密解（3次元形状）', shortLabel: '厳密解（3D）' },
  sekine: { label: 'Sekine らの式 (4)-(8)', shortLabel: 'Sekine ら' },
  redonnet: { label: 'Redonnet らの式 (9), (8)', shortLabel: 'Redonnet ら' },
  bedi: { label: 'Bedi らの式 (10)-(11)', shortLabel: 'Bedi ら' },
  osculating: { label: '接触点での接触円', shortLabel: '接触円' },
  cornerBall: { label: 'コーナ半径の球', shortLabel: 'コーナ半径の球' },
};

const corrected = (key: CorrectedKey): ProcedureName => ({
  label: `${NAMES[key].shortLabel}、曲率補正（1/rho = 1/Reff + 1/Rs）`,
  shortLabel: `${NAMES[key].shortLabel}、曲率補正`,
});

/** What a corrected row assumes (the registry's `assumes`, in the words of the glossary). */
const assumesCorrected = (key: CorrectedKey): string =>
  `${NAMES[key].shortLabel}の半径 Reff の円に、通常の 2 次の曲率補正を加えます：合成半径 1/rho = 1/Reff + 1/Rs（Rs は符号付き。軸が送りに直交するとき面は送り直交方向に直線なので rho = Reff）を L = 2 sqrt(2 rho h - h^2) に入れます。`;

export const JA_PROCEDURES: ProcedureNames = {
  names: NAMES,
  rows: {
    plane: { label: '平面の厳密解（曲率を無視）', shortLabel: '平面（曲率を無視）' },
    sekineCorrected: corrected('sekine'),
    redonnetCorrected: corrected('redonnet'),
    osculatingCorrected: corrected('osculating'),
    cornerBallCorrected: corrected('cornerBall'),
  },
  curved: {
    'Exact (this doubly curved point)': '厳密解（この複曲面上の点）',
    'Plane, exact (both curvatures ignored)': '平面の厳密解（両方の曲率を無視）',
    'Cylinder along the feed, exact (Rf ignored)': '軸が送り方向の円筒の厳密解（Rf を無視）',
    'Cylinder across the feed, exact (Rc ignored)': '軸が送りに直交する円筒の厳密解（Rc を無視）',
  },
  leadOnly: '（前傾のみ）',
  cylinderHead: '円筒上：曲率を無視、または通常の方法で補正',
  table: '手法の表（行を選ぶと、すべてのビューでその手法が強調されます）',
  region: '手法の表（列より広いときは横にスクロールします）',
  select: 'クリックすると、すべてのビューでこの手法を選択します',
  head: {
    Procedure: '手法',
    Model: 'モデル',
    Deviation: '誤差',
    'Deviation [%]': '誤差 [%]',
    'Scallop it leaves': '残るカスプ高さ',
  },
  assumes: {
    plane: '同じ h での平面の厳密解：面の曲率を無視する計算機が出す値です。',
    sekineCorrected: assumesCorrected('sekine'),
    redonnetCorrected: assumesCorrected('redonnet'),
    osculatingCorrected: assumesCorrected('osculating'),
    cornerBallCorrected: assumesCorrected('cornerBall'),
  },
  curvedTitles: {
    'The exact step-over at this point.': 'この点での厳密なピックフィード。',
    'The exact answer on a plane at the same posture.': '同じ姿勢での平面の厳密解。',
    'The exact answer on the cylinder of radius Rc with its axis along the feed.':
      '半径 Rc で軸が送り方向の円筒上の厳密解。',
    'The exact answer on the cylinder of radius Rf with its axis across the feed.':
      '半径 Rf で軸が送りに直交する円筒上の厳密解。',
    'The usual correction: the effective radius combined with the radius across the feed.':
      '通常の補正：有効半径を送り直交方向の半径と合成します。',
  },
  notes: {
    noScallop:
      'カスプなし：平面に密着したフラットエンドミルは、直径までのどのピックフィードでもカスプを残さないため、L = 2R です。',
    leadOnly: (names) => `傾斜があるとき、${names}は前傾のみのモデルです：前傾角だけで適用し、傾斜は無視します。`,
    cylinder:
      '円筒上では、上の手法は平面と同じように適用します（曲率を無視）。その下の行は、同じ入力での平面の厳密解（曲率を無視）と、有効半径をもつ各手法の通常の補正 1/rho = 1/Reff + 1/Rs で、それぞれ円筒上の厳密解と並べています。',
    crossAxis:
      '円筒の軸が送りに直交するとき、送り直交断面は直線（そこでは 1/Rs = 0）なので、補正しても rho = Reff のままで、補正した各行は上の同じ手法の行と等しくなります。',
    curved:
      '厳密解と並べた各行：平面（両方の曲率を無視）、各円筒（一方の半径を無視）、有効半径をもつ各手法の通常の補正 1/rho = 1/Reff + 1/Rc。厳密解からの誤差と、その L がこの点で実際に残すカスプ高さを示します。',
    curvedInverse: '比較の行は順問題（カスプ高さからピックフィード）についてだけ示します。',
    beyond: (name, what, value, model, limit, limitValue) =>
      `${name}：${what} = ${value} は${model === 'ellipse' ? '楕円' : model === 'combined' ? '合成した円' : '円'}の${what === 'h' ? '最も広い点より上' : '幅より広い'}です（${
        limit === 'Reff'
          ? 'Reff'
          : limit === 'height'
            ? '楕円の高さ Rlong sin(rho)'
            : limit === 'halfWidth'
              ? '楕円の半幅 Rlong'
              : 'rho'
      } = ${limitValue}）。`,
    wall: (name, interval, max, cylinder) =>
      `${name}：ピックフィード L = ${interval} は、${cylinder ? 'この円筒上で' : ''}カスプが残る最大のピックフィード（${max}）未満ではありません。これほど離れたパスはカスプではなく壁を残します。`,
    reason: (name, reason) => `${name}：${reason}。`,
    planeBeyond: '平面：ピックフィードが、平面上で工具が許す最大のピックフィード以上です。',
    notPositive: (name, reff) =>
      `${name}：有効半径${reff === null ? '' : `（${reff}）`}が凹面の半径より小さくないため、合成半径が正になりません。`,
    flankLimit: (name) => `${name}：h がその面でのフランクの限界以上です。`,
    combinedWidest: (name, radius) => `${name}：h が合成した円（${radius}）の最も広い点より上です。`,
  },
};
