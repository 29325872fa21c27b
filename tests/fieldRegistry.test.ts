/**
 * The field registry (src/core/input/fields.ts) is the one place each input's names live: every
 * channel takes every registry field under the registry's name, and no channel takes a name the
 * registry does not have. Driven through each channel's own entry point (the command line's main,
 * the batch's header and rows, the page's URL and fields, the worker's revalidation, the embed
 * element's generated attribute list), so a name changed in one place only fails here.
 */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { attributesBlock, EMBED_SCRIPT, embedAttributesDrift, withAttributes } from '../src/build/embedAttributes';
import { FLAG_OPTIONS, SETTING_OPTIONS, VALUE_OPTIONS } from '../src/cli/args';
import { batchRow, HEADER_RULE, outputHeader, parseHeader, RESULT_COLUMNS } from '../src/cli/batch';
import { parseCsv } from '../src/cli/csv';
import { USAGE } from '../src/cli/main';
import {
  CLI_OPTIONS,
  CSV_OPTIONAL_COLUMNS,
  CSV_REQUIRED_COLUMNS,
  CSV_TARGET_COLUMNS,
  cliFlag,
  EMBED_ATTRIBUTES,
  FIELD_LABELS,
  FIELD_NAMES,
  FIELDS,
  type FieldId,
  type FieldName,
  type FieldSpec,
  fieldOfPageKey,
  isLengthField,
  PAGE_FIELD_KEYS,
  PASS_FIELDS,
  pageKeyOf,
  URL_PARAMS,
} from '../src/core/input/fields';
import { rawOf } from '../src/core/input/raw';
import {
  describeInputError,
  forwardInput,
  inputError,
  inverseInput,
  MAX_SURFACE_RADIUS_MM,
  MAX_TOOL_RADIUS_MM,
  MIN_LENGTH_MM,
  MIN_SURFACE_RADIUS_MM,
  MIN_TOOL_RADIUS_MM,
} from '../src/core/input/validate';
import { LOOKUP_HEADER } from '../src/core/output/lookupTable';
import { validateRaTarget } from '../src/core/roughness/raTarget';
import { targetRzPair, validateTargetSa } from '../src/core/roughness/targetSa';
import { validateForward, validateInverse } from '../src/core/surfaces/validate';
import { FINISH_KEYS } from '../src/ui/finishFields';
import { buildRequest, stateMessages } from '../src/ui/request';
import {
  defaultState,
  FIELD_KEYS,
  isLengthField as isPageLength,
  parseUrl,
  toSearch,
  withField,
} from '../src/ui/state';
import { revalidate } from '../src/worker/jobs/revalidate';
import { sameRequest } from '../src/worker/protocol';
import { runMain } from './cli/helpers';

const ENTRIES = Object.entries(FIELDS) as Array<[FieldId, FieldSpec]>;
/** Every field the page's URL takes (the three-axis ones and the doubly curved point's radii too). */
const withUrl = ENTRIES.filter(([, f]) => f.url !== null);

/**
 * The rest of a link that makes a field count: the inverse mode for L, the target for Ra, the
 * three-axis machine for its fields (inverse for the programmed steps, waterline passes for dz).
 */
function urlContext(id: string): string {
  if (id === 'interval') return '&mode=inverse';
  if (id === 'ra') return '&target=ra';
  if (id === 'targetSa') return '&target=sa';
  if (id === 'slope' || id === 'rasterAngle' || id === 'passes') return '&machine=3axis';
  if (id === 'horizontalStep') return '&machine=3axis&mode=inverse';
  if (id === 'stepDown') return '&machine=3axis&mode=inverse&passes=waterline';
  return '';
}
const withCli = ENTRIES.filter(([, f]) => f.cli !== null);

