/**
 * The README's glossary sketch (tests/readme/glossary.svg) is drawn to scale and right: read back
 * from the SVG, its CC points, cusp P_hp, h pseudo plane, corner ball, dimensions and tool outlines
 * agree with the core's exact answer for the inputs the sketch states (its data-* attributes), and
 * the two posture insets lean by the stated lead and tilt with the tool resting on its plane.
 */
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { solveForwardRaw } from '../../src/core/library';

const SVG = readFileSync(fileURLToPath(new URL('./glossary.svg', import.meta.url)), 'utf8');

/** The attributes of the element with this id. */
function element(id: string): Record<string, string> {
  const m = new RegExp(`<\\w+\\s[^>]*\\bid="${id}"[^>]*>`).exec(SVG);
  if (!m) throw new Error(`glossary.svg has no element #${id}`);
  const out: Record<string, string> = {};
  for (const a of m[0].matchAll(/([\w-]+)="([^"]*)"/g)) out[a[1] as string] = a[2] as string;
  return out;
}

const num = (attrs: Record<string, string>, name: string): number => {
  const v = Number(attrs[name]);
  if (!Number.isFinite(v)) throw new Error(`no number ${name}`);
  return v;
};

const root = (() => {
  const m = /<svg\s[^>]*>/.exec(SVG);
  if (!m) throw new Error('no <svg>');
  const out: Record<string, string> = {};
  for (const a of m[0].matchAll(/([\w-]+)="([^"]*)"/g)) out[a[1] as string] = a[2] as string;
  return out;
})();

const scalePx = num(root, 'data-scale-px-per-mm');
const originX = num(root, 'data-origin-x');
const originY = num(root, 'data-origin-y');
const R = num(root, 'data-r-mm');
const Rcr = num(root, 'data-rcr-mm');
const rhoDeg = num(root, 'data-rho-deg');
const hMm = num(root, 'data-h-mm');
const tiltDeg = num(root, 'data-tilt-deg');

/** Sketch px to the cross-feed plane's (Y, Z) in mm, the contact of pass 1 at the origin. */
const toMm = (x: number, y: number): [number, number] => [(x - originX) / scalePx, (originY - y) / scalePx];

/** The points of a path of M/L commands, in px. */
function pathPoints(d: string): Array<[number, number]> {
  return [...d.matchAll(/[ML]\s*(-?[\d.]+)\s+(-?[\d.]+)/g)].map((m) => [Number(m[1]), Number(m[2])]);
}

const answer = solveForwardRaw({ R, Rcr, rho: rhoDeg, h: hMm });
if (!answer.ok) throw new Error('the sketch states an invalid input');
const { intervalMm, halfIntervalMm } = answer.value.exact;
/** Half a pixel, in mm: what the sketch's two decimals and the eye can hold it to. */
const PX = 0.5 / scalePx;

