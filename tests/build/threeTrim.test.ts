/**
 * The three.js trim of the build (src/build/threeTrim.ts, src/build/glslDeadBlocks.ts): the shader
 * blocks it removes are those a full preprocessor would never compile, for every definition of
 * the other macros (checked against an independent full evaluator on random nested programs), and
 * a feature is removed only while the page's sources cannot reach it.
 */
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { dropDeadBlocks, knownCondition } from '../../src/build/glslDeadBlocks';
import { pageSources, trimModule, trimPlan } from '../../src/build/threeTrim';

const DEAD = new Set(['D1', 'D2']);
const LIVE = ['L1', 'L2'] as const;

/**
 * The reference: a full preprocessor pass over conditionals, given exactly which macros are
 * defined (`defined(X)` terms with `!`, `&&`, `||`, brackets): the lines a compiler would see.
 */
function preprocess(glsl: string, defined: ReadonlySet<string>): string[] {
  const truth = (expr: string): boolean => {
    const js = expr
      .replace(/defined\s*\(\s*(\w+)\s*\)/g, (_, n: string) => String(defined.has(n)))
      .replace(/defined\s+(\w+)/g, (_, n: string) => String(defined.has(n)));
    if (!/^[\s()!&|truefals]*$/.test(js)) throw new Error(`reference: cannot evaluate ${expr}`);
    return Function(`return (${js});`)() as boolean;
  };
  const out: string[] = [];
  const stack: Array<{ active: boolean; taken: boolean; outer: boolean; closed?: boolean }> = [];
  const on = () => stack.every((f) => f.active);
  for (const line of glsl.split('\n')) {
    const m = /^\s*#\s*(ifdef|ifndef|if|elif|else|endif)\b\s*(.*)$/.exec(line);
    if (m === null) {
      // Blank lines compile to nothing.
      if (on() && line.trim() !== '') out.push(line);
      continue;
    }
    const [, kind, rest] = m as unknown as [string, string, string];
    if (kind === 'ifdef' || kind === 'ifndef' || kind === 'if') {
      const outer = on();
      const v = kind === 'ifdef' ? defined.has(rest) : kind === 'ifndef' ? !defined.has(rest) : truth(rest);
      stack.push({ active: outer && v, taken: v, outer });
    } else if (kind === 'endif') {
      if (stack.pop() === undefined) throw new Error('reference: #endif without #if');
    } else {
      const f = stack.at(-1);
      // A compiler refuses a branch after #else (and an #else or #elif without #if).
      if (f === undefined || f.closed) throw new Error(`reference: #${kind} after #else or without #if`);
      f.closed = kind === 'else';
      const v = !f.taken && (kind === 'else' || truth(rest));
      f.active = f.outer && v;
      f.taken ||= v;
    }
  }
  if (stack.length > 0) throw new Error('reference: #if without #endif');
  return out;
}

/** Random nested conditional programs over dead (D1, D2) and live (L1, L2) macros. */
const term = fc
  .tuple(fc.constantFrom('D1', 'D2', 'L1', 'L2'), fc.boolean())
  .map(([n, neg]) => `${neg ? '!' : ''}defined( ${n} )`);
const condition = fc.oneof(
  fc.constantFrom('D1', 'D2', 'L1', 'L2').map((n) => `#ifdef ${n}`),
  fc.constantFrom('D1', 'D2', 'L1', 'L2').map((n) => `#ifndef ${n}`),
  fc
    .tuple(fc.array(term, { minLength: 1, maxLength: 3 }), fc.constantFrom(' || ', ' && '))
    .map(([ts, op]) => `#if ${ts.join(op)}`),
);
const elifCondition = fc
  .tuple(fc.array(term, { minLength: 1, maxLength: 2 }), fc.constantFrom(' || ', ' && '))
  .map(([ts, op]) => `#elif ${ts.join(op)}`);
let counter = 0;
const block: fc.Memo<string[]> = fc.memo((depth) =>
  fc
    .tuple(
      condition,
      fc.array(elifCondition, { maxLength: 2 }),
      fc.boolean(),
      fc.array(depth > 1 ? fc.oneof(fc.constant(null), block(depth - 1)) : fc.constant(null), { maxLength: 3 }),
    )
    .map(([open, elifs, withElse, children]) => {
      const body = () => children.flatMap((c) => (c === null ? [`line${counter++};`] : c));
      const lines = [open, ...body()];
      for (const e of elifs) lines.push(e, ...body());
      if (withElse) lines.push('#else', ...body());
      lines.push('#endif');
      return lines;
    }),
);

