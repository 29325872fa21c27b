/** Minimal 3-vector helpers for the pure geometry (plain tuples, no classes). */

export type Vec3 = readonly [number, number, number];

export function add(p: Vec3, q: Vec3): Vec3 {
  return [p[0] + q[0], p[1] + q[1], p[2] + q[2]];
}

export function scale(p: Vec3, k: number): Vec3 {
  return [p[0] * k, p[1] * k, p[2] * k];
}

/** p + k q */
export function addScaled(p: Vec3, q: Vec3, k: number): Vec3 {
  return [p[0] + k * q[0], p[1] + k * q[1], p[2] + k * q[2]];
}

export function dot(p: Vec3, q: Vec3): number {
  return p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
}

export function cross(p: Vec3, q: Vec3): Vec3 {
  return [p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]];
}

export function norm(p: Vec3): number {
  return Math.sqrt(dot(p, p));
}
