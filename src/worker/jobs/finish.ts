/**
 * The `finish` job (issue 29): the feed marks (hf, its period, the balanced feed fz*) and the areal
 * parameters (Sa ... Sku) with the cell's map and the profiles along and across the feed, of the plane the page answered, from the finish fields validated here by
 * the core (finishInput.ts: whole teeth, fz up to R, runout up to R/10), each refusal one line in
 * the user's unit on its field; on request the x3p file of one period cell (core arealMap and
 * output/x3p.ts, the notes' grid). Loaded by the worker on the first finish question, so neither
 * the page's nor the worker's first script grows.
 */
import { finishFailureKind, finishFailureWords } from '../../core/finish/envelope';
import { describeFinishError } from '../../core/finish/finishInput';
import {
  arealMap,
  arealParameters,
  balancedFeed,
  feedMarks,
  toothModel,
  validateFinish,
} from '../../core/finish/index';
import { finishProfiles } from '../../core/finish/profiles';
import { x3pBytes } from '../../core/output/x3p';
import { type FinishReply, type FinishRequest, MAP_SIZE, PROFILE_POINTS } from '../finishProtocol';
import { teethSurface } from '../teethSurface';

/**
 * Answers a finish question, the part asked (the feed marks as core finishReport gives them, or
 * the areal parameters), or its x3p; never throws for a bad value: each is a message on its field.
 */
export function finish(request: FinishRequest): FinishReply {
  try {
    return answer(request);
  } catch (e) {
    // A search that did not converge (or a surface left undefined): one line on the feed, not a crash.
    const part = request.x3p === undefined && request.part !== 'areal' ? 'marks' : 'areal';
    const message = finishFailureWords(e, part);
    const kind = finishFailureKind(e);
    if (message === null || kind === null) throw e;
    return { ok: false, request, errors: [{ field: 'fz', message, failure: { kind, part } }] };
  }
}

function answer(request: FinishRequest): FinishReply {
  const v = request.values;
  const checked = validateFinish(
    {
      flutes: v.flutes,
      fz: v.fz,
      feedRate: v.feedRate,
      spindleSpeed: v.spindleSpeed,
      runout: v.runout,
      runoutPhase: v.runoutPhase,
      passPhase: v.passPhase,
    },
    request.tool.toolRadiusMm,
  );
  if (!checked.ok) {
    const errors = checked.errors.map((e) => {
      const typed = request.typed[e.field].trim();
      const { message: _english, ...data } = typed === '' ? e : { ...e, got: typed };
      return { field: e.field, message: describeFinishError(data, request.unit), error: data };
    });
    return { ok: false, request, errors };
  }
  const model = () =>
    toothModel({ tool: request.tool, pattern: request.pattern, intervalMm: request.intervalMm, finish: checked.value });
  const asked = request.x3p;
  if (asked !== undefined) {
    const map = arealMap(model(), asked.size, asked.size, 1, 1);
    const grid = { ...map, xOriginMm: map.dxMm / 2, yOriginMm: map.dyMm / 2 };
    return {
      ok: true,
      request,
      feedMarks: null,
      areal: null,
      x3p: x3pBytes(grid, { comment: asked.comment }),
      map: null,
    };
  }
  if (request.part === 'areal') {
    const m = model();
    const a = arealParameters(m);
    const areal = { Sa: a.saMm, Sq: a.sqMm, Sz: a.szMm, Sp: a.spMm, Sv: a.svMm, Ssk: a.ssk, Sku: a.sku };
    const map = Float32Array.from(arealMap(m, MAP_SIZE, MAP_SIZE, 1, 1).heightsMm);
    // The profiles: along the CC path, and across it where the feed marks stand highest.
    const profiles = finishProfiles(m, PROFILE_POINTS, feedMarks(m).crestXMm);
    // The surface over several cells, drawn in 3D by the Machined surface view.
    const surface = teethSurface(m, a);
    return { ok: true, request, feedMarks: null, areal, x3p: null, map, profiles, surface };
  }
  const marks = feedMarks(model());
  const balanced = balancedFeed(request.tool, request.pattern, request.intervalMm, checked.value);
  const feed = {
    height: marks.heightMm,
    period: marks.periodMm,
    balancedFz: balanced.ok ? balanced.feedPerToothMm : null,
  };
  return { ok: true, request, feedMarks: feed, areal: null, x3p: null, map: null };
}
