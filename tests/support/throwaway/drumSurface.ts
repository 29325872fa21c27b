/**
 * A throwaway surface model (one module), to show that the registry's promise holds: a drum, the
 * cylinder of radius 100 mm whose axis runs along the feed, answered by the cylinders' model. Not a
 * product surface: registered only by the test that uses it.
 */
import type { CylinderSurface } from '../../../src/core/domain/surface';
import { cylinderModel } from '../../../src/core/surfaces/models/cylinder';
import type { SurfaceModel } from '../../../src/core/surfaces/surface';

export interface DrumSurface {
  readonly kind: 'throwawayDrum';
}

export const DRUM_AS_CYLINDER: CylinderSurface = { kind: 'cylinder', radiusMm: 100, axis: 'feed' };
const C = DRUM_AS_CYLINDER;

export const drumModel: SurfaceModel<DrumSurface> = {
  kind: 'throwawayDrum',
  intervalMm: (input) => cylinderModel.intervalMm({ ...input, surface: C }),
  forward: (input) => cylinderModel.forward({ ...input, surface: C }),
  inverse: (input) => cylinderModel.inverse({ ...input, surface: C }),
  limits: (tool) => cylinderModel.limits(tool, C),
  maxIntervalMm: (tool, pattern) => cylinderModel.maxIntervalMm(tool, pattern, C),
  flankWidths: (tool) => cylinderModel.flankWidths(tool, C),
  fit: (tool) => cylinderModel.fit(tool, C),
  leavesNoScallop: (tool) => cylinderModel.leavesNoScallop(tool, C),
};
