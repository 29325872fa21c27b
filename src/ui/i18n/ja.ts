/**
 * Japanese (issue 30): the shop's and the classroom's terms (工具, 送り, ピックフィード, カスプ高さ,
 * 前傾角; roughness names as JIS B 0601 gives them); the paper's symbols kept. The README's glossary
 * names each term's source. Loaded only when chosen.
 */
import type { Catalogue } from './catalogue';
import { curvedMessageIn, radiusFieldIn } from './curvedText';
import { JA_CHART } from './jaChart';
import { JA_CURVED } from './jaCurved';
import { JA_ERRORS } from './jaErrors';
import { JA_FINISH } from './jaFinish';
import { JA_FORMULAS } from './jaFormulas';
import { JA_LINK_NOTICES } from './jaLinkNotices';
import { JA_PROCEDURES } from './jaProcedures';
import { JA_PROFILE } from './jaProfile';
import { JA_RADIUS } from './jaRadius';
import { JA_SHEET } from './jaSheet';
import { JA_SLOPE } from './jaSlope';
import { JA_STEPPER } from './jaStepper';
import { JA_SURFACE } from './jaSurface';
import { JA_TABLES } from './jaTables';
import { JA_THREE_AXIS } from './jaThreeAxis';
import { sceneWordsIn } from './sceneText';

