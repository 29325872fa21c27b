/**
 * What the 3D scene is given for an answer on screen (pure: no DOM): its geometry, the labels of its
 * dimensions in the user's unit, and whether its legend is the plane's (the cusp sections and their
 * curves) or the curved surfaces' (the cusp points). A plane's or a cylinder's answer, a doubly curved
 * point's (the torus patch) and a three-axis one's (the machine frame, the programmed step); null
 * where the answer has no scene (a three-axis case without a scallop).
 */
import type { LengthUnit } from '../core/input/units';
import { isSolveReply, type PageReply } from '../worker/pageProtocol';
import type { SceneGeometry } from '../worker/protocol';
import { formatLenUnit, formatSignedLenUnit } from './format';
import { catalogue } from './i18n/words';
import type { SceneLabelTexts } from './sceneLabelTexts';

/** The scene of an answer: its geometry, labels, and whether the curved surfaces' legend applies. */
export interface SceneOfReply {
  readonly geometry: SceneGeometry;
  readonly labels: SceneLabelTexts;
  /** True where the cusps are points on the offset surface (cylinder, doubly curved, revolution). */
  readonly curvedLegend: boolean;
}

/** The scene an answer shows, or null (an error, or nothing to draw); its labels in the language in force. */
export function sceneOfReply(reply: PageReply, unit: LengthUnit): SceneOfReply | null {
  const scene = englishScene(reply, unit);
  const words = catalogue();
  return words && scene ? { ...scene, labels: words.scene.labels(scene.labels) } : scene;
}

function englishScene(reply: PageReply, unit: LengthUnit): SceneOfReply | null {
  if (!reply.ok) return null;
  const geometry = reply.scene;
  if (geometry === null) return null;
  const surface = geometry.surface;
  const L = geometry.intervalMm;
  // The step-over is an arc where it is measured around a circle across the feed.
  const arc =
    (surface.kind === 'cylinder' && surface.axis === 'feed') ||
    ((surface.kind === 'torus' || surface.kind === 'revolution') && Number.isFinite(surface.crossRadiusMm));
  const curvedLegend = surface.kind !== 'plane';
  const interval = `L = ${formatLenUnit(L, unit)}`;
  const half = isSolveReply(reply) ? reply.exact.halfIntervalMm : L / 2;
  const halfInterval = `L/2 = ${formatLenUnit(half, unit)}`;
  if (isSolveReply(reply) || !('answer' in reply)) {
    const y0 = reply.exact.contactOffsetMm;
    return {
      geometry,
      curvedLegend,
      labels: { interval, halfInterval, arc, contactOffset: y0 === 0 ? null : `y0 = ${formatSignedLenUnit(y0, unit)}` },
    };
  }
  const a = reply.answer;
  const programmedStep =
    a.passes === 'waterline' && a.stepDownMm !== null
      ? `dz = ${formatLenUnit(a.stepDownMm, unit)}`
      : `Lxy = ${formatLenUnit(a.horizontalStepMm, unit)}`;
  return { geometry, curvedLegend, labels: { interval, halfInterval, arc, contactOffset: null, programmedStep } };
}
