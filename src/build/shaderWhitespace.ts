/**
 * Build step: the GLSL of three.js's shaders shipped without comments, indentation and the blanks
 * around brackets and separators. The site builds three.js from its sources (src/render/threeParts.ts),
 * where each shader is a commented, indented template literal in a `*.glsl.js` file (about 150 kB
 * of the `three` chunk's raw size), which the JavaScript minifier cannot touch; the WebGL compiler
 * ignores comments and that whitespace. No change to what the shaders compute.
 *
 * Only whitespace goes: every line keeps its own line (a preprocessor directive ends at its line's
 * end), a directive's blanks are only collapsed (`#define NAME ( x )` is an object-like macro and
 * `#define NAME( x )` a function-like one: the blank before its bracket is kept), and no blank
 * between two operators goes (`a - -b` must not become the decrement `a--b`).
 */
import type { Plugin } from 'vite';

/**
 * `glsl` without indentation, blank lines, runs of blanks, and (outside preprocessor directives)
 * the blanks beside `( ) [ ] { } , ;`. Pure; the result compiles to the same shader.
 */
export function compactGlsl(glsl: string): string {
  return glsl
    .split('\n')
    .map((line) => {
      const collapsed = line.trim().replace(/\s+/g, ' ');
      return collapsed.startsWith('#') ? collapsed : collapsed.replace(/ ?([()[\]{},;]) ?/g, '$1');
    })
    .filter((line) => line !== '')
    .join('\n');
}

/** three.js's shader sources: GLSL in template literals tagged by a `glsl` comment, in `*.glsl.js` files. */
const THREE_SHADER_FILE = /\/node_modules\/three\/src\/renderers\/shaders\/.*\.glsl\.js$/;
const GLSL_TEMPLATE = /\/\* glsl \*\/`([^`]*)`/g;

/** The GLSL of each `/* glsl *\/` template of a three.js shader source file, as written (with comments). */
export function glslTemplates(source: string): string[] {
  return [...source.matchAll(GLSL_TEMPLATE)].map((m) => m[1] as string);
}

/** `glsl` without its comments (GLSL has no strings, so `//` and `/*` always open one). */
export function stripGlslComments(glsl: string): string {
  return glsl.replace(/\/\*[\s\S]*?\*\//g, ' ').replace(/\/\/[^\n]*/g, '');
}

/**
 * A three.js shader source file (`src/renderers/shaders/**\/*.glsl.js`) with each GLSL template
 * without comments and compacted ({@link compactGlsl}), as three's own build strips them. Throws
 * when the file holds no such template or one interpolates (`\${}`), so a three.js upgrade that
 * changes the layout fails the build instead of silently shipping the shaders whole.
 */
export function compactThreeShaderSource(source: string, file = 'shader'): string {
  let templates = 0;
  const code = source.replace(GLSL_TEMPLATE, (_, glsl: string) => {
    if (glsl.includes('${')) throw new Error(`shaderWhitespace: ${file} interpolates into its GLSL`);
    templates++;
    return `\`${compactGlsl(stripGlslComments(glsl))}\``;
  });
  if (templates === 0) throw new Error(`shaderWhitespace: no /* glsl */ template in ${file}`);
  return code;
}

/** Vite plugin applying {@link compactThreeShaderSource} to three.js's shader sources in the build. */
export function shaderWhitespacePlugin(): Plugin {
  return {
    name: 'three-shader-whitespace',
    apply: 'build',
    transform: {
      filter: { id: THREE_SHADER_FILE },
      handler(code, id) {
        return { code: compactThreeShaderSource(code, id), map: null };
      },
    },
  };
}
