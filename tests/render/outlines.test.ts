/** The outlines of the neighbouring passes' tools and of the two surfaces (index pairs over shared vertices). */
import { describe, expect, it } from 'vitest';
import { TOOL_PROFILE_POINTS } from '../../src/core/tool/toolMesh';
import { patchLineIndices, toolOutlineIndices } from '../../src/render/outlineIndices';

describe('toolOutlineIndices', () => {
  it('three rings (the end, the top of the corner, the shank top) and four lines up the side, within the mesh', () => {
    const segments = 64;
    const idx = toolOutlineIndices(segments);
    expect(idx.length).toBe(2 * (3 * segments + 4 * (TOOL_PROFILE_POINTS - 2)));
    const vertices = TOOL_PROFILE_POINTS * (segments + 1);
    expect(Math.max(...idx)).toBeLessThan(vertices);
    // No segment through the bottom centre (row 0): the outline would cross the end face.
    expect(Math.min(...idx)).toBeGreaterThanOrEqual(segments + 1);
  });
});

describe('patchLineIndices', () => {
  it("the edge only, or the edge and a grid: the h pseudo surface's pattern has more lines", () => {
    const edge = patchLineIndices(0);
    expect(edge.length).toBe(2 * (2 * 64 + 2 * 48));
    const grid = patchLineIndices(8);
    expect(grid.length).toBe(2 * (7 * 64 + 9 * 48));
    expect(Math.max(...grid)).toBe(49 * 65 - 1);
  });
});
