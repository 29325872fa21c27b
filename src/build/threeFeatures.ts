/**
 * The features of three.js that src/build/threeTrim.ts removes when the page's sources cannot reach
 * them: for each, the check that proves it unused, the preprocessor switches only it turns on, and
 * the modules replaced by stand-ins or cut in part.
 */
/**
 * A feature of three.js the page may not use: the proof (`unused`, given the exported class names
 * and the page's sources) and the preprocessor switches that only it turns on (WebGLProgram.js's
 * prefixes: each `#define` there depends on a material, geometry, scene or renderer property
 * that the feature alone sets). `modules`: three's modules it replaces by a stand-in.
 */
export interface Feature {
  readonly name: string;
  unused(exports: ReadonlySet<string>, sources: string): boolean;
  readonly macros: readonly string[];
  readonly modules?: readonly string[];
  /** three's modules of which a part only it reaches is cut ({@link REWRITES}). */
  readonly rewrites?: readonly string[];
  /**
   * A further proof over the GLSL the page can compile (the kept shader chunks, after the other
   * features' dead blocks are dropped, and the page's own sources): false keeps the feature whole.
   * Only for a feature without macros (its removal must not change the shaders it reads).
   */
  unusedInShaders?(glsl: string): boolean;
}

const exportsNone = (exports: ReadonlySet<string>, pattern: RegExp) => ![...exports].some((e) => pattern.test(e));

/** The line between two files in the page's sources as threeTrim.ts pageSources joins them. */
export const SOURCE_SEPARATOR = '\n// --- threeTrim: next source file ---\n';

