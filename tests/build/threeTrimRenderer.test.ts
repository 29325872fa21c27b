/**
 * The three.js trim's cuts inside the renderer (src/build/threeFeatures.ts, threeTrim.ts): the
 * render targets and the cube, 3D and array textures, the renderer's API beyond what the page calls,
 * the output pass, uniform buffer objects, serialisation, raycasting, the other materials' uniform
 * refreshes and the dead switches' prefix lines go while the page's sources
 * and the shaders it can compile prove them unreachable, and stay whole when a source could reach
 * them. The pixels are the scene tests' (tests/e2e/scene*.test.ts); a reached stand-in throws, naming
 * itself. Also the site's public scripts, minified in the build (src/build/publicScripts.ts).
 */
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { minifySync } from 'vite';
import { describe, expect, it } from 'vitest';
import { minifyScript } from '../../src/build/publicScripts';
import { SOURCE_SEPARATOR, withoutBlocks } from '../../src/build/threeFeatures';
import {
  dropDeadDefines,
  dropMethods,
  pageSources,
  trimModule,
  trimPlan,
  unnamedMethods,
} from '../../src/build/threeTrim';

const root = fileURLToPath(new URL('../../', import.meta.url));
const three = `${root}node_modules/three/src/`;
const parts = readFileSync(`${root}src/render/threeParts.ts`, 'utf8');
const sources = pageSources(`${root}src`);
const plan = trimPlan(three, parts, sources);
const read = (path: string) => readFileSync(`${three}${path}`, 'utf8');
/** A module of three.js as the page's plan trims it. */
const cutOf = (path: string) => trimModule(path, read(path), plan) as string;

const TEXTURES = 'render targets and cube, 3D and array textures';
const RENDERER = "the renderer's render-target, copy and compile API";

