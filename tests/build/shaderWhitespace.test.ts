/**
 * three.js's shaders compacted at build time (src/build/shaderWhitespace.ts) are the same GLSL:
 * checked against an independent reading of each shader source, its token sequence (maximal
 * munch, as the GLSL compiler reads it, comments skipped, so two operators glued into another
 * fail) and its preprocessor directives (each on its own line, the blank that makes a macro
 * object-like kept).
 */
import { readdirSync, readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { compactGlsl, compactThreeShaderSource } from '../../src/build/shaderWhitespace';

/** GLSL tokens, comments first (then dropped), longest operator first (`--` is one token, `- -` two). */
const TOKEN =
  /\/\/[^\n]*|\/\*[\s\S]*?\*\/|[A-Za-z_]\w*|\d+\.?\d*(?:[eE][+-]?\d+)?[uUfF]?|\.\d+(?:[eE][+-]?\d+)?|<<=|>>=|\+\+|--|<<|>>|&&|\|\||\^\^|[-+*/%<>=!&|^]=|\S/g;
const tokens = (glsl: string) => (glsl.match(TOKEN) ?? []).filter((t) => !t.startsWith('//') && !t.startsWith('/*'));
/** The directives, each line's comments dropped and blanks collapsed (`#define A( x )` and `#define A ( x )` stay distinct). */
const directives = (glsl: string) =>
  glsl
    .replace(/\/\*[\s\S]*?\*\//g, ' ')
    .split('\n')
    .map((l) =>
      l
        .replace(/\/\/.*$/, '')
        .trim()
        .replace(/\s+/g, ' '),
    )
    .filter((l) => l.startsWith('#'));
/** The GLSL templates of a shader source (tagged), or of its compacted form (the tag goes with the comments). */
const templates = (source: string, tagged = true) =>
  [...source.matchAll(tagged ? /\/\* glsl \*\/`([^`]*)`/g : /`([^`]*)`/g)].map((m) => m[1] as string);

const SHADERS = fileURLToPath(new URL('../../node_modules/three/src/renderers/shaders', import.meta.url));
const files = readdirSync(SHADERS, { recursive: true, encoding: 'utf8' }).filter((f) => f.endsWith('.glsl.js'));

describe('compactGlsl', () => {
  it('drops indentation and the blanks beside brackets, keeps each line and every operator apart', () => {
    const glsl = '#ifdef USE_A\n\tfloat x = f( a - -b, c );\n\n#endif\n#define OBJ ( 1.0 )\n#define FN( x ) ( x )';
    const out = compactGlsl(glsl);
    expect(out).toBe('#ifdef USE_A\nfloat x = f(a - -b,c);\n#endif\n#define OBJ ( 1.0 )\n#define FN( x ) ( x )');
    expect(tokens(out)).toEqual(tokens(glsl));
    expect(directives(out)).toEqual(directives(glsl));
  });
});

describe("three.js's shader sources, compacted", () => {
  it('are each the same tokens and directives, and smaller', () => {
    expect(files.length).toBeGreaterThan(100);
    let before = 0;
    let after = 0;
    for (const file of files) {
      const source = readFileSync(`${SHADERS}/${file}`, 'utf8');
      const was = templates(source);
      const now = templates(compactThreeShaderSource(source, file), false);
      expect(now.length, file).toBe(was.length);
      was.forEach((glsl, i) => {
        expect(tokens(now[i] as string), file).toEqual(tokens(glsl));
        expect(directives(now[i] as string), file).toEqual(directives(glsl));
      });
      before += source.length;
      after += compactThreeShaderSource(source, file).length;
    }
    expect(after).toBeLessThan(before * 0.85);
  });

  it('leave the JavaScript around the templates as it was', () => {
    const source =
      'export const vertex = /* glsl */`\n\tvoid main() {\n\t\tgl_Position = vec4( 0.0 ); // here\n\t}\n`;\n';
    expect(compactThreeShaderSource(source)).toBe(
      'export const vertex = `void main(){\ngl_Position = vec4(0.0);\n}`;\n',
    );
  });

  it('fail the build when three.js no longer has that layout', () => {
    expect(() => compactThreeShaderSource('export default `x`;', 'a.glsl.js')).toThrow(/no \/\* glsl \*\/ template/);
    // biome-ignore lint/suspicious/noTemplateCurlyInString: the source text of a template that interpolates
    expect(() => compactThreeShaderSource('export default /* glsl */`${a}`;', 'b.glsl.js')).toThrow(/interpolates/);
  });
});