describe('the registry itself', () => {
  it("gives the three-axis fields the issue's names (URL and embed element)", () => {
    const three = ENTRIES.filter(([, f]) => f.group === 'threeAxis');
    expect(three.map(([, f]) => f.url)).toEqual([
      'slope',
      'passes',
      'rasterAngle',
      'feedRadius',
      'crossRadius',
      'Lxy',
      'dz',
    ]);
    expect(three.map(([, f]) => f.cli)).toEqual([
      'slope',
      'passes',
      'raster-angle',
      'feed-radius',
      'cross-radius',
      'horizontal-step',
      'step-down',
    ]);
    for (const [, f] of three) expect(EMBED_ATTRIBUTES).toContainEqual([f.embed, f.url]);
  });

  it('names each field once per channel: no URL parameter, flag, column, attribute or page field is shared', () => {
    for (const channel of ['url', 'cli', 'embed', 'page'] as const) {
      const names = ENTRIES.map(([, f]) => f[channel]).filter((n) => n !== null);
      expect(new Set(names).size, channel).toBe(names.length);
    }
    const columns = ENTRIES.flatMap(([, f]) => (f.csv === null ? [] : [f.csv.column]));
    expect(new Set(columns).size).toBe(columns.length);
  });

  it("validation's labels and length rule are the registry's", () => {
    for (const name of FIELD_NAMES) {
      expect(FIELD_LABELS[name]).toBe(FIELDS[name].label);
      // A limit of 25.4 mm reads 1 in for a length; an angle's limit stays in degrees.
      const text = describeInputError(inputError(name, 'too-large', 'x', 25.4), 'in');
      expect(text.startsWith(FIELDS[name].label), text).toBe(true);
      expect(text).toContain(isLengthField(name) ? 'at most 1 in' : 'at most 25.4 degrees');
    }
    expect(describeInputError(inputError('interval', 'missing', ''), 'mm', { intervalAsHalf: true })).toMatch(
      new RegExp(`^${FIELDS.halfInterval.label.replace('/', '\\/')} is missing`),
    );
    expect(describeInputError(inputError('R', 'missing', ''), 'mm', { toolSizeAsDiameter: true })).toMatch(
      new RegExp(`^${FIELDS.D.label} is missing`),
    );
  });

  it("the fixed bounds are validation's, and validation holds them", () => {
    expect([FIELDS.R.range.min, FIELDS.R.range.max]).toEqual([MIN_TOOL_RADIUS_MM, MAX_TOOL_RADIUS_MM]);
    expect([FIELDS.surfaceRadius.range.min, FIELDS.surfaceRadius.range.max]).toEqual([
      MIN_SURFACE_RADIUS_MM,
      MAX_SURFACE_RADIUS_MM,
    ]);
    expect(FIELDS.h.range.min).toBe(MIN_LENGTH_MM);
    expect(FIELDS.ra.range.min).toBe(MIN_LENGTH_MM);
    expect(FIELDS.interval.range.min).toBe(2 * MIN_LENGTH_MM);
    // The angles' bounds: accepted at an included bound, refused at an excluded one and beyond.
    const ok = (rho: number, tilt: number) => validateForward({ R: 3, Rcr: 3, rho, tilt, h: 1e-6 }).ok;
    for (const id of ['rho', 'tilt'] as const) {
      const { min, max, minIncluded, maxIncluded } = FIELDS[id].range;
      const at = (v: number) => (id === 'rho' ? ok(v, 0) : ok(0, v));
      expect(at(min), `${id} at ${min}`).toBe(minIncluded);
      expect(at(max), `${id} at ${max}`).toBe(maxIncluded);
      expect(at(min - 1e-9)).toBe(false);
      expect(at(max + 1e-9)).toBe(false);
      expect(at((min + max) / 2)).toBe(true);
    }
  });
});