describe("three.js's renderer without what the page cannot reach", () => {
  it('the page: every renderer cut made, stand-ins for the output pass and uniform buffer objects', () => {
    for (const name of [
      TEXTURES,
      'the output render pass',
      'uniform buffer objects',
      "other materials' uniform refreshes",
    ])
      expect(plan.removed, name).toContain(name);
    expect([...plan.standIns.keys()]).toEqual(
      expect.arrayContaining(['renderers/webgl/WebGLOutput.js', 'renderers/webgl/WebGLUniformsGroups.js']),
    );
    expect([...plan.rewrites]).toEqual(
      expect.arrayContaining(['renderers/webgl/WebGLTextures.js', 'renderers/webgl/WebGLMaterials.js']),
    );
  });

  it('WebGLTextures keeps 2D textures (the DFG table) and stubs render targets and the other kinds, each throwing its name', () => {
    const cut = cutOf('renderers/webgl/WebGLTextures.js');
    expect(cut).toContain('function uploadTexture(');
    expect(cut).toContain('function setTexture2D( texture, slot ) {');
    expect(cut).not.toMatch(/function setTexture2D\( texture, slot \) \{\s*throw/);
    for (const name of [
      'setTextureCube',
      'setTexture3D',
      'setTexture2DArray',
      'setupRenderTarget',
      'updateMultisampleRenderTarget',
    ])
      expect(cut, name).toContain(`three.js trimmed: WebGLTextures.${name} is not in this build`);
    // Minified, the helpers only those reach go too: no framebuffer, render buffer or cube face left.
    const minified = minifySync('WebGLTextures.js', cut, { module: true }).code;
    expect(minifySync('WebGLTextures.js', read('renderers/webgl/WebGLTextures.js'), { module: true }).code).toContain(
      'framebufferTexture2D',
    );
    expect(minified).not.toMatch(
      /framebufferTexture2D|renderbufferStorageMultisample|blitFramebuffer|TEXTURE_CUBE_MAP_POSITIVE_X/,
    );
    expect(minified).toContain('texSubImage2D');
    // Uploads: data textures only (three's DFG table); the other kinds' branches go, another texture throws.
    expect(minified).not.toMatch(/compressedTexImage2D|texImage3D|copyTexSubImage2D/);
    expect(cut).toContain('three.js trimmed: a texture other than a DataTexture is not in this build');
    expect(cut).toMatch(/\n\t\t\tif \( texture\.isDataTexture \) \{\n/);
  });

  it('WebGLMaterials keeps the basic, Lambert, standard and points refreshes and stubs the others', () => {
    const cut = cutOf('renderers/webgl/WebGLMaterials.js');
    expect(cut).toContain('MeshPhysicalMaterial is not in this build');
    expect(cut).toContain('LineDashedMaterial is not in this build');
    expect(cut).not.toContain('clearcoatNormalScale');
    for (const kept of ['refreshUniformsCommon', 'refreshUniformsStandard', 'refreshUniformsPoints']) {
      expect(cut, kept).toContain(`function ${kept}(`);
      expect(cut, kept).not.toMatch(new RegExp(`function ${kept}\\([^)]*\\) \\{\\s*throw`));
    }
  });

  it("WebGLProgram loses the prefix lines of dead switches and of their maps' channels, and keeps the live ones", () => {
    const code = read('renderers/webgl/WebGLProgram.js');
    const cut = trimModule('renderers/webgl/WebGLProgram.js', code, plan) as string;
    expect(code).toContain("parameters.map ? '#define USE_MAP' : '',");
    expect(code).toContain("parameters.mapUv ? '#define MAP_UV ' + parameters.mapUv : '',");
    expect(cut).not.toMatch(
      /#define (USE_MAP|MAP_UV|USE_CLEARCOAT_NORMALMAP|CLEARCOAT_NORMALMAP_UV|USE_FOG|USE_SKINNING)\b/,
    );
    for (const live of [
      'HAS_NORMAL',
      'USE_COLOR',
      'DOUBLE_SIDED',
      'FLAT_SHADED',
      'USE_SIZEATTENUATION',
      'TONE_MAPPING',
    ])
      expect(cut, live).toContain(`'#define ${live}'`);
    // A switch that is not dead keeps its line, and its map's channel.
    const lines = "\t\t\tp.map ? '#define USE_MAP' : '',\n\t\t\tp.mapUv ? '#define MAP_UV ' + p.mapUv : '',\n";
    expect(dropDeadDefines(lines, new Set(['USE_FOG']))).toBe(lines);
    expect(dropDeadDefines(lines, new Set(['USE_MAP']))).toBe('');
  });

  it('WebGLRenderer keeps what the page calls and stubs render targets, copies, reads, effects, compiling and transmission', () => {
    const cut = cutOf('renderers/WebGLRenderer.js');
    for (const name of ['setRenderTarget', 'readRenderTargetPixels', 'copyTextureToTexture', 'compile', 'setEffects'])
      expect(cut, name).toContain(`three.js trimmed: WebGLRenderer.${name} is not in this build`);
    expect(cut).toContain('three.js trimmed: the transmission pass is not in this build');
    for (const kept of ['render', 'setSize', 'setPixelRatio', 'setClearColor', 'dispose'])
      expect(cut, kept).not.toMatch(new RegExp(`this\\.${kept} = function \\([^)]*\\) \\{\\s*throw`));
    expect(minifySync('WebGLRenderer.js', cut, { module: true }).code).not.toMatch(/readPixels|blitFramebuffer/);
  });

  it('serialisation and raycasting stubbed in every module that has them; the rest of each module kept', () => {
    const object = cutOf('core/Object3D.js');
    expect(object).toContain('three.js trimmed: Object3D.js toJSON is not in this build');
    expect(object).toMatch(/\n\tcopy\( source, recursive = true \) \{\n\n\t\tthis\.name = source\.name/);
    const material = cutOf('materials/Material.js');
    expect(material).toContain('Material.js fromJSON is not in this build');
    expect(material).not.toContain('json.clippingPlanes');
    expect(cutOf('objects/Mesh.js')).toContain('three.js trimmed: Mesh.js raycast is not in this build');
    expect(cutOf('objects/Points.js')).toContain('three.js trimmed: Points.js raycast is not in this build');
  });

  it('each cut stays whole when a source could reach it', () => {
    const keptWith = (extraSources: string, extraParts = '') =>
      trimPlan(three, parts + extraParts, `${sources}\n${extraSources}`).kept;
    expect(keptWith('renderer.setRenderTarget(target);')).toEqual([TEXTURES, RENDERER]);
    expect(keptWith('new WebGLRenderer({ outputBufferType: HalfFloatType });')).toEqual([
      'the output render pass',
      TEXTURES,
      RENDERER,
    ]);
    expect(keptWith('material.uniformsGroups = [group];')).toEqual(['uniform buffer objects']);
    expect(keptWith('renderer.compile(scene, camera);')).toEqual([RENDERER]);
    expect(keptWith('const saved = mesh.toJSON();')).toEqual(['serialisation (toJSON, fromJSON)']);
    expect(keptWith('const x = 1;', '')).toEqual([]);
    expect(keptWith('', "\nexport { Raycaster } from 'three/src/core/Raycaster.js';")).toEqual(['raycasting']);
    expect(keptWith('mesh.raycast(caster, hits);')).toEqual(['raycasting']);
    expect(keptWith('', "\nexport { MeshPhongMaterial } from 'three/src/materials/MeshPhongMaterial.js';")).toEqual([
      "other materials' uniform refreshes",
    ]);
    // A page shader with a cube sampler binds cube textures.
    expect(keptWith('const glsl = `uniform samplerCube sky;`;')).toEqual([TEXTURES]);
    expect(keptWith('const glsl = `uniform highp sampler2DArray layers;`;')).toEqual([TEXTURES]);
    // JSON.stringify calls toJSON: not in a file that imports three; elsewhere (plain data) it is no reach.
    const stringified = `${SOURCE_SEPARATOR}import { Mesh } from 'three';\nsave(JSON.stringify(mesh));`;
    expect(keptWith(stringified)).toEqual(['serialisation (toJSON, fromJSON)']);
    expect(keptWith(`${SOURCE_SEPARATOR}save(JSON.stringify({ a: 1 }));`)).toEqual([]);
  });

  it('a sampler under `#if NUM_LIGHT_PROBE_GRIDS > 0` is not compiled without light probe grids; its #else part is', () => {
    const glsl = [
      'a',
      '#if NUM_LIGHT_PROBE_GRIDS > 0',
      'uniform sampler3D s;',
      '#ifdef X',
      'b',
      '#endif',
      '#endif',
      'c',
    ].join('\n');
    expect(withoutBlocks(glsl, '#if NUM_LIGHT_PROBE_GRIDS > 0')).toBe('a\nc');
    const withElse = ['#if NUM_LIGHT_PROBE_GRIDS > 0', 'x', '#else', 'uniform samplerCube y;', '#endif', 'z'].join(
      '\n',
    );
    expect(withoutBlocks(withElse, '#if NUM_LIGHT_PROBE_GRIDS > 0')).toContain('samplerCube y');
    expect(withoutBlocks(withElse, '#if NUM_LIGHT_PROBE_GRIDS > 0')).toContain('z');
  });
});

describe("the site's public scripts ship minified", () => {
  it('embed.js: under half its gzip size, the same element, and a syntax error stops the build', () => {
    const source = readFileSync(`${root}public/embed.js`, 'utf8');
    const out = minifyScript('embed.js', source);
    expect(out.length).toBeLessThan(0.5 * source.length);
    expect(out).toContain('path-interval-calculator');
    expect(out).not.toMatch(/^\s*import |^\s*export /m);
    expect(() => minifyScript('broken.js', 'function (')).toThrow(/broken\.js/);
  });
});

describe("three.js's class methods that nothing names", () => {
  it('drops a method named nowhere else (in three or the page), keeps any named elsewhere, to a fixpoint', () => {
    expect(plan.unnamed.get('math/Vector4.js')).toEqual(
      expect.arrayContaining(['setAxisAngleFromQuaternion', 'setAxisAngleFromRotationMatrix']),
    );
    // Methods the page or three calls stay.
    for (const [path, name] of [
      ['core/Object3D.js', 'lookAt'],
      ['core/Object3D.js', 'updateMatrixWorld'],
      ['math/Quaternion.js', 'setFromUnitVectors'],
      ['math/Matrix4.js', 'makeRotationAxis'],
    ] as const)
      expect(plan.unnamed.get(path) ?? [], `${path} ${name}`).not.toContain(name);
    // A page source that names one keeps it.
    const named = unnamedMethods(three, `${sources}\nq.setAxisAngleFromQuaternion(x);`);
    expect(named.get('math/Vector4.js')).not.toContain('setAxisAngleFromQuaternion');
    const cut = cutOf('math/Vector4.js');
    expect(cut).not.toContain('setAxisAngleFromRotationMatrix(');
    expect(cut).toContain('\n\tapplyMatrix4( m ) {');
  });

  it('a method named only inside dropped methods goes in the next round', () => {
    const dir = mkdtempSync(join(tmpdir(), 'three-src-'));
    const a =
      'export class A {\n\n\tgone() {\n\n\t\treturn this.helper();\n\n\t}\n\n\thelper() {\n\n\t\treturn 1;\n\n\t}\n\n\tused() {\n\n\t\treturn 2;\n\n\t}\n\n}\n';
    writeFileSync(join(dir, 'A.js'), a);
    writeFileSync(join(dir, 'B.js'), 'import { A } from "./A.js";\nnew A().used();\n');
    expect(unnamedMethods(`${dir}/`, '')).toEqual(new Map([['A.js', ['gone', 'helper']]]));
    rmSync(dir, { recursive: true });
  });

  it('drops a whole method and nothing past it, and never matches past a method that is not a class method', () => {
    const code =
      'class A {\n\n\tkeep() {\n\n\t\treturn 1;\n\n\t}\n\n\tgone( x ) {\n\n\t\treturn x;\n\n\t}\n\n\tnext() {}\n\n}\n';
    expect(dropMethods(code, ['gone'])).toBe('class A {\n\n\tkeep() {\n\n\t\treturn 1;\n\n\t}\n\n\n\tnext() {}\n\n}\n');
    // An object literal's method closes with `\t},`: no class method there, nothing dropped.
    const literal =
      'const o = {\n\tgone() {\n\t\treturn 1;\n\t},\n\tother: 2\n};\nclass B {\n\tb() {\n\t\treturn 2;\n\t}\n}\n';
    expect(dropMethods(literal, ['gone'])).toBe(literal);
  });
});
