import { describe, expect, it } from 'vitest';
import { URL_PARAMS } from '../../src/core/input/fields';
import { convertState, defaultState, parseUrl, toSearch, withField } from '../../src/ui/state';

describe('URL state and units', () => {
  it('round-trips a state through the query string', () => {
    const parsed = parseUrl('?R=6&Rcr=2&rho=10&h=0.1&unit=mm');
    expect(parsed.notices).toEqual([]);
    expect(parsed.state.fields).toMatchObject({ R: '6', Rcr: '2', rho: '10', h: '0.1' });
    expect(parseUrl(toSearch(parsed.state)).state).toEqual(parsed.state);
  });

  it('records inverse mode with L, and embed', () => {
    const p = parseUrl('?R=3&Rcr=1&rho=5&L=2.5&mode=inverse&unit=in&embed=1');
    expect(p.state.mode).toBe('inverse');
    expect(p.state.unit).toBe('in');
    expect(p.embed).toBe(true);
    expect(toSearch(p.state)).toBe('?R=3&Rcr=1&rho=5&mode=inverse&L=2.5&unit=in');
  });

  it('invalid or missing values fall back to defaults with a notice each; no parameters, no notice', () => {
    const p = parseUrl('?R=abc&Rcr=1&rho=5&unit=furlong');
    expect(p.state.fields.R).toBe('3');
    expect(p.notices.join(' ')).toMatch(/unit="furlong"/);
    expect(p.notices.join(' ')).toMatch(/R="abc"/);
    expect(p.notices.join(' ')).toMatch(/h is missing/);
    expect(parseUrl('').notices).toEqual([]);
    expect(parseUrl('?R=1e999').notices.join(' ')).toMatch(/not a number/);
  });

  it('a key given twice (unit=mm ... unit=inch, a second h=): the first is read and a notice names the value ignored', () => {
    const p = parseUrl('?unit=mm&R=3&Rcr=1&rho=5&h=0.05&unit=inch&h=0.07');
    expect(p.state.unit).toBe('mm');
    expect(p.state.fields.h).toBe('0.05');
    expect(p.notices).toEqual([
      'unit is in the link 2 times; using the first, unit="mm" (unit="inch" ignored).',
      'h is in the link 2 times; using the first, h="0.05" (h="0.07" ignored).',
    ]);
    // The same question without the repeats reads the same state, with nothing to say.
    const plain = parseUrl('?unit=mm&R=3&Rcr=1&rho=5&h=0.05');
    expect(plain.notices).toEqual([]);
    expect(p.state).toEqual(plain.state);
    // A repeated value equal to the first is still a repeat (the link says two things).
    expect(parseUrl('?R=3&Rcr=1&rho=5&h=0.05&rho=5').notices).toEqual([
      'rho is in the link 2 times; using the first, rho="5" (rho="5" ignored).',
    ]);
  });

  it('every parameter the page reads is reported when repeated; thousands of repeats make one short notice', () => {
    for (const name of URL_PARAMS) {
      const notices = parseUrl(`?${name}=first&${name}=second`).notices;
      expect(notices, name).toContain(
        `${name} is in the link 2 times; using the first, ${name}="first" (${name}="second" ignored).`,
      );
      expect(
        notices.filter((n) => n.includes('in the link 2 times')),
        name,
      ).toHaveLength(1);
    }
    const flood = parseUrl(`?R=3&Rcr=1&rho=5${'&h=0.0123456789012345678901234'.repeat(5000)}`).notices;
    expect(flood).toEqual([
      'h is in the link 5000 times; using the first, h="0.012345678901234567" ' +
        '(h="0.012345678901234567", h="0.012345678901234567", h="0.012345678901234567" and 4996 more ignored).',
    ]);
    // Keys the page does not read are not its business.
    expect(parseUrl('?R=3&Rcr=1&rho=5&h=0.05&utm=a&utm=b').notices).toEqual([]);
  });

  it('converts between mm and inch, keeps angles and invalid text as they are', () => {
    const inch = convertState(withField(withField(defaultState(), 'h', 'x'), 'R', '3'), 'in');
    expect(inch.fields.R).toBe('0.1181102362205');
    expect(inch.fields.rho).toBe('5');
    expect(inch.fields.h).toBe('x');
    expect(convertState(inch, 'mm').fields.R).toBe('3');
  });
});