/** A valid command line, and the option whose value `bad` replaces for field `id`. */
function cliCase(id: FieldId, bad: string): string[] {
  const threeAxis = FIELDS[id].group === 'threeAxis';
  // A three-axis case: the slope in place of the lead; waterline for its own fields.
  const base = ['--R', '3', '--Rcr', '1', ...(threeAxis ? ['--slope', '30'] : ['--rho', '5'])];
  if (id === 'feedRadius' || id === 'crossRadius' || id === 'stepDown') base.push('--passes', 'waterline');
  const given = ['--h', '0.05'];
  if (id === 'interval' || id === 'halfInterval' || id === 'ra' || id === 'horizontalStep' || id === 'stepDown')
    given.length = 0;
  // A target finish (--target-sa, --target-rz) is the quantity, with the teeth.
  if (id === 'targetSa' || id === 'targetRz') {
    given.length = 0;
    base.push('--flutes', '2');
  }
  if (id === 'surfaceAxis') base.push('--surface-radius', '50');
  // The finish's fields come with the teeth and their feed (each needs the other).
  // The feed rate and spindle speed give fz in its place (one way only).
  if (id === 'feedRate' || id === 'spindleSpeed') base.push('--flutes', '2', '--feed-rate', '500', '--rpm', '5000');
  else if (FIELDS[id].group === 'finish') base.push('--flutes', '2', '--fz', '0.1');
  // The diameter stands in place of the radius.
  if (id === 'D') base.splice(0, 2);
  const args = [...base, ...given];
  const flag = cliFlag(id);
  const at = args.indexOf(flag);
  if (at >= 0) args[at + 1] = bad;
  else args.push(flag, bad);
  return args;
}

describe('the command line takes every registry field under its flag', () => {
  it('each flag feeds its own field: a bad value is named by the flag and the field label', async () => {
    expect([...withCli.map(([, f]) => f.cli), ...SETTING_OPTIONS]).toEqual([...VALUE_OPTIONS]);
    for (const [id, f] of withCli) {
      const bad = f.kind === 'enum' ? 'nope' : 'abc';
      const r = await runMain(cliCase(id, bad));
      expect(r.code, `${id}: ${r.stderr}`).toBe(2);
      expect(r.stderr, id).toContain(`${cliFlag(id)}: ${f.label}`);
    }
  });

  it('the help names every flag, and every flag it names is one', () => {
    const named = new Set([...USAGE.matchAll(/--([a-z][a-zA-Z0-9-]*)/g)].map((m) => m[1]));
    const known = new Set<string>([...CLI_OPTIONS, ...FLAG_OPTIONS, ...SETTING_OPTIONS]);
    expect([...named].filter((n) => n !== undefined && !known.has(n))).toEqual([]);
    for (const option of CLI_OPTIONS) expect(USAGE, option).toContain(`--${option} <`);
  });

  it('the command line sources name no flag the registry or the flag list does not have', () => {
    // `--name` is the parser's own placeholder (`--name value`, `--name=value`).
    const known = new Set<string>([...CLI_OPTIONS, ...FLAG_OPTIONS, ...SETTING_OPTIONS, 'name']);
    for (const file of [
      'args.ts',
      'main.ts',
      'report.ts',
      'reportExtras.ts',
      'reportJson.ts',
      'batch.ts',
      'batchHeader.ts',
    ]) {
      const source = readFileSync(new URL(`../src/cli/${file}`, import.meta.url), 'utf8');
      const named = [...source.matchAll(/--([a-z][a-zA-Z0-9-]*)/g)].map((m) => m[1] as string);
      expect(
        named.filter((n) => !known.has(n)),
        file,
      ).toEqual([]);
    }
  });
});

