/**
 * The curved patch's material: its colour bands read per pixel from a band coordinate interpolated
 * across each triangle (curvatureShading.ts: the attribute `band`, its u in 0..1 along the strip of
 * colours, v unused), so that
 * the band edges follow the iso-height lines rather than the grid's cells, times the vertex's shade
 * (`shade`, its normal's lighting). The strip's colours are a uniform array read at the nearest entry,
 * as a texture read at its nearest texel would be, without a texture (the site's three.js ships no
 * texture code: src/build/threeFeatures.ts). Translucent, both sides, no depth write.
 */
import { Color, DoubleSide, ShaderMaterial } from 'three';
import { BAND_TEXELS, bandStripRgba } from './curvatureShading';

const VERTEX = `
attribute vec3 shade;
attribute vec2 band;
varying vec3 vShade;
varying float vBand;
void main() {
  vShade = shade;
  vBand = band.x;
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
}`;

const FRAGMENT = `
uniform vec3 bands[${BAND_TEXELS}];
uniform float alpha;
varying vec3 vShade;
varying float vBand;
void main() {
  int i = int(clamp(floor(vBand * ${BAND_TEXELS}.0), 0.0, ${BAND_TEXELS - 1}.0));
  gl_FragColor = vec4(bands[i] * vShade, alpha);
  #include <colorspace_fragment>
}`;

/** The strip's colours as the shader reads them (0-1 linear, quantised to bytes as a texel would be). */
function bandColours(): Color[] {
  const rgba = bandStripRgba();
  const out: Color[] = [];
  for (let t = 0; t < BAND_TEXELS; t++)
    out.push(
      new Color((rgba[4 * t] as number) / 255, (rgba[4 * t + 1] as number) / 255, (rgba[4 * t + 2] as number) / 255),
    );
  return out;
}

/** A banded patch's material at `opacity`. */
export class BandMaterial extends ShaderMaterial {
  constructor(opacity: number) {
    super({
      uniforms: { bands: { value: bandColours() }, alpha: { value: opacity } },
      vertexShader: VERTEX,
      fragmentShader: FRAGMENT,
      side: DoubleSide,
      transparent: true,
      depthWrite: false,
    });
  }
}