describe('URL state of the posture', () => {
  it('tilt and pattern round-trip; their defaults (0, one-way) stay out of the URL', () => {
    const p = parseUrl('?R=3&Rcr=1&rho=5&tilt=-12.5&pattern=zigzag&h=0.05&unit=mm');
    expect(p.notices).toEqual([]);
    expect(p.state.fields.tilt).toBe('-12.5');
    expect(p.state.pattern).toBe('zigzag');
    expect(toSearch(p.state)).toBe('?R=3&Rcr=1&rho=5&tilt=-12.5&pattern=zigzag&h=0.05&unit=mm');
    expect(parseUrl(toSearch(p.state)).state).toEqual(p.state);
    const plain = parseUrl('?R=3&Rcr=1&rho=5&h=0.05&unit=mm');
    expect(plain.state.fields.tilt).toBe('0');
    expect(plain.state.pattern).toBe('one-way');
    expect(toSearch(plain.state)).toBe('?R=3&Rcr=1&rho=5&h=0.05&unit=mm');
  });

  it('a bad tilt or pattern falls back with a notice; tilt is never "missing"', () => {
    const p = parseUrl('?R=3&Rcr=1&rho=5&tilt=x&pattern=spiral&h=0.05');
    expect(p.state.fields.tilt).toBe('0');
    expect(p.state.pattern).toBe('one-way');
    expect(p.notices.join(' ')).toMatch(/tilt="x".*not a number/);
    expect(p.notices.join(' ')).toMatch(/pattern="spiral" is not one-way or zigzag/);
    expect(parseUrl('?R=3&Rcr=1&rho=5&h=0.05').notices).toEqual([]);
  });

  it('angles are not converted by a unit switch', () => {
    const inch = convertState(parseUrl('?R=3&Rcr=1&rho=5&tilt=7&h=0.05').state, 'in');
    expect(inch.fields.tilt).toBe('7');
    expect(inch.fields.h).toBe('0.002'); // the default h, as the inch page's own default
  });
});

describe('URL state of the teeth and the feed (optional fields)', () => {
  it('an empty one is not given and says nothing; a bad one is left empty, said so (no "default" that is not there)', () => {
    const parsed = parseUrl('?R=3&Rcr=1&rho=5&h=0.05&unit=mm&z=&fz=abc');
    expect(parsed.notices).toEqual(['fz="abc" in the link is not a number; left empty.']);
    expect(parsed.state.fields.z).toBe('');
    expect(parsed.state.fields.fz).toBe('');
    const good = parseUrl('?R=3&Rcr=1&rho=5&h=0.05&unit=mm&z=4&fz=0.1');
    expect(good.notices).toEqual([]);
    expect([good.state.fields.z, good.state.fields.fz]).toEqual(['4', '0.1']);
  });

  it("the teeth alone, or their target Sa alone (the README's target=sa&sa=0.0008&z=2), leave the tool at its defaults silently", () => {
    expect(parseUrl('?z=2&fz=0.1').notices).toEqual([]);
    const sa = parseUrl('?target=sa&sa=0.0008&z=2');
    expect(sa.notices).toEqual([]);
    expect([sa.state.target, sa.state.fields.sa, sa.state.fields.z]).toEqual(['sa', '0.0008', '2']);
    expect(sa.state.fields.Rcr).toBe(defaultState('mm').fields.Rcr);
    // With a number of the tool given, the target Sa it needs is missing, said so, as h or Ra would be.
    expect(parseUrl('?R=3&Rcr=1&rho=5&target=sa&z=2').notices).toEqual([
      `sa is missing from the link; using the default ${defaultState('mm').fields.sa}.`,
    ]);
  });
});
