import { describe, expect, it } from 'vitest';
import { parseArgs } from '../../src/cli/args';

const usage = (args: string[]) => {
  const r = parseArgs(args);
  if (r.kind !== 'usage') throw new Error(`expected a usage error for ${args.join(' ')}, got ${r.kind}`);
  return r.error;
};

describe('command-line arguments', () => {
  it('reads --name value and --name=value; a value is kept as typed (validation words it)', () => {
    expect(
      parseArgs(['--R', '3', '--Rcr=1', '--rho', '-5', '--tilt', ' 2 ', '--pattern=zigzag', '--h', '0.05']),
    ).toEqual({
      kind: 'forward',
      json: false,
      values: { R: '3', Rcr: '1', rho: '-5', tilt: ' 2 ', pattern: 'zigzag', h: '0.05' },
    });
    expect(parseArgs(['--R=', '--json'])).toEqual({ kind: 'forward', json: true, values: { R: '' } });
  });

  it('the inverse: --interval or --half-interval (with or without --inverse)', () => {
    expect(parseArgs(['--interval', '2'])).toMatchObject({ kind: 'inverse', half: false, values: { interval: '2' } });
    expect(parseArgs(['--inverse', '--half-interval', '1'])).toMatchObject({ kind: 'inverse', half: true });
    expect(parseArgs(['--inverse', '--R', '3'])).toMatchObject({ kind: 'inverse', half: false });
  });

  it('-h and --help win over everything else, even a usage error', () => {
    for (const args of [['-h'], ['--help'], ['--R', '3', '-h'], ['--bogus', '--help'], ['--batch', '--json', '-h']]) {
      expect(parseArgs(args)).toEqual({ kind: 'help' });
    }
    // A value that looks like -h is a value.
    expect(parseArgs(['--tilt', '-h'])).toMatchObject({ kind: 'forward', values: { tilt: '-h' } });
  });

  it('a repeated option is a usage error naming it', () => {
    expect(usage(['--R', '3', '--R', '4'])).toBe('--R is given more than once');
    expect(usage(['--R=3', '--R', '3'])).toBe('--R is given more than once');
    expect(usage(['--json', '--json'])).toBe('--json is given more than once');
    expect(usage(['--batch', '--batch'])).toBe('--batch is given more than once');
    expect(usage(['--tilt', '0', '--tilt', '0'])).toBe('--tilt is given more than once');
  });

  it('contradictory combinations are usage errors naming them', () => {
    expect(usage(['--batch', '--json'])).toMatch(/^--json does not go with --batch/);
    expect(usage(['--json', '--batch'])).toMatch(/^--json does not go with --batch/);
    expect(usage(['--batch', '--R', '3'])).toMatch(/^--R does not go with --batch/);
    expect(usage(['--batch', '--inverse'])).toMatch(/^--inverse does not go with --batch/);
    expect(usage(['--h', '1', '--interval', '2'])).toMatch(/--h and --interval do not go together/);
    expect(usage(['--half-interval', '1', '--h', '2'])).toMatch(/--h and --half-interval do not go together/);
    expect(usage(['--interval', '1', '--half-interval', '2'])).toMatch(/give the step-over once/);
    expect(usage(['--inverse', '--h', '2'])).toMatch(/--inverse computes h/);
  });

  it('unknown options, stray arguments, missing values and values given to flags', () => {
    expect(usage(['--bogus', '1'])).toBe('unknown option --bogus');
    expect(usage(['3'])).toBe('unexpected argument "3"');
    expect(usage(['-R', '3'])).toBe('unexpected argument "-R"');
    expect(usage(['--'])).toBe('unexpected argument "--"');
    expect(usage(['--R'])).toBe('--R needs a value');
    expect(usage(['--R', '--Rcr', '1'])).toBe('--R needs a value');
    expect(usage(['--json=yes'])).toBe('--json takes no value');
  });
});