describe('the batch takes every registry column', () => {
  const header = [...CSV_REQUIRED_COLUMNS, ...CSV_TARGET_COLUMNS, ...CSV_OPTIONAL_COLUMNS];

  it('its header rule names each column, and its echo keeps the registry order', () => {
    for (const column of header) expect(HEADER_RULE).toMatch(new RegExp(`\\b${column}\\b`));
    const [record] = parseCsv(
      [...header]
        .reverse()
        .filter((c) => c !== 'Ra' && c !== 'L')
        .join(','),
    );
    const h = record && parseHeader(record);
    if (!h?.ok) throw new Error('header');
    expect(outputHeader(h.layout)).toBe(
      `${header.filter((c) => c !== 'Ra' && c !== 'L').join(',')},${RESULT_COLUMNS.join(',')}\n`,
    );
    // The page's lookup table writes the batch's header.
    expect(LOOKUP_HEADER).toBe(outputHeader(h.layout).trim());
  });

  it('each column feeds its own field: a bad value in it is named by the field label', () => {
    for (const target of CSV_TARGET_COLUMNS) {
      const columns = header.filter((c) => !CSV_TARGET_COLUMNS.includes(c) || c === target);
      const good: Record<string, string> = {
        R: '3',
        Rcr: '1',
        rho: '5',
        h: '0.05',
        Ra: '0.01',
        L: '1',
        tilt: '0',
        pattern: 'one-way',
        surfaceRadius: '50',
        surfaceAxis: 'feed',
      };
      const [record] = parseCsv(columns.join(','));
      const h = record && parseHeader(record);
      if (!h?.ok) throw new Error('header');
      const layout = h.layout;
      const fields = (line: string) => {
        const [row] = parseCsv(line);
        if (row === undefined) throw new Error('no record');
        return parseCsv(batchRow(row, layout))[0]?.fields ?? [];
      };
      expect(fields(columns.map((c) => good[c]).join(',')).at(-1), 'valid row').toBe('');
      for (const column of columns) {
        const field = ENTRIES.find(([, f]) => f.csv?.column === column)?.[1];
        const bad = field?.kind === 'enum' ? 'nope' : 'abc';
        const error = fields(columns.map((c) => (c === column ? bad : good[c])).join(',')).at(-1) ?? '';
        expect(error.startsWith(field?.label ?? '?'), `${column}: ${error}`).toBe(true);
      }
    }
  });
});

describe("the page's URL takes every registry field under its parameter", () => {
  it('a number of each field is read into its field and written back under the same parameter', () => {
    for (const [id, f] of withUrl) {
      // A name (the tool's) is text: tests/ui/toolName.test.ts.
      if (f.kind === 'enum' || f.kind === 'text') continue;
      const mode = urlContext(id);
      const parsed = parseUrl(`?${f.url}=7${mode}&unit=mm`);
      const key = id === 'D' ? 'R' : id === 'surfaceRadius' ? 'Rs' : pageKeyOf(id);
      expect(key, id).not.toBeNull();
      expect(parsed.state.fields[key as 'R'], id).toBe('7');
      expect(new URLSearchParams(toSearch(parsed.state)).get(f.url as string), id).toBe('7');
      // Text that is not a number is named in a notice by the same parameter.
      const bad = parseUrl(`?${f.url}=zzz${mode}`).notices.join(' ');
      expect(bad, id).toContain(`${f.url}="zzz" in the link is not a number`);
    }
  });

  it('every word of each switch is taken (and written back), another word gets a notice naming the parameter', () => {
    for (const [id, f] of withUrl) {
      if (f.kind !== 'enum') continue;
      for (const value of f.values ?? []) {
        const search = `?${f.url}=${value}${id === 'surfaceAxis' ? '&surfaceRadius=40' : urlContext(id)}`;
        const parsed = parseUrl(search);
        expect(parsed.notices, `${id}=${value}`).toEqual([]);
        if (id === 'view') expect(parsed.view).toBe(value);
        else if (id === 'present') expect(parsed.present).toBe(value);
        else if (id === 'embed') expect(parsed.embed).toBe(true);
        else if (id === 'theme' || id === 'lang')
          continue; // read by the theme (tests/ui/pageNames.test.ts) and the language (tests/ui/i18n/language.test.ts)
        else if (value !== f.values?.[0] || id === 'surfaceAxis' || id === 'unit')
          expect(new URLSearchParams(toSearch(parsed.state)).get(f.url as string), `${id}=${value}`).toBe(value);
      }
      // view, present: the page says so (app.ts, present.ts); embed: anything else is not embedded; theme:
      // tests/ui/pageNames.test.ts; lang: tests/ui/i18n/language.test.ts.
      if (id === 'view' || id === 'present' || id === 'embed' || id === 'theme' || id === 'lang') continue;
      expect(parseUrl(`?${f.url}=zzz`).notices.join(' '), id).toContain(`${f.url}="zzz" is not`);
    }
  });

  it("the page's sources read and write no URL parameter the registry does not have", () => {
    const known = new Set(URL_PARAMS);
    for (const file of ['state.ts', 'theme.ts', 'themeChoice.ts', 'app.ts', 'urlState.ts', 'embedCode.ts']) {
      const source = readFileSync(new URL(`../src/ui/${file}`, import.meta.url), 'utf8');
      const named = [...source.matchAll(/(?:params|searchParams|\))\.(?:get|has|set)\(\s*'([^']+)'/g)].map(
        (m) => m[1] as string,
      );
      expect(
        named.filter((n) => !known.has(n)),
        file,
      ).toEqual([]);
    }
  });
});

