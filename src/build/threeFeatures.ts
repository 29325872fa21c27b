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
}

const exportsNone = (exports: ReadonlySet<string>, pattern: RegExp) => ![...exports].some((e) => pattern.test(e));

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
 * Parts of modules cut, by module path under three/src/: WebGLBackground's texture backgrounds
 * (the cube and plane meshes with their shaders; a colour or no background is unchanged).
 */
export const REWRITES: Readonly<Record<string, (code: string) => string>> = {
  'renderers/webgl/WebGLBackground.js': (code) =>
    cut(
      code,
      '\tfunction addToRenderList( renderList, scene ) {',
      '\tfunction setClear( color, alpha ) {',
      `\tfunction addToRenderList( renderList, scene ) {\n\t\tconst background = getBackground( scene );\n\t\tif ( background && background.isTexture ) ${unreachable('a texture background')};\n\t}\n\n`,
      'WebGLBackground.js',
    ),
};
