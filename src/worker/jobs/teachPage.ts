/**
 * The worker's `teach` job for any page question: a plane's or a cylinder's (jobs/teach.ts), a
 * doubly curved point's (the chart of L against each radius, the profile on the curved section)
 * or three-axis machining's (the chart "step against slope"). The request is validated again; a bad
 * one gets an error reply, never an exception. The reply echoes its request.
 */
import { MIN_LENGTH_MM } from '../../core/input/validate';
import { doublyCurvedHeightForRaMm } from '../../core/roughness/doublyCurved';
import { curvedInverse, curvedPointOf } from '../../core/surfaces/doublyCurvedPoint';
import { curvedSection } from '../data/curvedSection';
import { radiusSweep } from '../data/radiusSweep';
import { slopeChart } from '../data/slopeChart';
import { equivalentPlaneRequest } from '../equivalentPlane';
import { type CurvedRequest, isSolveRequest, type PageRequest, type ThreeAxisRequest } from '../pageProtocol';
import type { CurvedTeachReply, PageTeachReply, ThreeAxisTeachReply } from '../teachProtocol';
import { revalidateCurved } from './curved';
import { teach } from './teach';
import { solveThreeAxisRequest } from './threeAxis';

const NO_SCALLOP = 'No scallop: these passes leave none, so there is nothing to chart.';

/** The chart "step against slope" for a three-axis request; on a sloped plane the plane's views at the equivalent posture. */
export function teachThreeAxis(request: ThreeAxisRequest): ThreeAxisTeachReply {
  const reply = solveThreeAxisRequest(request);
  if (!reply.ok) return { ok: false, request, reason: null };
  const slope = slopeChart(reply);
  if (slope === null) return { ok: false, request, reason: NO_SCALLOP };
  const equivalent = equivalentPlaneRequest(reply);
  const taught = equivalent === null ? null : teach(equivalent);
  return { ok: true, request, slope, plane: taught?.ok ? taught : null };
}

/** The doubly curved point's chart and profile (in inverse mode at the model's solved h, for a target Ra at its h). */
export function teachCurved(request: CurvedRequest): CurvedTeachReply {
  if (revalidateCurved(request) !== null) return { ok: false, request, reason: null };
  const i = request.input;
  const hMm =
    request.mode === 'curved-forward'
      ? request.input.scallopHeightMm
      : request.mode === 'curved-ra'
        ? doublyCurvedHeightForRaMm(curvedPointOf(i), request.input.targetRaMm)
        : curvedInverse(curvedPointOf(i), request.input.intervalMm).cuspHeightMm;
  if (!(hMm >= MIN_LENGTH_MM)) return { ok: false, request, reason: NO_SCALLOP };
  return {
    ok: true,
    request,
    feed: radiusSweep(i, i, i.pattern, hMm, 'feed'),
    cross: radiusSweep(i, i, i.pattern, hMm, 'cross'),
    section: curvedSection(i, i, i.pattern, hMm),
  };
}

/** The teaching views' data for any page request. */
export function teachPage(request: PageRequest): PageTeachReply {
  if (isSolveRequest(request)) return teach(request);
  return request.mode === 'three-axis' ? teachThreeAxis(request) : teachCurved(request);
}
