/** The URL follows the state once the inputs settle (src/ui/urlState.ts), with fake timers and a stand-in history. */
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { parseUrl, withField } from '../../src/ui/state';
import { URL_SETTLE_MS, UrlState } from '../../src/ui/urlState';

describe('UrlState', () => {
  let writes: string[];
  let visibility: () => void;
  let hidden = false;
  beforeEach(() => {
    vi.useFakeTimers();
    writes = [];
    hidden = false;
    vi.stubGlobal('window', {
      history: { replaceState: (_s: unknown, _t: string, url: string) => writes.push(url) },
      location: { hash: '' },
    });
    vi.stubGlobal('document', {
      addEventListener: (type: string, listener: () => void) => {
        if (type === 'visibilitychange') visibility = listener;
      },
      get visibilityState() {
        return hidden ? 'hidden' : 'visible';
      },
    });
  });
  afterEach(() => {
    vi.useRealTimers();
    vi.unstubAllGlobals();
  });

  const base = parseUrl('?R=3&Rcr=1&rho=5&h=0.05&unit=mm').state;
  const withH = (h: string) => withField(base, 'h', h);

  it('writes nothing while changes come faster than the settle time, then the last state once', () => {
    const link = { href: '' } as HTMLAnchorElement;
    const url = new UrlState({ embed: '1' }, link);
    for (let i = 1; i <= 50; i++) {
      url.write(withH(`0.0${i}`));
      // The embedded page's link to the full calculator follows at once (no embed in it).
      expect(link.href).toContain(`h=0.0${i}`);
      expect(link.href).not.toContain('embed');
      vi.advanceTimersByTime(URL_SETTLE_MS - 1);
    }
    expect(writes).toEqual([]);
    vi.advanceTimersByTime(1);
    expect(writes).toHaveLength(1);
    expect(writes[0]).toContain('h=0.050');
    expect(writes[0]).toContain('embed=1');
    vi.advanceTimersByTime(10 * URL_SETTLE_MS);
    expect(writes).toHaveLength(1);
  });

  it('a page being hidden writes the waiting state at once', () => {
    const url = new UrlState({}, null);
    url.write(withH('0.07'));
    hidden = true;
    visibility();
    expect(writes).toHaveLength(1);
    expect(writes[0]).toContain('h=0.07');
    vi.advanceTimersByTime(URL_SETTLE_MS);
    expect(writes).toHaveLength(1);
  });

  it('a page setting (present=1) is written at once with the latest state, and removed again', () => {
    const url = new UrlState({ view: 'chart' }, null);
    url.setExtra('present', '1');
    expect(writes).toEqual([]); // no state yet: nothing to write
    url.write(withH('0.07'));
    vi.advanceTimersByTime(URL_SETTLE_MS);
    expect(new URLSearchParams(writes[0]).get('present')).toBe('1');
    url.setExtra('present', null);
    expect(writes).toHaveLength(2);
    const params = new URLSearchParams(writes[1]);
    expect(params.has('present')).toBe(false);
    expect(params.get('view')).toBe('chart');
    expect(params.get('h')).toBe('0.07');
    // A state waiting to be written goes with the setting, once.
    url.write(withH('0.08'));
    url.setExtra('present', '1');
    expect(new URLSearchParams(writes[2]).get('h')).toBe('0.08');
    vi.advanceTimersByTime(URL_SETTLE_MS);
    expect(writes).toHaveLength(3);
  });
});
