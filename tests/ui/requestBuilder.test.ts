/**
 * The page's one builder (issue 27 points 3 and 4): app.ts builds every request through
 * questionRequest.ts's buildPageRequest and no other builder, which picks each product mode's
 * builder by the mode registry's kind (one line per mode); request.ts's buildRequest is that same
 * function with the three-axis builder handed in statically, which the page hands in once it has
 * loaded it (not part of the first result: app.ts loadThreeAxis). The page's own counting of builds
 * per key press is the browser test tests/e2e/onePass.test.ts; the three-axis builder's load on
 * first use is tests/e2e/threeAxisLazy.test.ts's.
 */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { productModeKinds } from '../../src/core/surfaces/modes';
import { pageModeKind } from '../../src/ui/questionRequest';
import { buildRequest } from '../../src/ui/request';
import { parseUrl } from '../../src/ui/state';

const source = (file: string) => readFileSync(new URL(`../../src/ui/${file}`, import.meta.url), 'utf8');

describe('the page builds its request through questionRequest.ts', () => {
  it('app.ts imports buildPageRequest and calls no other builder; request.ts re-exports it', () => {
    const app = source('app.ts');
    expect(app).toMatch(/import \{ buildPageRequest, pageModeKind \} from '\.\/questionRequest';/);
    expect(app.match(/buildPageRequest\(/g)).toHaveLength(1);
    for (const other of ['buildRequest', 'buildFiveAxisRequest', 'buildThreeAxisRequest(', 'buildCurvedRequest'])
      expect(app, other).not.toContain(other);
    // The three-axis builder only by the dynamic import (no static import of it: the first result's).
    expect(app).not.toMatch(/from '\.\/threeAxisRequest'/);
    expect(app).toMatch(/import\('\.\/threeAxisRequest'\)/);
  });

  it('each product mode of the registry has its builder, and the machine switch picks it', () => {
    const links: Record<string, string> = {
      fiveAxis: '?R=3&Rcr=1&rho=5&h=0.05&unit=mm',
      threeAxis: '?R=3&Rcr=1&machine=3axis&slope=30&h=0.05&unit=mm',
    };
    expect(Object.keys(links).sort()).toEqual([...productModeKinds()].sort());
    const modes: Record<string, string> = {};
    for (const [kind, link] of Object.entries(links)) {
      const state = parseUrl(link).state;
      expect(pageModeKind(state)).toBe(kind);
      const built = buildRequest(state);
      if (!built.ok) throw new Error(JSON.stringify(built.errors));
      modes[kind] = built.request.mode;
    }
    expect(modes).toEqual({ fiveAxis: 'forward', threeAxis: 'three-axis' });
    const curved = buildRequest(
      parseUrl('?R=3&Rcr=1&rho=5&surface=curved&feedRadius=50&crossRadius=-80&h=0.01&unit=mm').state,
    );
    expect(curved.ok && curved.request.mode).toBe('curved-forward');
  });
});