describe('glossary sketch', () => {
  it('states the L the core gives for its inputs', () => {
    expect(SVG).toContain(`so L = ${intervalMm.toFixed(3)} mm`);
  });

  it('puts the CC points L apart on the design plane and P_hp at (L/2, h) on the h pseudo plane', () => {
    const cc1 = element('cc-1');
    const cc2 = element('cc-2');
    const php = element('php');
    expect(toMm(num(cc1, 'cx'), num(cc1, 'cy'))).toEqual([0, 0]);
    const [y2, z2] = toMm(num(cc2, 'cx'), num(cc2, 'cy'));
    expect(Math.abs(y2 - intervalMm)).toBeLessThan(PX);
    expect(z2).toBe(0);
    const [yc, zc] = toMm(num(php, 'cx'), num(php, 'cy'));
    expect(Math.abs(yc - halfIntervalMm)).toBeLessThan(PX);
    expect(Math.abs(zc - hMm)).toBeLessThan(PX);
    const plane = element('design-plane');
    expect([num(plane, 'y1'), num(plane, 'y2')]).toEqual([originY, originY]);
    const hPlane = element('h-pseudo-plane');
    expect(toMm(0, num(hPlane, 'y1'))[1]).toBeCloseTo(hMm, 9);
    expect(hPlane.y2).toBe(hPlane.y1);
  });

  it('dimensions L from CC to CC, L/2 from CC to the cusp, h from the plane to the h pseudo plane', () => {
    const l = element('dim-l');
    expect([num(l, 'x1'), num(l, 'x2')]).toEqual([num(element('cc-1'), 'cx'), num(element('cc-2'), 'cx')]);
    const half = element('dim-half');
    expect([num(half, 'x1'), num(half, 'x2')]).toEqual([num(element('cc-1'), 'cx'), num(element('php'), 'cx')]);
    expect(num(element('dim-h-top'), 'y2')).toBe(num(element('h-pseudo-plane'), 'y1'));
    expect(num(element('dim-h-bottom'), 'y2')).toBe(originY);
  });

  it('draws each pass as the ring ellipse offset by Rcr, with the shank at |Y| = R above the centre', () => {
    const a = R - Rcr;
    const b = a * Math.sin((rhoDeg * Math.PI) / 180);
    const centreZ = b + Rcr;
    const o = element('centre-1');
    const [oy, oz] = toMm(num(o, 'cx'), num(o, 'cy'));
    expect(Math.abs(oy)).toBeLessThan(PX);
    expect(Math.abs(oz - centreZ)).toBeLessThan(PX);
    /** Distance from (y, z) to the ring ellipse (semi-axes a, b) centred at (dy, centreZ), mm. */
    const toEllipse = (y: number, z: number, dy: number): number => {
      let best = Number.POSITIVE_INFINITY;
      for (let i = 0; i < 20_000; i++) {
        const t = (2 * Math.PI * i) / 20_000;
        best = Math.min(best, Math.hypot(y - dy - a * Math.sin(t), z - centreZ + b * Math.cos(t)));
      }
      return best;
    };
    for (const [id, dy] of [
      ['profile-1', 0],
      ['profile-2', intervalMm],
    ] as const) {
      const points = pathPoints(element(id).d ?? '').map(([x, y]) => toMm(x, y));
      expect(points.length).toBeGreaterThan(40);
      for (const [y, z] of points) {
        if (z > centreZ + PX) expect(Math.abs(Math.abs(y - dy) - R)).toBeLessThan(PX);
        else expect(Math.abs(toEllipse(y, z, dy) - Rcr)).toBeLessThan(PX);
      }
    }
  });

  it('draws the corner ball at the cusp: radius Rcr, centred on the ring ellipse, through P_hp', () => {
    const ball = element('corner-ball');
    expect(num(ball, 'r') / scalePx).toBeCloseTo(Rcr, 9);
    const [ey, ez] = toMm(num(ball, 'cx'), num(ball, 'cy'));
    const [py, pz] = toMm(num(element('php'), 'cx'), num(element('php'), 'cy'));
    expect(Math.abs(Math.hypot(py - ey, pz - ez) - Rcr)).toBeLessThan(PX);
    const a = R - Rcr;
    const b = a * Math.sin((rhoDeg * Math.PI) / 180);
    expect(Math.abs((ey / a) ** 2 + ((ez - (b + Rcr)) / b) ** 2 - 1)).toBeLessThan(0.01);
  });

  it('leans the insets by the lead and the tilt, front corner down, resting on their plane', () => {
    for (const [id, angleDeg] of [
      ['lead-tool', rhoDeg],
      ['tilt-tool', tiltDeg],
    ] as const) {
      const g = element(id);
      const m = /translate\((-?[\d.]+) (-?[\d.]+)\) rotate\((-?[\d.]+)\)/.exec(g.transform ?? '');
      if (!m) throw new Error(`#${id} has no translate/rotate`);
      const [tx, ty, angle] = [Number(m[1]), Number(m[2]), Number(m[3])];
      expect(angle).toBe(angleDeg);
      // The outline (tool frame: bottom centre at the origin, y down): corners of radius rcr at x = +-(Rl - rcr).
      const shape = SVG.slice(SVG.indexOf(`id="${id}"`)).match(/d="M (-?[\d.]+) [^"]*?A ([\d.]+) /);
      if (!shape) throw new Error(`#${id} has no outline`);
      const [halfWidth, rcr] = [Math.abs(Number(shape[1])), Number(shape[2])];
      expect(halfWidth / rcr).toBeCloseTo(R / Rcr, 9); // the same tool, at its own scale
      const t = (angle * Math.PI) / 180;
      const lowest = (side: number): number => {
        const [x, y] = [side * (halfWidth - rcr), -rcr];
        return ty + x * Math.sin(t) + y * Math.cos(t) + rcr;
      };
      const plane = /<line class="plane" x1="[\d.]+" y1="([\d.]+)"/g;
      const planes = [...SVG.matchAll(plane)].map((p) => Number(p[1])).filter((y) => y > originY);
      expect(planes.length).toBe(2);
      expect(Math.abs(lowest(1) - (planes[0] as number))).toBeLessThan(0.5); // +X / +Y corner touches
      expect(lowest(-1)).toBeLessThan(lowest(1));
      expect(tx).toBeGreaterThan(0);
    }
  });
});
