/**
 * three.js scene of the inclined tool, its section circle and the h pseudo plane.
 * Objects are built once and updated in place; a frame is rendered only when something
 * changed (camera move, new geometry, resize), never in a busy loop.
 * Frame: the paper's (X feed, Y cross-feed, Z up), lengths in mm.
 */
import {
  AmbientLight,
  ArrowHelper,
  BufferAttribute,
  BufferGeometry,
  Color,
  DirectionalLight,
  DoubleSide,
  Group,
  Line,
  LineBasicMaterial,
  LineLoop,
  Mesh,
  MeshBasicMaterial,
  MeshStandardMaterial,
  PerspectiveCamera,
  PlaneGeometry,
  Points,
  PointsMaterial,
  Scene,
  SphereGeometry,
  Vector3,
  WebGLRenderer,
} from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { CSS2DObject, CSS2DRenderer } from 'three/examples/jsm/renderers/CSS2DRenderer.js';
import { toolMeshIndices } from '../core/toolMesh';
import type { SceneGeometry, TraceFrame } from '../worker/protocol';

export type CameraPreset = 'iso' | 'feed' | 'top';

const SECTION_POINTS = 96;
const LOOP_CAPACITY = 1024;
const RADIAL_SEGMENTS = 64;

/** The WebGL renderer's name says it rasterises in software (checked on a throwaway context). */
function isSoftwareWebGL(): boolean {
  const gl = document.createElement('canvas').getContext('webgl2');
  if (!gl) return false;
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  const name = String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
  gl.getExtension('WEBGL_lose_context')?.loseContext();
  return /swiftshader|llvmpipe|softpipe|software|basic render/i.test(name);
}

function lineOf(capacity: number, color: number, loop = false): Line {
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(new Float32Array(capacity * 3), 3));
  geometry.setDrawRange(0, 0);
  const material = new LineBasicMaterial({ color, depthTest: false });
  const line = loop ? new LineLoop(geometry, material) : new Line(geometry, material);
  line.renderOrder = 10;
  line.frustumCulled = false;
  return line;
}

function setLine(line: Line, points: ArrayLike<number>, count: number): void {
  const attr = line.geometry.getAttribute('position') as BufferAttribute;
  const arr = attr.array as Float32Array;
  const n = Math.min(count, arr.length / 3);
  for (let i = 0; i < n * 3; i++) arr[i] = points[i] as number;
  attr.needsUpdate = true;
  line.geometry.setDrawRange(0, n);
}

/** Points of a circle (flat xyz) around `centre` in the plane with unit normal `normal`. */
function circlePoints(centre: readonly number[], normal: readonly number[], radius: number): Float32Array {
  const n = new Vector3(normal[0], normal[1], normal[2]);
  const u = new Vector3(0, 0, 1).cross(n);
  if (u.lengthSq() < 1e-12) u.set(1, 0, 0);
  u.normalize();
  const v = new Vector3().crossVectors(n, u).normalize();
  const pts = new Float32Array(SECTION_POINTS * 3);
  for (let i = 0; i < SECTION_POINTS; i++) {
    const a = (2 * Math.PI * i) / SECTION_POINTS;
    const c = Math.cos(a) * radius;
    const s = Math.sin(a) * radius;
    pts[3 * i] = (centre[0] as number) + c * u.x + s * v.x;
    pts[3 * i + 1] = (centre[1] as number) + c * u.y + s * v.y;
    pts[3 * i + 2] = (centre[2] as number) + c * u.z + s * v.z;
  }
  return pts;
}

function label(text: string, className: string): CSS2DObject {
  const div = document.createElement('div');
  div.className = `scene-label ${className}`;
  div.textContent = text;
  return new CSS2DObject(div);
}