/** The page's source files that import three (through threeParts.ts: `from 'three'`). */
const threeImporters = (sources: string) =>
  sources.split(SOURCE_SEPARATOR).filter((file) => /\bfrom\s*['"]three['"]/.test(file));

/** The modules of three in the build with their serialisation methods (class methods). */
const SERIALISED: Readonly<Record<string, readonly string[]>> = {
  'core/Object3D.js': ['toJSON'],
  'core/BufferGeometry.js': ['toJSON'],
  'core/BufferAttribute.js': ['toJSON'],
  'materials/Material.js': ['toJSON', 'fromJSON'],
  'materials/ShaderMaterial.js': ['toJSON', 'fromJSON'],
  'textures/Texture.js': ['toJSON'],
  'textures/TextureSource.js': ['toJSON'],
  'textures/DepthTexture.js': ['toJSON'],
  'scenes/Scene.js': ['toJSON'],
  'lights/Light.js': ['toJSON'],
  'lights/LightShadow.js': ['toJSON'],
  'lights/DirectionalLight.js': ['toJSON'],
  'cameras/PerspectiveCamera.js': ['toJSON'],
  'cameras/OrthographicCamera.js': ['toJSON'],
};

/** The objects' raycast methods (called only by a Raycaster). */
const RAYCAST: Readonly<Record<string, readonly string[]>> = {
  'objects/Mesh.js': ['raycast'],
  'objects/Points.js': ['raycast'],
};

/** WebGLRenderer's methods for render targets, texture copies, pixel reads, effects and compiling ahead. */
const RENDERER_API = [
  'setEffects',
  'compile',
  'compileAsync',
  'setRenderTargetTextures',
  'setRenderTargetFramebuffer',
  'setRenderTarget',
  'readRenderTargetPixels',
  'readRenderTargetPixelsAsync',
  'copyFramebufferToTexture',
  'copyTextureToTexture',
  'initRenderTarget',
  'initTexture',
];

export const FEATURES: readonly Feature[] = [
  {
    // No texture can exist: no texture class, loader or render target is exported, and the page
    // imports three only through threeParts.ts (checked in threeTrimPlugin). So no material map,
    // no environment (scene.environment, envMap) and no PMREM.
    name: 'textures and environment maps',
    unused: (exports, sources) =>
      exportsNone(exports, /Texture|Loader|RenderTarget|CubeCamera|PMREM/) &&
      !/\b(envMap|environment)\s*[:=]/.test(sources),
    macros: [
      ...['MAP', 'ALPHAMAP', 'AOMAP', 'LIGHTMAP', 'BUMPMAP', 'NORMALMAP', 'DISPLACEMENTMAP', 'EMISSIVEMAP'].map(
        (m) => `USE_${m}`,
      ),
      ...['METALNESSMAP', 'ROUGHNESSMAP', 'SPECULARMAP', 'GRADIENTMAP', 'MATCAP', 'ENVMAP', 'POINTS_UV'].map(
        (m) => `USE_${m}`,
      ),
      'USE_NORMALMAP_OBJECTSPACE',
      'USE_NORMALMAP_TANGENTSPACE',
      'USE_PACKED_NORMALMAP',
      'USE_UV1',
      'USE_UV2',
      'USE_UV3',
      'ENVMAP_TYPE_CUBE',
      'ENVMAP_TYPE_CUBE_UV',
      'ENVMAP_MODE_REFRACTION',
      'ENVMAP_BLENDING_MULTIPLY',
      'ENVMAP_BLENDING_MIX',
      'ENVMAP_BLENDING_ADD',
      'DECODE_VIDEO_TEXTURE',
      'DECODE_VIDEO_TEXTURE_EMISSIVE',
    ],
    modules: ['renderers/webgl/WebGLEnvironments.js'],
    rewrites: ['renderers/webgl/WebGLBackground.js'],
  },
  {
    // MeshPhysicalMaterial's switches: its class is not exported and no source sets one of its
    // properties on another material (WebGLPrograms tests `material.clearcoat > 0` and the like).
    name: 'physical-only material features',
    unused: (exports, sources) =>
      !exports.has('MeshPhysicalMaterial') &&
      !/\b(clearcoat|sheen|iridescence|transmission|thickness|anisotropy|dispersion|retroreflectivity|diffuseRoughness|specularIntensity|specularColor|attenuation)\w*\s*[:=]/.test(
        sources,
      ),
    macros: [
      'PHYSICAL',
      ...['CLEARCOAT', 'CLEARCOATMAP', 'CLEARCOAT_NORMALMAP', 'CLEARCOAT_ROUGHNESSMAP', 'SHEEN', 'SHEEN_COLORMAP'].map(
        (m) => `USE_${m}`,
      ),
      ...['SHEEN_ROUGHNESSMAP', 'IRIDESCENCE', 'IRIDESCENCEMAP', 'IRIDESCENCE_THICKNESSMAP', 'TRANSMISSION'].map(
        (m) => `USE_${m}`,
      ),
      ...['TRANSMISSIONMAP', 'THICKNESSMAP', 'ANISOTROPY', 'ANISOTROPYMAP', 'DISPERSION', 'DIFFUSE_ROUGHNESS'].map(
        (m) => `USE_${m}`,
      ),
      ...['DIFFUSE_ROUGHNESSMAP', 'RETROREFLECTION', 'SPECULAR_COLORMAP', 'SPECULAR_INTENSITYMAP'].map(
        (m) => `USE_${m}`,
      ),
    ],
  },
  {
    // Tangents need a normal map or anisotropy (both dead when textures and physical features are).
    name: 'tangents',
    unused: (exports, sources) =>
      (FEATURES[0] as Feature).unused(exports, sources) && (FEATURES[1] as Feature).unused(exports, sources),
    macros: ['USE_TANGENT'],
  },
  {
    name: 'shadow maps',
    unused: (_exports, sources) => !/\b(shadowMap|castShadow|receiveShadow)\b/.test(sources),
    macros: [
      'USE_SHADOWMAP',
      'SHADOWMAP_TYPE_PCF',
      'SHADOWMAP_TYPE_PCF_SOFT',
      'SHADOWMAP_TYPE_VSM',
      'SHADOWMAP_TYPE_BASIC',
    ],
    modules: ['renderers/webgl/WebGLShadowMap.js'],
  },
  {
    name: 'WebXR',
    unused: (_exports, sources) => !/\.xr\b|\bXRSession\b|\bWebXR/.test(sources),
    macros: [],
    modules: ['renderers/webxr/WebXRManager.js'],
  },
  {
    name: 'morph targets',
    unused: (_exports, sources) => !/\bmorph(Attributes|TargetInfluences|TargetDictionary|Targets)\b/.test(sources),
    macros: ['USE_MORPHTARGETS', 'USE_MORPHNORMALS', 'USE_MORPHCOLORS', 'USE_INSTANCING_MORPH'],
    modules: ['renderers/webgl/WebGLMorphtargets.js'],
  },
  {
    name: 'skinning, instancing and batching',
    unused: (exports) => exportsNone(exports, /^(SkinnedMesh|Skeleton|Bone|InstancedMesh|BatchedMesh)$/),
    macros: ['USE_SKINNING', 'USE_INSTANCING', 'USE_INSTANCING_COLOR', 'USE_BATCHING', 'USE_BATCHING_COLOR'],
  },
  {
    name: 'fog',
    unused: (exports, sources) => exportsNone(exports, /^Fog/) && !/\.fog\s*=/.test(sources),
    macros: ['USE_FOG', 'FOG_EXP2'],
  },
  {
    name: 'logarithmic and reversed depth buffers',
    unused: (_exports, sources) => !/\b(logarithmicDepthBuffer|reversedDepthBuffer)\b/.test(sources),
    macros: ['USE_LOGARITHMIC_DEPTH_BUFFER', 'USE_REVERSED_DEPTH_BUFFER'],
  },
  {
    name: 'light probes',
    unused: (exports) => exportsNone(exports, /LightProbe/),
    macros: ['USE_LIGHT_PROBES'],
  },
  {
    // Uniform buffer objects: only a ShaderMaterial whose `uniformsGroups` the page fills has one
    // (the class UniformsGroup is not exported, and no source names the property).
    name: 'uniform buffer objects',
    unused: (exports, sources) => exportsNone(exports, /^UniformsGroup$/) && !/\buniformsGroups\b/.test(sources),
    macros: [],
    modules: ['renderers/webgl/WebGLUniformsGroups.js'],
  },
  {
    // The renderer's own render pass (WebGLOutput): made only for an `outputBufferType` other than
    // the default UnsignedByteType (HDR, post-processing effects), which no source gives.
    name: 'the output render pass',
    unused: (_exports, sources) => !/\boutputBufferType\b/.test(sources),
    macros: [],
    modules: ['renderers/webgl/WebGLOutput.js'],
  },
  {
    // Render targets, and textures other than 2D ones: no render target class is exported (the
    // first feature) and no source draws into one or copies textures (the renderer's own render
    // targets are the transmission pass's, the shadow maps', WebXR's and the output pass's, all
    // removed above); a cube, 3D or array texture is bound only for a sampler of that type, and no
    // shader the page can compile declares one. Data textures stay (MeshStandardMaterial's DFG table,
    // the only texture uploaded): uploadTexture keeps their branch only (dataTexturesOnly).
    name: 'render targets and cube, 3D and array textures',
    unused: (exports, sources) =>
      [
        'textures and environment maps',
        'physical-only material features',
        'shadow maps',
        'WebXR',
        'light probes',
      ].every((name) => FEATURES.find((f) => f.name === name)?.unused(exports, sources)) &&
      !/\boutputBufferType\b/.test(sources) &&
      !/\b(setRenderTarget|initRenderTarget|initTexture|copyTextureToTexture\w*|copyFramebufferToTexture|readRenderTargetPixels\w*)\b/.test(
        sources,
      ),
    // The light probe grids' 3D textures are declared under `#if NUM_LIGHT_PROBE_GRIDS > 0`, the count
    // of LightProbeGrid objects (WebGLPrograms), 0 without the class (the light probes feature).
    unusedInShaders: (glsl) =>
      !/\b[iu]?sampler(Cube|3D|2DArray)\w*\b/.test(withoutBlocks(glsl, '#if NUM_LIGHT_PROBE_GRIDS > 0')),
    macros: [],
    rewrites: ['renderers/webgl/WebGLTextures.js'],
  },
  {
    // Serialisation: three calls toJSON and fromJSON only from each other (ObjectLoader and the
    // other loaders are not in the build); the page names neither, and no file that imports three
    // calls JSON.stringify (which would call toJSON).
    name: 'serialisation (toJSON, fromJSON)',
    unused: (_exports, sources) =>
      !/\b(toJSON|fromJSON)\b/.test(sources) && !threeImporters(sources).some((file) => /JSON\.stringify/.test(file)),
    macros: [],
    rewrites: Object.keys(SERIALISED),
  },
  {
    // Picking: a mesh's or points' raycast runs only for a Raycaster, which is not exported.
    name: 'raycasting',
    unused: (exports, sources) => exportsNone(exports, /^Raycaster$/) && !/\braycast\b/.test(sources),
    macros: [],
    rewrites: Object.keys(RAYCAST),
  },
  {
    // WebGLRenderer's API beyond what the page calls, which only render targets, texture copies and
    // reads, effects, compiling ahead and the transmission pass (physical materials) reach: kept
    // while a source names one of these methods, or render targets can exist.
    name: "the renderer's render-target, copy and compile API",
    unused: (exports, sources) =>
      FEATURES.find((f) => f.name === 'render targets and cube, 3D and array textures')?.unused(exports, sources) ===
        true && !new RegExp(`\\b(${RENDERER_API.join('|')})\\b`).test(sources),
    macros: [],
    rewrites: ['renderers/WebGLRenderer.js'],
  },
  {
    // WebGLMaterials' uniform refreshes of materials the page has no class of (each called only
    // for its own material, `material.isMeshPhysicalMaterial` and the like): cut while none of them
    // is exported, all kept while any is.
    name: "other materials' uniform refreshes",
    unused: (exports) => Object.values(OTHER_MATERIALS).every((m) => !exports.has(m)),
    macros: [],
    rewrites: ['renderers/webgl/WebGLMaterials.js'],
  },
];

/** WebGLMaterials.js's refreshes of materials the page does not use, each with its material's class. */
const OTHER_MATERIALS: Readonly<Record<string, string>> = {
  refreshUniformsToon: 'MeshToonMaterial',
  refreshUniformsPhong: 'MeshPhongMaterial',
  refreshUniformsPhysical: 'MeshPhysicalMaterial',
  refreshUniformsMatcap: 'MeshMatcapMaterial',
  refreshUniformsDistance: 'MeshDistanceMaterial',
  refreshUniformsSprites: 'SpriteMaterial',
  refreshUniformsLine: 'LineBasicMaterial',
  refreshUniformsDash: 'LineDashedMaterial',
};

/**
 * `glsl` without the blocks that open with the line `opening` (to their `#endif`, nested blocks
 * counted); a block with an `#else` or `#elif` of its own is kept from there on (that part compiles).
 */
export function withoutBlocks(glsl: string, opening: string): string {
  const out: string[] = [];
  let depth = 0;
  for (const line of glsl.split('\n')) {
    const directive = line.trim();
    if (depth === 0) {
      if (directive === opening) depth = 1;
      else out.push(line);
    } else if (/^#\s*if/.test(directive)) depth++;
    else if (/^#\s*endif/.test(directive)) depth--;
    else if (depth === 1 && /^#\s*(else|elif)/.test(directive)) {
      depth = 0;
      out.push('#if 1');
    }
  }
  return out.join('\n');
}

/** WebGLTextures.js's functions for render targets and for cube, 3D and array textures. */
const TEXTURE_FUNCTIONS = [
  'setTexture2DArray',
  'setTexture3D',
  'setTextureCube',
  'rebindTextures',
  'setupRenderTarget',
  'updateRenderTargetMipmap',
  'updateMultisampleRenderTarget',
  'setupDepthRenderbuffer',
  'setupFrameBufferTexture',
];

/** A stand-in module's code: a class or factory whose reached methods throw, naming `what`. */
const unreachable = (what: string) => `throw new Error("three.js trimmed: ${what} is not in this build")`;

/** The stand-ins, by module path under three/src/ (the API WebGLRenderer and WebGLBackground call). */
export const STAND_INS: Readonly<Record<string, string>> = {
  'renderers/webxr/WebXRManager.js': `export class WebXRManager {
  constructor() { this.enabled = false; this.isPresenting = false; this.cameraAutoUpdate = true; }
  addEventListener() {} removeEventListener() {} setAnimationLoop() {} dispose() {}
  getEnvironmentBlendMode() { return undefined; } hasDepthSensing() { return false; }
  getDepthSensingMesh() { return null; }
  updateCamera() { ${unreachable('WebXR')} } getCamera() { ${unreachable('WebXR')} }
}`,
  'renderers/webgl/WebGLShadowMap.js': `import { PCFShadowMap } from '../../constants.js';
export function WebGLShadowMap() {
  this.enabled = false; this.autoUpdate = true; this.needsUpdate = false; this.type = PCFShadowMap;
  this.render = function () { if (this.enabled) ${unreachable('the shadow map')}; };
}`,
  'renderers/webgl/WebGLEnvironments.js': `export function WebGLEnvironments() {
  return { get(texture) { if (texture === null || texture === undefined) return null; ${unreachable('an environment map')}; }, dispose() {} };
}`,
  'renderers/webgl/WebGLMorphtargets.js': `export function WebGLMorphtargets() {
  return { update() { ${unreachable('morph targets')}; } };
}`,
  'renderers/webgl/WebGLOutput.js': `export function WebGLOutput() { ${unreachable('the output render pass')}; }`,
  'renderers/webgl/WebGLUniformsGroups.js': `export function WebGLUniformsGroups() {
  return { bind() { ${unreachable('a uniform buffer object')}; }, update() { ${unreachable('a uniform buffer object')}; }, dispose() {} };
}`,
};

/**
 * `code` with the text from `from` up to (not including) `to` replaced by `by`; throws when either
 * marker is missing (a three.js upgrade that moved the code fails the build instead of shipping it).
 */
function cut(code: string, from: string, to: string, by: string, file: string): string {
  const start = code.indexOf(from);
  const end = code.indexOf(to, start);
  if (start < 0 || end < 0) throw new Error(`threeTrim: ${file} no longer has ${JSON.stringify(from)}`);
  return code.slice(0, start) + by + code.slice(end);
}

/**
 * `code` with the body of a function replaced by a throw naming `what`; throws when it is missing. The
 * function opens with the text `opening` (up to its ` {` line end) and closes at the next line that
 * is `closing` (its indentation and brace).
 */
function stubBody(code: string, opening: string, closing: string, what: string, file: string): string {
  const start = code.indexOf(opening);
  const open = code.indexOf(' {\n', start);
  const end = code.indexOf(`\n${closing}\n`, open);
  if (start < 0 || open < 0 || end < 0) throw new Error(`threeTrim: ${file} no longer has ${JSON.stringify(opening)}`);
  const indent = `${/^\t*/.exec(closing)?.[0] ?? ''}\t`;
  return `${code.slice(0, open)} {\n${indent}${unreachable(what)};${code.slice(end)}`;
}

/** An inner function of a factory (`\tfunction name(`), or with `method`, a class method (`\tname(`), stubbed. */
function stubFunction(code: string, name: string, what: string, file: string, method = false): string {
  return stubBody(code, method ? `\n\t${name}(` : `\tfunction ${name}(`, '\t}', what, file);
}

/** WebGLRenderer's methods (`this.name = function`) and inner functions (`function name(`), stubbed. */
function stubRenderer(code: string): string {
  const file = 'WebGLRenderer.js';
  const methods = RENDERER_API.reduce(
    (out, name) => stubBody(out, `\t\tthis.${name} = `, '\t\t};', `WebGLRenderer.${name}`, file),
    code,
  );
  return stubBody(methods, '\t\tfunction renderTransmissionPass(', '\t\t}', 'the transmission pass', file);
}

/**
 * WebGLTextures' uploadTexture for data textures only: the only texture uploaded is three's DFG table
 * (a DataTexture, MeshStandardMaterial's); no texture class is exported, render targets (with their
 * depth textures) are gone, and WebGLUniforms' empty textures are never uploaded (version 0). The
 * depth, compressed, array, 3D, framebuffer, HTML and image branches go; another texture throws.
 */
function dataTexturesOnly(code: string): string {
  const file = 'WebGLTextures.js';
  const depthCut = cut(
    code,
    '\t\t\tif ( texture.isDepthTexture ) {',
    '\t\t\t} else if ( texture.isDataTexture ) {',
    '',
    file,
  );
  return cut(
    depthCut.replace('\t\t\t} else if ( texture.isDataTexture ) {', '\t\t\tif ( texture.isDataTexture ) {'),
    '\t\t\t} else if ( texture.isCompressedTexture ) {',
    '\n\n\t\t\tif ( textureNeedsGenerateMipmaps( texture ) && texture.mipmapsAutoUpdate === true ) {',
    `\t\t\t} else {\n\t\t\t\t${unreachable('a texture other than a DataTexture')};\n\t\t\t}`,
    file,
  );
}

/**
 * Parts of modules cut, by module path under three/src/: WebGLBackground's texture backgrounds
 * (the cube and plane meshes with their shaders; a colour or no background is unchanged), and
 * WebGLMaterials' refreshes of other materials' uniforms.
 */
export const REWRITES: Readonly<Record<string, (code: string) => string>> = {
  'renderers/WebGLRenderer.js': stubRenderer,
  ...Object.fromEntries(
    Object.entries({ ...SERIALISED, ...RAYCAST }).map(([path, methods]) => [
      path,
      (code: string) =>
        methods.reduce((out, name) => stubFunction(out, name, `${path.split('/').pop()} ${name}`, path, true), code),
    ]),
  ),
  'renderers/webgl/WebGLTextures.js': (code) =>
    dataTexturesOnly(
      TEXTURE_FUNCTIONS.reduce(
        (out, name) => stubFunction(out, name, `WebGLTextures.${name}`, 'WebGLTextures.js'),
        code,
      ),
    ),
  'renderers/webgl/WebGLMaterials.js': (code) =>
    Object.entries(OTHER_MATERIALS).reduce(
      (out, [name, material]) => stubFunction(out, name, material, 'WebGLMaterials.js'),
      code,
    ),
  'renderers/webgl/WebGLBackground.js': (code) =>
    cut(
      code,
      '\tfunction addToRenderList( renderList, scene ) {',
      '\tfunction setClear( color, alpha ) {',
      `\tfunction addToRenderList( renderList, scene ) {\n\t\tconst background = getBackground( scene );\n\t\tif ( background && background.isTexture ) ${unreachable('a texture background')};\n\t}\n\n`,
      'WebGLBackground.js',
    ),
};