describe("the page's fields are the registry's", () => {
  it('each text field is a registry field, with its unit kind and its label in the messages', () => {
    expect([...FIELD_KEYS].sort()).toEqual([...PAGE_FIELD_KEYS].sort());
    for (const key of FIELD_KEYS) {
      const name = fieldOfPageKey(key);
      expect(pageKeyOf(name)).toBe(key);
      expect(isPageLength(key)).toBe(isLengthField(name));
      let state = withField(defaultState(), key, 'abc');
      if (key === 'L') state = { ...state, mode: 'inverse' };
      if (key === 'ra') state = { ...state, target: 'ra' };
      if (key === 'sa') state = { ...state, target: 'sa' };
      if (key === 'Rs') state = { ...state, surface: 'convex' };
      // Three-axis fields in three-axis machining; the radii at a doubly curved point (both curved).
      if (key === 'slope' || key === 'psi') state = { ...state, machine: '3axis' };
      if (key === 'Lxy') state = { ...state, machine: '3axis', mode: 'inverse' };
      if (key === 'dz') state = { ...state, machine: '3axis', mode: 'inverse', passes: 'waterline' };
      if (key === 'Rf' || key === 'Rc')
        state = { ...state, surface: 'curved', feedSide: 'convex', crossSide: 'convex' };
      const built = buildRequest(state);
      // The teeth and their feed are optional: their text is named on its field, the question still asked.
      if (built.ok !== FINISH_KEYS.includes(key))
        throw new Error(`${key}=abc: the question ${built.ok ? 'is' : 'is not'} asked`);
      const message = stateMessages(state, built, null).get(key) ?? '';
      expect(message.startsWith(FIELDS[name].label), `${key}: ${message}`).toBe(true);
    }
  });
});