export class ToolScene {
  private readonly renderer: WebGLRenderer;
  private readonly labels: CSS2DRenderer;
  private readonly scene = new Scene();
  private readonly camera = new PerspectiveCamera(40, 1, 0.01, 1000);
  private readonly controls: OrbitControls;
  private readonly toolGeometry = new BufferGeometry();
  private readonly tool: Mesh;
  private readonly ghost: Mesh;
  private readonly designedPlane: Mesh;
  private readonly hPlane: Mesh;
  private readonly section = lineOf(SECTION_POINTS, 0xff7a00, true);
  private readonly loops = [lineOf(LOOP_CAPACITY, 0xd6336c, true), lineOf(LOOP_CAPACITY, 0xd6336c, true)];
  private readonly toolAxis = lineOf(2, 0x444444);
  private readonly dimension = lineOf(6, 0x111111);
  private readonly pBase: Mesh;
  private readonly pHp: Mesh;
  private readonly pBaseLabel = label('P_base', 'label-pbase');
  private readonly pHpLabel = label('P_hp', 'label-php');
  private readonly dimLabel = label('L/2', 'label-dim');
  private readonly axes = new Group();
  private readonly traceSection = lineOf(SECTION_POINTS, 0x7c3aed, true);
  private readonly candidates = new Points(
    (() => {
      const g = new BufferGeometry();
      g.setAttribute('position', new BufferAttribute(new Float32Array(64 * 3), 3));
      g.setDrawRange(0, 0);
      return g;
    })(),
    new PointsMaterial({ color: 0x7c3aed, size: 6, sizeAttenuation: false, depthTest: false }),
  );
  private readonly traceMarker: Mesh;
  private readonly traceLabel = label('', 'label-trace');
  private frameRequested = false;
  private sectionRadius = 1;
  private sizeMm = 0;
  /** Frames rendered so far (read by tests and the benchmark). */
  frames = 0;
  /** Called after each rendered frame. */
  onFrame: (() => void) | null = null;

  /** Whether WebGL runs on a software rasteriser (SwiftShader, llvmpipe): then no MSAA, pixel ratio 1. */
  readonly softwareRendering: boolean;

  constructor(private readonly container: HTMLElement) {
    // Multisampling and a high pixel ratio cost little on a GPU, but on a software rasteriser
    // they tripled the input-to-frame time (measured: about 50 ms against 6 ms on SwiftShader).
    this.softwareRendering = isSoftwareWebGL();
    this.renderer = new WebGLRenderer({ antialias: !this.softwareRendering });
    this.renderer.setPixelRatio(this.softwareRendering ? 1 : Math.min(2, window.devicePixelRatio || 1));
    this.renderer.setClearColor(new Color(0xf7f8fa));
    this.renderer.domElement.setAttribute('data-testid', 'scene-canvas');
    this.renderer.domElement.setAttribute(
      'aria-label',
      '3D view of the inclined tool, its section circle and the h pseudo plane',
    );
    this.renderer.domElement.setAttribute('role', 'img');
    container.appendChild(this.renderer.domElement);
    this.labels = new CSS2DRenderer();
    this.labels.domElement.className = 'scene-labels';
    container.appendChild(this.labels.domElement);

    this.camera.up.set(0, 0, 1);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.enableDamping = false;
    this.controls.addEventListener('change', () => this.requestRender());

    this.scene.add(new AmbientLight(0xffffff, 1.2));
    const sun = new DirectionalLight(0xffffff, 1.6);
    sun.position.set(3, -4, 6);
    this.scene.add(sun);

    this.toolGeometry.setAttribute('position', new BufferAttribute(new Float32Array(0), 3));
    this.toolGeometry.setIndex(new BufferAttribute(toolMeshIndices(RADIAL_SEGMENTS), 1));
    this.tool = new Mesh(
      this.toolGeometry,
      new MeshStandardMaterial({
        color: 0xb8c7d9,
        metalness: 0.3,
        roughness: 0.45,
        transparent: true,
        opacity: 0.22,
        side: DoubleSide,
        depthWrite: false,
      }),
    );
    this.ghost = new Mesh(
      this.toolGeometry,
      new MeshBasicMaterial({ color: 0x6c7a89, wireframe: true, transparent: true, opacity: 0.12 }),
    );
    this.designedPlane = new Mesh(
      new PlaneGeometry(1, 1),
      new MeshBasicMaterial({ color: 0xc9ced6, side: DoubleSide, transparent: true, opacity: 0.55, depthWrite: false }),
    );
    this.hPlane = new Mesh(
      new PlaneGeometry(1, 1),
      new MeshBasicMaterial({ color: 0x2f80ed, side: DoubleSide, transparent: true, opacity: 0.18, depthWrite: false }),
    );
    const dot = new SphereGeometry(1, 16, 12);
    this.pBase = new Mesh(dot, new MeshBasicMaterial({ color: 0x1b7f3b, depthTest: false }));
    this.pHp = new Mesh(dot, new MeshBasicMaterial({ color: 0xd6336c, depthTest: false }));
    this.pBase.renderOrder = this.pHp.renderOrder = 11;
    this.pBase.add(this.pBaseLabel);
    this.pHp.add(this.pHpLabel);
    this.scene.add(
      this.designedPlane,
      this.hPlane,
      this.tool,
      this.ghost,
      this.section,
      ...this.loops,
      this.toolAxis,
      this.dimension,
      this.pBase,
      this.pHp,
      this.axes,
    );
    this.dimension.add(this.dimLabel);
    this.traceMarker = new Mesh(dot, new MeshBasicMaterial({ color: 0x7c3aed, depthTest: false }));
    this.traceMarker.renderOrder = 12;
    this.traceMarker.add(this.traceLabel);
    this.candidates.frustumCulled = false;
    this.candidates.renderOrder = 12;
    this.scene.add(this.traceSection, this.candidates, this.traceMarker);
    this.showTraceFrame(null);

    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
  }