export const catalogue: Catalogue = {
  lang: 'ja',
  page: {
    title: 'ラジアスエンドミルのピックフィード（任意の工具姿勢）',
    stepOverMeaning:
      'ピックフィード L は、隣り合う工具接触点（CC）経路の間隔です（CAM システムのピックフィードと同じ意味）。',
    centreOffset: '工具中心点 O でプログラムする場合は、各 CC 経路を送りと直角方向に次だけずらします：',
    fullStop: '。',
    lede: '指定したカスプ高さに対する厳密なピックフィードを、任意の前傾角・傾斜角、片方向・往復のパスについて求め、Sekine・Redonnet・Bedi の近似（Sekine & Kameya 2022）、接触点の曲率円、コーナ球と比較します。',
    language: '言語',
    machine: '機械',
    machine5: '5軸',
    machine3: '3軸',
    unit: '単位',
    inch: 'インチ',
    sizeAs: '工具寸法の指定',
    sizeD: '直径 D',
    sizeR: '半径 R',
    preset: '工具プリセット',
    shelf: 'マイ工具：保存した工具と Fusion 360 ライブラリ',
    passes: 'パスの方式',
    raster: '走査線',
    waterline: '等高線',
    solveFor: '求める量',
    forward: 'ピックフィード',
    inverse: 'カスプ高さ',
    given: '与える量',
    givenH: 'カスプ高さ h',
    givenRa: '粗さ Ra',
    pattern: 'パス',
    oneWay: '片方向',
    zigzag: '往復',
    surface: '加工面',
    plane: '平面',
    convex: '凸の円筒',
    concave: '凹の円筒',
    curved: '複曲面上の点',
    axis: '円筒の軸',
    axisFeed: '送り方向',
    axisCross: '送りに直交',
    finish: '刃数と送り（任意）：送りマークと面の粗さ',
    downloadTable: '早見表をダウンロード（CSV）',
    shopSheet: '現場用シート',
    copyLink: 'リンクをコピー',
    copyEmbed: '埋め込みコードをコピー',
    cameraIso: '等角図',
    cameraFeed: '送り方向から',
    cameraTop: '上から',
    rightFlank: '（右側）',
    leftFlank: '（左側）',
    contactOffset: '（接触点のずれ）',
    cuspHeights: 'カスプ高さ（往復）',
    openFull: 'フル版の計算機を開く',
    embedTitle: 'ピックフィード計算機',
    teachingViews: '解説ビュー',
    alongSurface: '面に沿った L',
    cuspNormal: 'カスプ高さ h（法線方向）',
    equivalentLead: '等価前傾角 ρ',
    equivalentTilt: '等価傾斜角 β',
    lookupNote:
      'この工具とパスの厳密なピックフィード L と L/2 を、カスプ高さ × 前傾角 × 傾斜角（3軸では × 勾配、CAM で指定する Lxy または dz）ごとに、画面の単位（各列とファイル名に明記）で、コマンドラインの一括処理と同じ形式にまとめます。',
    sheetNote:
      '印刷用の 1 ページ：この工具・姿勢・加工面のピックフィードをカスプ高さ × 前傾角（3軸では × 勾配）の表にし、CSV も付けます。',
    staleBadge: '最後の有効な状態を表示中',
    typingBadge: '入力中：手を止めるか Enter を押すと 3D 表示が更新されます',
    camera: 'カメラ',
    legendTool: '工具と隣り合うパス（往復では鏡映）',
    legendPath: '接触点（CC）の経路、間隔 L',
    legendContact: 'CC（P_base）：このパスの接触点',
    legendDimension: 'このパスの CC 経路から測った L と L/2',
    legendOffset: 'y0：工具中心 O から見た接触点のずれ',
    legendCentre: 'O：工具中心点',
    legendAxis: '工具軸（面上の足から）',
    legendDesign: '設計平面',
    legendHplane: 'h 擬似平面',
    legendPhp: 'P_hp：カスプ高さにある工具上の点',
    legendSection: '各 P_hp を通る断面円',
    legendLoop: 'トーラス／h 擬似平面',
    legendRidge: '送り方向に続くカスプ（スカラップの稜線）',
    legendDesignCurved: '円筒または複曲面（接平面からの高さで帯状に着色：青は下がり、橙は上がる）',
    legendHsurface: 'h 擬似曲面（面を h だけオフセットした面）',
    legendCusp: 'その上のカスプ',
    legendAxes: '接触点の X（送り）、Y、Z（3軸では機械上の姿勢で工具軸が垂直、Lxy または dz は CAM で指定する値）',
    legendTrace: '段階表示：試した断面、候補 P_hp[i]、求めた点',
    legendExaggeration: 'スカラップが低くて見えないときは面の近くで高さを N 倍に拡大（表示にバッジ、数値は不変）',
    givenSa: '目標 Sa（面、刃を考慮）',
    surfacePreset: '面のプリセット',
    present: '発表モード',
    leavePresent: '発表モードを終了（Esc）',
    presentInputs: '入力',
    hideInputs: '入力を隠す',
  },
  labels: {
    fullCalculator: 'すべての機能を備えた計算機',
    notices: 'お知らせ',
    teaching: '解説ビュー',
    inputs: '入力',
    results: '結果',
    finish: '仕上げ面',
    targetSa: '目標 Sa',
    view3d: '3D 表示',
    currentAnswer: '現在の答え',
  },
  fields: {
    R: { label: '工具半径 R', hint: '工具直径の半分' },
    Rcr: { label: 'コーナ半径 Rcr', hint: '0 でスクエア、R でボールエンドミル' },
    rho: { label: '前傾角 rho', hint: '送り方向への工具の傾き' },
    tilt: { label: '傾斜角 beta', hint: '送りに直交する方向への工具の傾き。+ でシャンクが +Y 側へ倒れる' },
    Rs: { label: '面の半径 Rs', hint: '円筒の半径（正の数。凸・凹は上で選ぶ）' },
    h: { label: 'カスプ高さ h', hint: 'パスの間に残る最も高いカスプの高さ' },
    ra: { label: '算術平均粗さ Ra', hint: '送りに直交する方向の目標粗さ。カスプ高さはここから決まる' },
    L: { label: 'ピックフィード L', hint: '隣り合う工具接触点の経路の間隔' },
    slope: { label: '面の勾配 alpha', hint: '接触点での面の水平からの傾き（0 で平らな底面）' },
    psi: { label: '走査角 psi', hint: '平面視で最大傾斜線から測ったパスの向き：0 で上り下り、90 で等高線沿い' },
    Rf: { label: '送り方向の半径 Rf', hint: '送り方向の主曲率半径（正の数。凸・凹は横で選ぶ）' },
    Rc: { label: '直交方向の半径 Rc', hint: '送りに直交する方向の主曲率半径（正の数。凸・凹は横で選ぶ）' },
    Lxy: { label: '水平ピック Lxy', hint: '隣り合う走査線パスの水平距離（CAM で指定する値）' },
    dz: { label: 'Z ピッチ dz', hint: '隣り合う段（工具先端）の高さの差（CAM で指定する値）' },
    z: { label: '刃数 z', hint: '刃の数。fz と合わせて送りマークを求める' },
    fz: { label: '一刃当たりの送り fz', hint: '一刃当たりの送り。空欄なら送りマークなし' },
    runout: { label: '振れ e', hint: '半径方向の振れ（既定 0）' },
    runoutPhase: { label: '振れの位相', hint: '刃 0 から測った振れの向き' },
    passPhase: { label: 'パスの位相 q', hint: 'パスのずれ（送り周期に対する割合）' },
    F: { label: '送り速度 F', hint: 'テーブル送り。n と合わせて fz = F / (n z)。fz を入力中は使わない' },
    n: { label: '主軸回転数 n', hint: '毎分回転数。F と合わせて fz を与える' },
    sa: {
      label: '目標 Sa',
      hint: '刃が残す面の目標粗さ（平面、振れなし）。刃数 z と合わせて最適なピックフィードと fz を求める',
    },
  },
  diameter: {
    label: '工具直径 D',
    hint: 'カタログの表記どおり。D = 2R',
    cornerHint: 'Rcr = 0 でスクエア、Rcr = D/2 でボールエンドミル',
  },
  degrees: '度',
  slider: 'のスライダー',
  headline: {
    stepOver: 'ピックフィード L',
    scallopHeight: 'カスプ高さ h',
    zeroFeed: 'ピックフィード L0（fz → 0 の端：Ra = Sa）',
  },
  phrases: {
    'Typing: the results follow when you pause or press Enter.':
      '入力中：手を止めるか Enter を押すと結果が更新されます。',
    'Updating: these numbers are for the previous inputs.': '更新中：表示中の数値は前の入力に対するものです。',
    'Out of date: the solver gave up; these numbers are for earlier inputs.':
      '古い結果：計算が打ち切られました。表示中の数値は以前の入力に対するものです。',
    'No answer: the solver gave up.': '答えなし：計算が打ち切られました。',
    'No scallop: a flat end on a flat floor lies flat, so L = 2R for any h.':
      'カスプなし：平らな底面にフラットエンドが密着するため、どの h でも L = 2R です。',
    Copy: 'コピー',
    Copied: 'コピーしました',
    'Copy failed': 'コピーできません',
    'Link copied: it opens this calculator with these inputs.': 'リンクをコピーしました：この入力で計算機を開きます。',
    'Copying was refused by the browser: the link is selected below, copy it by hand.':
      'ブラウザがコピーを拒否しました：下のリンクが選択されています。手動でコピーしてください。',
    'Embed code copied: an iframe and the <path-interval-calculator> element.':
      '埋め込みコードをコピーしました：iframe と <path-interval-calculator> 要素です。',
    'Copying was refused by the browser: the embed code is selected below, copy it with Ctrl+C.':
      'ブラウザがコピーを拒否しました：下の埋め込みコードが選択されています。Ctrl+C でコピーしてください。',
    'Copy the headline value': '見出しの値をコピー',
    'Copy L/2': 'L/2 をコピー',
    'Copy the programmed step': 'プログラム上のピッチをコピー',
    'Copy L along the surface': '面に沿った L をコピー',
    'Copy the centre offset': '工具中心のずれをコピー',
    'Copy the current answer': '現在の答えをコピー',
    'Horizontal step Lxy (as programmed)': '水平ピック Lxy（CAM で指定する値）',
    'Step-down dz (as programmed)': 'Z ピッチ dz（CAM で指定する値）',
  },
  finish: {
    'Finish: the feed marks the teeth leave': '仕上げ面：刃が残す送りマーク',
    'Scallop h (across the feed)': 'カスプ高さ h（送りに直交）',
    'Feed marks hf (along the CC path)': '送りマーク hf（接触点の経路に沿って）',
    'Ra (across the feed)': 'Ra（送りに直交）',
    'Sa (areal)': 'Sa（面）',
    'Feed period': '送りの周期',
    'Balanced feed fz* (hf = h)': '釣り合う送り fz*（hf = h）',
    'use the balanced feed': '釣り合う送りを使う',
    'Download x3p': 'x3p をダウンロード',
    'none: hf stays below h at every fz up to R': 'なし：R までのどの fz でも hf は h より低い',
    'Computing the feed marks and the areal parameters...': '送りマークと面の粗さパラメータを計算中…',
    'Computing the areal parameters...': '面の粗さパラメータを計算中…',
    'Areal parameters over one period cell (ISO 25178-2, no filter, the design plane as reference); straight teeth, M3. The x3p file holds that cell, 256 x 256 heights (ISO 25178-72).':
      '面の粗さパラメータは 1 周期のセルについて求めます（ISO 25178-2、フィルタなし、設計平面を基準）。直刃、M3。x3p ファイルはそのセルの 256 × 256 点の高さです（ISO 25178-72）。',
    'Along the CC path (y = 0), two feed periods': '切削点の経路に沿って（y = 0）、送り 2 周期',
    'Across the feed, one period of the passes, where the feed marks stand highest:':
      '送りと直角に、パス 1 周期、送りマークが最も高い位置で：',
    'not used with a target Sa: fz is its answer': '使わない：目標 Sa では fz が答え',
    'Target Sa: the best step-over and feed per tooth': '目標 Sa：最適なピックフィードと一刃送り',
    'Step-over L': 'ピックフィード L',
    'Feed per tooth fz': '一刃送り fz',
    'use this pair': 'この組を使う',
    'L * fz (area per tooth)': 'L × fz（一刃あたりの加工面積）',
    'Sa it leaves': '残る Sa',
    'h for this Ra': 'この Ra でのカスプ高さ h',
    'Scallop h at this L': 'この L でのカスプ高さ h',
    'L0 (fz -> 0: Ra = Sa)': 'L0（fz → 0 の端：Ra = Sa）',
    'Computing the pairs of step-over and feed per tooth that leave this Sa (a few seconds)...':
      'この Sa を残すピックフィードと一刃送りの組を計算中（数秒）…',
    'The pair with the largest L * fz (the area machined per tooth: the fastest finish at a given spindle speed) among those whose areal Sa is the target (plane, straight teeth, no runout). "use this pair" solves for the scallop height at that L with that fz, both rounded down.':
      '面の Sa が目標と等しくなる組のうち L × fz（一刃あたりの加工面積：同じ主軸回転数で最も速い仕上げ）が最大の組です（平面、直刃、振れなし）。「この組を使う」はその L と fz（どちらも切り捨て）でカスプ高さを求めます。',
    'Every pair that leaves this Sa: the dot is the best, the curve ends at L0 where fz -> 0':
      'この Sa を残すすべての組：点が最適、曲線は fz → 0 となる L0 で終わる',
    "The teeth's surface (z teeth, fz per tooth, passes L apart; feed periods x pass periods shown):":
      '刃が残す面（刃数 z、1 刃送り fz、パス間隔 L。表示は送り周期 × パス周期）：',
    'Continuous passes: the tool sweeps without teeth.': '連続したパス：刃を考えず、工具の回転体が連続して掃引した面。',
    'Along the feed, lengths drawn longer by': '送り方向の長さの拡大倍率',
  },
  tabs: {
    'Cross-feed profile': '送り直交断面',
    'L against lead and tilt': '前傾角・傾斜角と L',
    'Step against slope': '勾配とピッチ',
    'L against each radius': '各半径と L',
    "The paper's tables": '論文の表',
    '3D procedure, step by step': '3D の手順（段階表示）',
    Formulas: '数式',
    'Machined surface': '加工面',
  },
  question: {
    ', ': '、',
    '5-axis': '5軸',
    '3-axis': '3軸',
    lead: '前傾',
    tilt: '傾斜',
    'one-way': '片方向',
    zigzag: '往復',
    plane: '平面',
    'convex cylinder': '凸の円筒',
    'concave cylinder': '凹の円筒',
    'along the feed': '送り方向',
    'across the feed': '送りに直交',
    'curved point': '複曲面上の点',
    across: '直交方向',
    straight: '直線',
    convex: '凸',
    concave: '凹',
    waterline: '等高線',
    slope: '勾配',
    raster: '走査角',
    'flat floor': '平らな底面',
  },
  errors: JA_ERRORS,
  sheet: JA_SHEET,
  said: {
    noScallopPlane: (d) =>
      `カスプなし：前傾も傾斜もないフラットエンドは平面に密着し、直径までのどのピックフィードでもカスプを残さないため、どの h でも L = 2R = ${d} です。`,
    copied: (v, u, q) => `${v}（${u}）をコピーしました${q === null ? '' : `：${q}`}。`,
    copyFailed: (v, u) => `コピーできませんでした。値を選択して手でコピーしてください（${v} ${u}）。`,
    empty: '空欄',
    restarted: (who, restarts) => {
      const subject = who === 'results' ? '計算' : '解説ビューの計算';
      return restarts === null
        ? [`${subject}を再起動しました（`, '）。最後の要求をもう一度送りました。']
        : [
            `${subject}は ${restarts} 回続けて再起動したあと停止しました（`,
            `）。${who === 'results' ? '表示中の数値' : 'ビュー'}は古く、そのように表示しています。入力をどれか変えるともう一度試します。`,
          ];
    },
    linkReplaced: 'リンクの値の一部を置き換えました：',
    ruleOfThumb: (ra, pct) => `経験則 Ra ~ h/4 = ${ra}：厳密な Ra に対して ${pct} %。`,
    diameterShare: (pct) => `L = 工具直径の ${pct} %`,
    revolution:
      'ここでは Rz、Ra、Rq を示しません。回転面上の等高線パスは段ごとに間隔が変わり、断面形状に測るための周期がないためです。答えはカスプ高さ h です。',
    preset: (d, r, tool) =>
      `D${d}、${r === null ? 'ボールエンドミル' : `コーナ R${r}`}${tool === null ? '' : `（論文の工具 ${tool}）`}`,
    custom: 'カスタム',
    metric: 'メートル系（mm）',
    catalogueTools: (units) => `カタログの工具（${units}）`,
    reason: (kind) =>
      kind === 'failed'
        ? 'ソルバーの計算が失敗しました'
        : kind === 'threw'
          ? 'ソルバーで予期しないエラーが発生しました'
          : kind === 'load'
            ? 'ソルバーを読み込めませんでした'
            : 'ソルバーが応答しなくなりました',
    notAvailable: '算出不可',
    cylinderMeaning: (side, r, axis) =>
      axis === 'feed'
        ? `この${side === 'convex' ? '凸' : '凹'}の円筒（半径 ${r}、軸は送り方向：パスは軸に沿って進む）では、L とフランク幅は CC 経路の間の面上の弧長で、高さはすべて円筒から半径方向に測ります。`
        : `この${side === 'convex' ? '凸' : '凹'}の円筒（半径 ${r}、軸は送りと直交：パスは円筒を周回し、軸方向に送られる）では、L とフランク幅は軸方向に測り、高さはすべて円筒から半径方向に測ります。`,
    curvedMeaning: ([fs, fr], [cs, cr]) =>
      `この複曲面上の点（送り方向 Rf ${fs === 'convex' ? '凸' : '凹'} ${fr}、直交方向 Rc ${cs === 'convex' ? '凸' : '凹'} ${cr}）では、L とフランクの到達幅は送りと直交する方向に面に沿って測った CC 経路の間の弧長で、高さはすべて接触点を通る送り直交面内で半径方向に測ります。`,
    sideBox: (label) => `${label}：凸・凹・直線`,
    linkText: 'この状態へのリンク',
    targetNotOffered: (symbol) => `3軸加工では目標 ${symbol} は使えません。カスプ高さ h を入力してください。`,
    surfacePresets: {
      custom: '半径を指定',
      dome: 'ドーム（両方向とも凸）',
      bowl: 'ボウル（両方向とも凹）',
      saddle: '鞍形（送り方向に凸、直交方向に凹）',
      sphere: '球（Rc = Rf、凸）',
      'cylinder-along': '円筒、軸が送り方向（Rf は直線）',
      'cylinder-across': '円筒、軸が送りに直交（Rc は直線）',
      plane: '平面（両方向とも直線）',
      boss: 'ボス（周方向に凸、母線は直線）',
      fillet: 'ポケットのすみ R（凹、Rc が小さい方）',
    },
    rasterNote: '傾斜した平面上の走査線パス：面の勾配と走査方向の角度が、接触点での工具の前傾角と傾斜角を決めます。',
    tableWorker: (gaveUp, reason) =>
      gaveUp
        ? `表なし：表の計算用ワーカーが停止しました（${reason}）。クリックするともう一度試します。`
        : `表の計算用ワーカーを再起動しました（${reason}）。再計算中…`,
    tableComputing: '計算用ワーカーで表を計算しています…',
    tableSaved: (file, rows, h, unit, axes, empty) =>
      `${file} を保存しました：${rows} 行、h ${h[0]}～${h[1]} ${unit} × ${
        axes.kind === 'five-axis'
          ? `前傾角 ${axes.lead[0]}～${axes.lead[1]}° × 傾斜角 ${axes.tilt[0]}～${axes.tilt[1]}°`
          : `面の勾配 ${axes.slope[0]}～${axes.slope[1]}°、各行にプログラム上のピッチ（${axes.step}）`
      }。有効範囲外の ${empty} 個のセルは空欄で、理由は error 列にあります。`,
  },
  threeAxis: JA_THREE_AXIS,
  chart: JA_CHART,
  slope: JA_SLOPE,
  radius: JA_RADIUS,
  finishText: JA_FINISH,
  surface: JA_SURFACE,
  profile: JA_PROFILE,
  procedures: JA_PROCEDURES,
  linkNotices: JA_LINK_NOTICES,
  stepper: JA_STEPPER,
  formulas: JA_FORMULAS,
  tables: JA_TABLES,
  curved: (e, state) => curvedMessageIn(catalogue, JA_CURVED, e, state),
  radiusField: (key, text, value) => radiusFieldIn(catalogue, JA_CURVED, key, text, value),
  scene: sceneWordsIn('ja', '（円弧）', '工具の姿勢、隣り合うパスとカスプの断面の 3D 表示', {
    designPlane: '設計平面',
    designSurface: '設計曲面',
    hPlane: 'h 擬似平面',
    hSurface: 'h 擬似曲面',
    cusp: 'カスプ',
    converged: 'P_hp（収束）',
    best: '最良の P_hp[i]',
    single: '単一接触',
    xAxis: 'X（送り）',
    scale: (k) => (k === null ? '高さは実寸' : `高さを ${k} 倍で表示（平面から 2h まで）`),
    scaleTitle: (k) =>
      k === null
        ? 'すべての長さと高さを実寸で描いています。'
        : `カスプが見えるように、平面からカスプ高さの 2 倍までの高さを ${k} 倍に拡大して描き、その上の工具は実寸で描いています。拡大は描画だけで、数値はすべてソルバーの値です。`,
  }),
  viewNotes: {
    curved: {
      tables: '論文の表は論文自身の条件（平面）のものです',
      stepper: '論文の手順の段階表示は平面か円筒を解きます',
      formulas: '論文の数式は平面か円筒を扱います',
      surface: '加工面のシミュレーションは平面か円筒で行います',
    },
    curvedAnswered:
      'この複曲面上の点の答えは、上の結果、送り直交断面（送りに直交する断面）と「各半径と L」のグラフにあります。',
    question: (slope, psi) => `勾配 ${slope}°、${psi === null ? '等高線' : `走査角 ${psi}°`}`,
    tables: '論文の表：論文自身の 5 軸の条件（平面上の前傾）で、参考として示します。画面の 3 軸の問いではありません。',
    revolution: (q) =>
      `回転面上の等高線パス（${q}）は段ごとに間隔が変わるので、合同なパスを描くこのビューには描くものがありません。「勾配とピッチ」のグラフと 3D 表示が示します。`,
    equivalent: (q, lead, tilt, surface) =>
      `${q}で垂直に立つ工具は、平面上で前傾角 ${lead}°、傾斜角 ${tilt}°、片方向の工具と同じです。${surface ? 'そのパスを平面自身の座標でシミュレーションします。' : '平面自身の座標で描きます（長さは平面に沿って、h は法線方向）。'}`,
  },
};
