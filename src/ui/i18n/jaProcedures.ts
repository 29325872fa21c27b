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
};