  /** Shows a solved state. Everything is updated in place. */
  update(g: SceneGeometry, dimensionText: string): void {
    const attr = this.toolGeometry.getAttribute('position') as BufferAttribute;
    if (attr.array.length !== g.toolPositions.length) {
      this.toolGeometry.setAttribute('position', new BufferAttribute(new Float32Array(g.toolPositions), 3));
    } else {
      (attr.array as Float32Array).set(g.toolPositions);
      attr.needsUpdate = true;
    }
    this.toolGeometry.computeVertexNormals();
    this.toolGeometry.computeBoundingSphere();
    this.ghost.position.set(0, 2 * g.halfIntervalMm, 0);

    const R = g.toolRadiusMm;
    const size = 2.4 * R + 2 * g.halfIntervalMm;
    this.designedPlane.scale.set(size, size, 1);
    this.designedPlane.position.set(0, g.halfIntervalMm, 0);
    this.hPlane.scale.set(size, size, 1);
    this.hPlane.position.set(0, g.halfIntervalMm, g.scallopHeightMm);

    // Section circle through P_hp: radius Rcr in the plane normal to the ring tangent.
    this.sectionRadius = g.sectionRadiusMm;
    const pts = circlePoints(g.sectionCentre, g.sectionNormal, g.sectionRadiusMm);
    setLine(this.section, pts, SECTION_POINTS);

    this.loops.forEach((line, i) => {
      const loop = g.intersectionLoops[i];
      setLine(line, loop ?? [], loop ? loop.length / 3 : 0);
    });

    const axisLen = 2.2 * R;
    setLine(
      this.toolAxis,
      [
        g.toolCentre[0] - 0.3 * R * g.toolAxis[0],
        0,
        g.toolCentre[2] - 0.3 * R * g.toolAxis[2],
        g.toolCentre[0] + axisLen * g.toolAxis[0],
        0,
        g.toolCentre[2] + axisLen * g.toolAxis[2],
      ],
      2,
    );

    // Dimension line for L/2 from the tool centre line (Y = 0) to P_hp, with end ticks.
    const [x, y, z] = g.pHp;
    const tick = 0.08 * R;
    setLine(this.dimension, [x, 0, z + tick, x, 0, z, x, y, z, x, y, z + tick, x, y, z, x, 0, z], 6);
    this.dimLabel.position.set(x, y / 2, z + 3 * tick);
    this.dimLabel.element.textContent = dimensionText;

    const dotR = 0.035 * R;
    this.pBase.scale.setScalar(dotR);
    this.pBase.position.set(...g.pBase);
    this.pHp.scale.setScalar(dotR);
    this.pHp.position.set(...g.pHp);

    if (Math.abs(R - this.sizeMm) > 1e-9) {
      this.rebuildAxes(R);
      const first = this.sizeMm === 0;
      this.sizeMm = R;
      if (first) this.setCamera('iso');
    }
    // New results are drawn at once rather than on the next animation frame: the browser
    // presents the frame at its next vsync either way, and this saves up to one frame of latency.
    this.renderNow();
  }

