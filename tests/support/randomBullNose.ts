/**
 * A random bull-nose tool for the finish's identity tests: R from 1 to 6 mm, Rcr from 0.2 R to R,
 * lead 1 to 21 degrees, tilt -10 to 10 degrees, drawn from `r` in that order (a seed keeps its cases).
 */
export function randomBullNose(r: () => number): {
  toolRadiusMm: number;
  cornerRadiusMm: number;
  leadAngleDeg: number;
  tiltAngleDeg: number;
} {
  const R = 1 + 5 * r();
  return {
    toolRadiusMm: R,
    cornerRadiusMm: R * (0.2 + 0.8 * r()),
    leadAngleDeg: 1 + 20 * r(),
    tiltAngleDeg: 20 * (r() - 0.5),
  };
}
