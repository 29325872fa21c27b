/**
 * The large arrays of a reply, marked for transfer instead of copy (rpc.ts `transfer`). Apart from
 * the jobs, so that the worker's entry holds no job it loads only when asked (workerApi.ts).
 */
import type { SceneGeometry, SolveReply, TeachReply } from './protocol';

/** Buffers of a scene's geometry that can be transferred instead of copied (added to `out`). */
export function sceneTransferables(g: SceneGeometry | null, out: Set<ArrayBuffer> = new Set()): Set<ArrayBuffer> {
  if (g === null) return out;
  out.add(g.toolPositions.buffer as ArrayBuffer);
  for (const cusp of [g.right, g.left]) for (const l of cusp?.loops ?? []) out.add(l.buffer as ArrayBuffer);
  if (g.machine !== null) out.add(g.machine.step.points.buffer as ArrayBuffer);
  return out;
}

/** Buffers of a reply that can be transferred instead of copied (each listed once). */
export function transferables(reply: SolveReply | TeachReply): ArrayBuffer[] {
  if (!reply.ok) return [];
  const out = new Set<ArrayBuffer>();
  if ('scene' in reply) sceneTransferables(reply.scene, out);
  else {
    const c = reply.curves;
    for (const curve of [c.profile, c.ringEllipse, ...Object.values(c.approximations)])
      if (curve) out.add(curve.buffer as ArrayBuffer);
    if (reply.cylinder !== null) {
      out.add(reply.cylinder.passProfile.buffer as ArrayBuffer);
      out.add(reply.cylinder.ringEllipse.buffer as ArrayBuffer);
    }
  }
  return [...out];
}