  /** Shows one frame of the paper's procedure (section, candidates, point), or hides the replay. */
  showTraceFrame(frame: TraceFrame | null): void {
    const on = frame !== null;
    if (!on && !this.traceSection.visible) return; // already hidden: nothing changed, no frame
    this.traceSection.visible = on;
    this.candidates.visible = on;
    this.traceMarker.visible = on && frame.point !== null;
    this.traceLabel.visible = this.traceMarker.visible;
    this.traceLabel.element.style.display = this.traceMarker.visible ? '' : 'none';
    if (frame) {
      setLine(
        this.traceSection,
        circlePoints(frame.sectionCentre, frame.sectionNormal, this.sectionRadius),
        SECTION_POINTS,
      );
      const attr = this.candidates.geometry.getAttribute('position') as BufferAttribute;
      const n = Math.min(frame.candidates.length / 3, attr.count);
      (attr.array as Float32Array).set(frame.candidates.slice(0, 3 * n));
      attr.needsUpdate = true;
      this.candidates.geometry.setDrawRange(0, n);
      if (frame.point) {
        this.traceMarker.position.set(...frame.point);
        this.traceMarker.scale.setScalar(0.03 * (this.sizeMm || 1));
        this.traceLabel.element.textContent =
          frame.phase === 'converged'
            ? 'P_hp (converged)'
            : frame.phase === 'search'
              ? 'best P_hp[i]'
              : 'single contact';
      }
    }
    this.requestRender();
  }

  /** Marks the view as showing the last valid state (or not). */
  setStale(stale: boolean): void {
    this.container.classList.toggle('stale', stale);
  }

  setCamera(preset: CameraPreset): void {
    const R = this.sizeMm || 3;
    const target = new Vector3(0, 0.45 * R, 0.25 * R);
    const d = 3.2 * R;
    if (preset === 'iso') this.camera.position.set(target.x + d * 0.75, target.y - d * 0.85, target.z + d * 0.6);
    else if (preset === 'feed') {
      // Looking back against the feed, so that Y runs to the right as in the profile view.
      target.z = 0.45 * R;
      this.camera.position.set(target.x + d * 1.3, target.y, target.z + 1e-3);
    } else this.camera.position.set(target.x, target.y, target.z + d * 1.3);
    this.camera.up.set(preset === 'top' ? 1 : 0, 0, preset === 'top' ? 0 : 1);
    this.controls.target.copy(target);
    this.controls.update();
    this.requestRender();
  }

  /** Renders on the next animation frame (several requests in one frame render once). */
  requestRender(): void {
    if (this.frameRequested) return;
    this.frameRequested = true;
    requestAnimationFrame(() => {
      if (this.frameRequested) this.renderNow();
    });
  }

  private renderNow(): void {
    this.frameRequested = false;
    this.renderer.render(this.scene, this.camera);
    this.labels.render(this.scene, this.camera);
    this.frames++;
    this.onFrame?.();
  }

  private rebuildAxes(R: number): void {
    for (const child of [...this.axes.children]) {
      this.axes.remove(child);
      (child as ArrowHelper).dispose();
    }
    const len = 1.6 * R;
    const specs: Array<[Vector3, number, string]> = [
      [new Vector3(1, 0, 0), 0xd62828, 'X (feed)'],
      [new Vector3(0, 1, 0), 0x2a9d8f, 'Y'],
      [new Vector3(0, 0, 1), 0x1d4ed8, 'Z'],
    ];
    for (const [dir, color, text] of specs) {
      const arrow = new ArrowHelper(dir, new Vector3(0, 0, 0), len, color, 0.12 * len, 0.06 * len);
      const tag = label(text, 'label-axis');
      tag.position.set(0, len * 1.08, 0); // ArrowHelper's local +Y is its direction
      arrow.add(tag);
      this.axes.add(arrow);
    }
  }

  private resize(): void {
    const w = Math.max(1, this.container.clientWidth);
    const h = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(w, h, false);
    this.labels.setSize(w, h);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.requestRender();
  }
}