describe('the worker reads the registry fields back from a request', () => {
  const cylinder = { kind: 'cylinder', radiusMm: -40, axis: 'cross' } as const;
  const tool = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 3 };

  it("each field's core property holds its value: validation gives the same input back", () => {
    const f = forwardInput(tool, 'zigzag', 0.05, cylinder);
    const back = validateForward(rawOf(f, [...PASS_FIELDS, 'h']));
    expect(back.ok && back.value).toEqual(f);
    const i = inverseInput(tool, 'one-way', 2, cylinder);
    const inv = validateInverse(rawOf(i, [...PASS_FIELDS, 'interval']));
    expect(inv.ok && inv.value).toEqual(i);
    const ra = validateRaTarget({ R: 3, Rcr: 1, rho: 5, tilt: 3, pattern: 'zigzag', ra: 0.002 });
    if (!ra.ok) throw new Error('valid');
    expect(validateRaTarget(rawOf(ra.value, [...PASS_FIELDS, 'ra']))).toEqual(ra);
    // Every field with a core property is read from the inputs that hold it.
    const sa = validateTargetSa({ R: 3, Rcr: 1, rho: 5, tilt: 3, pattern: 'zigzag', sa: 0.002 });
    if (!sa.ok) throw new Error('valid');
    const rz = targetRzPair(sa.value, { flutes: 2, runoutMm: 0, runoutPhaseDeg: 0, passPhase: 0 }, 0.002);
    const holders: Record<string, object> = { h: f, interval: i, ra: ra.value, targetSa: sa.value, targetRz: rz };
    for (const name of FIELD_NAMES) {
      const raw: Partial<Record<FieldName, unknown>> = rawOf(holders[name] ?? f, [name]);
      expect(raw[name], name).toBeDefined();
    }
    // A plane has no surface fields.
    expect(Object.keys(rawOf(forwardInput(tool, 'one-way', 0.05), PASS_FIELDS))).toEqual([
      'R',
      'Rcr',
      'rho',
      'tilt',
      'pattern',
    ]);
  });

  it('two requests ask the same question exactly when every field is equal (sameRequest)', () => {
    const f = forwardInput(tool, 'one-way', 0.05, cylinder);
    const ask = (input: typeof f) => ({ mode: 'forward' as const, input });
    expect(sameRequest(ask(f), ask({ ...f, surface: { ...cylinder } }))).toBe(true);
    for (const changed of [
      { toolRadiusMm: 3.1 },
      { cornerRadiusMm: 0.9 },
      { leadAngleDeg: 6 },
      { tiltAngleDeg: -3 },
      { pattern: 'zigzag' as const },
      { surface: { ...cylinder, radiusMm: -41 } },
      { surface: { ...cylinder, axis: 'feed' as const } },
      { surface: { kind: 'plane' as const } },
      { scallopHeightMm: 0.06 },
    ])
      expect(sameRequest(ask(f), ask({ ...f, ...changed })), JSON.stringify(changed)).toBe(false);
    const i = inverseInput(tool, 'one-way', 2, cylinder);
    expect(sameRequest({ mode: 'inverse', input: i }, { mode: 'inverse', input: { ...i, intervalMm: 2.1 } })).toBe(
      false,
    );
    expect(sameRequest({ mode: 'inverse', input: i }, { mode: 'inverse', input: { ...i } })).toBe(true);
  });

  it('revalidation names the field of a bad value by the registry', () => {
    const f = forwardInput(tool, 'one-way', 0.05, cylinder);
    expect(revalidate({ mode: 'forward', input: f })).toBeNull();
    for (const [name, key] of [
      ['R', 'toolRadiusMm'],
      ['rho', 'leadAngleDeg'],
      ['h', 'scallopHeightMm'],
    ] as const) {
      expect(FIELDS[name].core).toBe(key);
      const errors = revalidate({ mode: 'forward', input: { ...f, [key]: Number.NaN } });
      expect(errors?.[0]?.field, name).toBe(name);
    }
  });
});

describe('the embed element takes every state the URL takes (public/embed.js, generated)', () => {
  const source = readFileSync(EMBED_SCRIPT, 'utf8');

  it("embed.js's attribute list is the one generated from the registry", () => {
    expect(source).toContain(attributesBlock());
    expect(withAttributes(source)).toBe(source);
    expect(embedAttributesDrift()).toBeNull();
  });

  it('each attribute (lower case, as HTML reads it) becomes a URL parameter of the registry; every parameter has one', () => {
    const literal = /const PARAMS = (\{[^}]*\});/.exec(source)?.[1];
    const params = new Function(`return ${literal};`)() as Record<string, string>;
    expect(Object.entries(params)).toEqual(EMBED_ATTRIBUTES.map(([a, p]) => [a, p]));
    for (const attribute of Object.keys(params)) expect(attribute).toBe(attribute.toLowerCase());
    // Every parameter the page reads, but `embed`, which the element sets itself, `present`, a
    // projector's layout of the full page (an embedded page ignores it), and `tool`, the name of the
    // shop's own saved or library tool (the full page's, as Copy link carries it).
    expect(new Set(Object.values(params))).toEqual(
      new Set(URL_PARAMS.filter((p) => p !== FIELDS.embed.url && p !== FIELDS.present.url && p !== FIELDS.tool.url)),
    );
  });
});
