/**
 * The tool's cross-feed profile as a polyline: a function of its posture alone, read by the pass
 * geometry a viewer draws (output/geometry.ts) and by the teaching steps (procedures/teaching.ts).
 * Pure; mm.
 */
import type { PostureShape } from './postureShape';

/**
 * The tool's cross-feed profile as a flat (y, z) array from its left widest point to its right
 * one: y from the contact, z above it (mm). Sampled by the normal angle theta (denser near the
 * contact), so corners are smooth and a flat bottom (b = 0) appears as the straight segment
 * between two samples. Where the shank cuts (the side the tool leans to), its straight
 * silhouette continues the profile up to the flank's widest height.
 */
export function profilePolyline(s: PostureShape, samplesPerHalf = 96): Float64Array {
  const n = Math.max(4, Math.round(samplesPerHalf));
  const point = (theta: number): [number, number] => {
    const psi = theta + s.phi;
    const sp = Math.sin(psi);
    const cp = Math.cos(psi);
    const d = Math.hypot(s.a * sp, s.b * cp);
    // Support point of the ring ellipse for the own-frame normal angle psi.
    const ey = d > 0 ? (s.a * s.a * sp) / d : s.a * Math.sign(sp);
    const ez = d > 0 ? (-s.b * s.b * cp) / d : 0;
    // Own frame to global: (y cos phi + z sin phi, -y sin phi + z cos phi).
    const gy = ey * s.cosPhi + ez * s.sinPhi + s.rcr * Math.sin(theta);
    const gz = -ey * s.sinPhi + ez * s.cosPhi - s.rcr * Math.cos(theta);
    return [gy, gz];
  };
  const [cy, cz] = s.flatOnPlane ? [0, -s.rcr] : point(0);
  const out: number[] = [];
  const add = (y: number, z: number) => out.push(y - cy, z - cz);
  // Left flank from its widest point (theta = -pi/2) to the contact, then the right flank.
  for (let i = n; i >= 1; i--) {
    const u = i / n;
    const theta = -(Math.PI / 2) * u * u;
    if (s.sinPhi < 0 && theta < -(Math.PI / 2 + s.phi)) continue;
    const [y, z] = point(theta);
    add(y, z);
  }
  if (s.flatOnPlane) {
    add(-s.a, -s.rcr);
    add(s.a, -s.rcr);
  } else add(cy, cz);
  for (let i = 1; i <= n; i++) {
    const u = i / n;
    const theta = (Math.PI / 2) * u * u;
    if (s.sinPhi > 0 && theta > Math.PI / 2 - s.phi) continue;
    const [y, z] = point(theta);
    add(y, z);
  }
  // The shank's silhouette on the leaning side: a line along a_yz = (sin phi, cos phi).
  const top = Math.max(...out.filter((_, i) => i % 2 === 1));
  if (s.sinPhi !== 0) {
    const sign = s.sinPhi > 0 ? 1 : -1;
    const [ty, tz] = point(sign * (Math.PI / 2 - Math.abs(s.phi)));
    const rise = top + cz - tz;
    if (rise > 0) {
      const along = rise / s.cosPhi;
      const end: [number, number] = [ty + sign * Math.abs(s.sinPhi) * along, tz + s.cosPhi * along];
      if (sign > 0) {
        add(ty, tz);
        add(end[0], end[1]);
      } else {
        const head = [end[0] - cy, end[1] - cz, ty - cy, tz - cz];
        out.unshift(...head);
      }
    }
  }
  return Float64Array.from(out);
}
