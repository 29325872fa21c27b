/**
 * What the scene's drawables share (render/drawables/parts.ts), in Node: a Disposer frees, with
 * itself, every geometry and material its objects and their descendants hold, each once (a
 * geometry two meshes share, as the marked points share their dot and a line its halo, freed once).
 */
import { BufferGeometry, Mesh, MeshBasicMaterial, type Object3D } from 'three';
import { describe, expect, it } from 'vitest';
import { Disposer, lineOf } from '../../../src/render/drawables/parts';

describe('Disposer', () => {
  it('frees each geometry and material of its objects and their descendants once', () => {
    const dot = new BufferGeometry();
    const outer = new MeshBasicMaterial();
    const inner = new MeshBasicMaterial();
    const mesh = new Mesh(dot, outer);
    mesh.add(new Mesh(dot, inner));
    const line = lineOf(4, 0x111111);
    const freed: object[] = [];
    for (const g of [dot, line.geometry]) g.addEventListener('dispose', () => freed.push(g));
    for (const m of [outer, inner]) m.addEventListener('dispose', () => freed.push(m));
    class Owner extends Disposer {
      readonly objects: readonly Object3D[] = [mesh, line];
    }
    new Owner().dispose();
    expect(freed).toHaveLength(4);
    expect(new Set(freed).size).toBe(4);
  });
});