describe('glslDeadBlocks: the blocks only dead macros open', () => {
  it('random nested programs (fast-check seed 20261207): for each definition of the live macros, the trimmed source compiles to the same lines', () => {
    fc.assert(
      fc.property(fc.array(fc.oneof(block(3), fc.constant(['plain;'])), { maxLength: 4 }), (parts) => {
        const glsl = parts.flat().join('\n');
        const trimmed = dropDeadBlocks(glsl, DEAD);
        for (const l1 of [false, true])
          for (const l2 of [false, true]) {
            const defined = new Set(LIVE.filter((_, i) => [l1, l2][i]));
            expect(preprocess(trimmed, defined)).toEqual(preprocess(glsl, defined));
          }
      }),
      { seed: 20261207, numRuns: 400 },
    );
  });

  it('drops a dead block, keeps a dead #ifndef and #else without their directives, keeps live blocks whole', () => {
    const glsl = [
      '#ifdef D1',
      'a',
      '#else',
      'b',
      '#endif',
      '#ifndef D2',
      'c',
      '#endif',
      '#ifdef L1',
      'd',
      '#endif',
    ].join('\n');
    expect(dropDeadBlocks(glsl, DEAD)).toBe(['b', 'c', '#ifdef L1', 'd', '#endif'].join('\n'));
    expect(dropDeadBlocks('#if defined( D1 ) && defined( L1 )\nx\n#endif', DEAD)).toBe('');
    expect(dropDeadBlocks('#if defined( D1 ) || defined( L1 )\nx\n#endif', DEAD)).toBe(
      '#if defined( D1 ) || defined( L1 )\nx\n#endif',
    );
    expect(dropDeadBlocks('#ifdef D1\na\n#elif defined( L2 )\nb\n#endif', DEAD)).toBe('#if defined( L2 )\nb\n#endif');
  });

  it('leaves values and comparisons to the compiler', () => {
    expect(knownCondition('NUM_DIR_LIGHT_SHADOWS > 0', DEAD)).toBeNull();
    expect(knownCondition('defined( D1 ) || NUM_X > 0', DEAD)).toBeNull();
    expect(knownCondition('( defined( D1 ) || defined( D2 ) )', DEAD)).toBe(false);
  });
});

describe('threeTrim: what the page cannot reach', () => {
  const root = fileURLToPath(new URL('../../', import.meta.url));
  const three = `${root}node_modules/three/src/`;
  const parts = readFileSync(`${root}src/render/threeParts.ts`, 'utf8');
  const sources = pageSources(`${root}src`);

  it("keeps the shaders of the page's materials (basic, Lambert, standard, points) and drops the others'", () => {
    const plan = trimPlan(three, parts, sources);
    for (const kept of [
      'meshbasic_vert',
      'meshlambert_frag',
      'meshphysical_frag',
      'points_vert',
      'colorspace_pars_fragment',
    ])
      expect(plan.chunks.has(kept), kept).toBe(true);
    for (const dropped of [
      'meshphong_frag',
      'meshtoon_frag',
      'meshmatcap_frag',
      'depth_frag',
      'distance_frag',
      'sprite_vert',
    ])
      expect(plan.chunks.has(dropped), dropped).toBe(false);
    expect(plan.kept).toEqual([]);
  });

  it('a source that casts a shadow keeps the shadow map whole; a Phong material keeps its shaders', () => {
    const shadowed = trimPlan(three, parts, `${sources}\nmesh.castShadow = true;`);
    // The render targets' cuts need the shadow maps gone (they draw into render targets).
    expect(shadowed.kept).toEqual([
      'shadow maps',
      'render targets and cube, 3D and array textures',
      "the renderer's render-target, copy and compile API",
    ]);
    expect(shadowed.dead.has('USE_SHADOWMAP')).toBe(false);
    expect([...shadowed.standIns.keys()]).not.toContain('renderers/webgl/WebGLShadowMap.js');
    const phong = `${parts}\nexport { MeshPhongMaterial } from 'three/src/materials/MeshPhongMaterial.js';`;
    expect(trimPlan(three, phong, sources).chunks.has('meshphong_frag')).toBe(true);
    const textured = `${parts}\nexport { CanvasTexture } from 'three/src/textures/CanvasTexture.js';`;
    expect(trimPlan(three, textured, sources).dead.has('USE_MAP')).toBe(false);
  });

  it("cuts WebGLBackground's texture backgrounds and keeps its colour clear; keeps it whole when a texture can exist", () => {
    const path = 'renderers/webgl/WebGLBackground.js';
    const original = readFileSync(`${three}${path}`, 'utf8');
    const cut = trimModule(path, original, trimPlan(three, parts, sources)) as string;
    expect(original).toContain('new BoxGeometry(');
    expect(cut).not.toMatch(/new BoxGeometry\(|new PlaneGeometry\(|ShaderLib\.background/);
    expect(cut).toContain('function setClear( color, alpha )');
    expect(cut).toContain('a texture background is not in this build');
    const textured = `${parts}\nexport { CanvasTexture } from 'three/src/textures/CanvasTexture.js';`;
    expect(trimModule(path, original, trimPlan(three, textured, sources))).toBeNull();
  });
});
