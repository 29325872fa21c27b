/**
 * Tools as the shop keeps them: a named tool (diameter, corner radius, flutes) checked against the
 * calculator's limits, and a Fusion 360 tool library (its JSON export) read into such tools. Pure
 * (no DOM): a tool that cannot be read gets one line naming the tool and the field, and the others
 * are kept. Names are kept as plain text (whoever shows them shows them as text, never as HTML).
 */
import { FIELDS } from './fields';
import { cleanToolName, TOOL_NAME_MAX_CHARS } from './toolNameText';
import { type LengthUnit, MM_PER_INCH } from './units';

export { cleanToolName, TOOL_NAME_MAX_CHARS };

/** A tool of a library or of the browser's saved tools; lengths in mm. */
export interface LibraryTool {
  /**
   * The unit the tool is sized in (its library's `unit`: inches or millimeters; a saved tool, the
   * page's unit when it was saved): the tool is listed in it, and the page offers it on choosing.
   */
  readonly unit: LengthUnit;
  /** The name the shop gives it (at most {@link TOOL_NAME_MAX_CHARS} characters, plain text). */
  readonly name: string;
  /** Cutting diameter D in mm, 2 * R within the tool radius's limits. */
  readonly diameterMm: number;
  /** Corner radius in mm, 0 (flat end) to D/2 (ball end). */
  readonly cornerRadiusMm: number;
  /** Number of flutes (1 to 99), or null when not given. */
  readonly flutes: number | null;
}

/** The largest library file read, in characters (a Fusion library of a few thousand tools is a few MB). */
export const LIBRARY_MAX_CHARS = 20_000_000;

/** The most tools read from one library (the rest are left, with a message). */
export const LIBRARY_MAX_TOOLS = 5000;

/** A library's tools, and a line for each thing it could not read. */
export interface LibraryRead {
  readonly tools: readonly LibraryTool[];
  readonly problems: readonly string[];
}

const R_RANGE = FIELDS.R.range;

/**
 * Checks a tool: D within twice the tool radius's limits (0.002 to 2000 mm), the corner radius from
 * 0 to D/2, flutes a whole number 1 to 99 or null. The tool (sized in `unit`), or the field at
 * fault and why.
 */
export function checkTool(
  name: string,
  diameterMm: unknown,
  cornerRadiusMm: unknown,
  flutes: unknown,
  unit: LengthUnit = 'mm',
): { ok: true; tool: LibraryTool } | { ok: false; field: 'D' | 'corner radius' | 'flutes'; why: string } {
  const minD = 2 * (R_RANGE.min ?? 0);
  const maxD = 2 * (R_RANGE.max ?? Number.POSITIVE_INFINITY);
  if (typeof diameterMm !== 'number' || !Number.isFinite(diameterMm))
    return { ok: false, field: 'D', why: 'is missing or not a number' };
  if (diameterMm < minD || diameterMm > maxD)
    return { ok: false, field: 'D', why: `must be from ${minD} to ${maxD} mm (got ${diameterMm} mm)` };
  if (typeof cornerRadiusMm !== 'number' || !Number.isFinite(cornerRadiusMm))
    return { ok: false, field: 'corner radius', why: 'is missing or not a number' };
  // A ball end's RE may be rounded in the last digit of its D/2.
  const half = diameterMm / 2;
  const corner = Math.abs(cornerRadiusMm - half) <= half * 1e-9 ? half : cornerRadiusMm;
  if (corner < 0 || corner > half)
    return {
      ok: false,
      field: 'corner radius',
      why: `must be from 0 to D/2 = ${half} mm (got ${cornerRadiusMm} mm)`,
    };
  if (flutes !== null && (typeof flutes !== 'number' || !Number.isInteger(flutes) || flutes < 1 || flutes > 99))
    return { ok: false, field: 'flutes', why: 'must be a whole number from 1 to 99' };
  return { ok: true, tool: { name: cleanToolName(name), unit, diameterMm, cornerRadiusMm: corner, flutes } };
}

/** The Fusion 360 tool types read, and the corner radius each has when its geometry leaves RE out. */
const END_MILLS: Readonly<Record<string, 'RE' | 'flat' | 'ball'>> = {
  'bull nose end mill': 'RE',
  'flat end mill': 'flat',
  'ball end mill': 'ball',
};

/** Tenths of a mm per unit: whole factors, so 0.375 in is exactly 9.525 mm (0.375 * 25.4 is not). */
const TENTH_MM_PER_UNIT: Readonly<Record<string, number>> = { millimeters: 10, inches: MM_PER_INCH * 10 };

/** The page's unit of a library's `unit`. */
const UNIT_OF: Readonly<Record<string, LengthUnit>> = { millimeters: 'mm', inches: 'in' };

function isRecord(v: unknown): v is Record<string, unknown> {
  return typeof v === 'object' && v !== null && !Array.isArray(v);
}

/** The name a library tool goes by: its description, else product id, else its place (`tool 3`). */
function nameOf(entry: Record<string, unknown>, index: number): string {
  for (const key of ['description', 'product-id'] as const) {
    const v = entry[key];
    if (typeof v === 'string' && cleanToolName(v) !== '') return cleanToolName(v);
  }
  return `tool ${index + 1}`;
}

/** A number of a Fusion geometry, in mm; null when absent, NaN when present but not a number. */
function lengthMm(geometry: Record<string, unknown>, key: string, tenthsPerUnit: number): number | null {
  const v = geometry[key];
  if (v === undefined || v === null) return null;
  return typeof v === 'number' && Number.isFinite(v) ? (v * tenthsPerUnit) / 10 : Number.NaN;
}

/** One library entry as a tool, or the line saying why it cannot be (null for a type the page skips quietly). */
function readEntry(entry: unknown, index: number): LibraryTool | string {
  if (!isRecord(entry)) return `Tool ${index + 1}: not a tool (an object with type, unit and geometry).`;
  const name = nameOf(entry, index);
  const at = `Tool ${index + 1} "${name}"`;
  const type = typeof entry.type === 'string' ? entry.type.toLowerCase() : '';
  const shape = Object.hasOwn(END_MILLS, type) ? END_MILLS[type] : undefined;
  if (shape === undefined)
    return `${at}: type "${cleanToolName(String(entry.type ?? ''))}" is not a flat, bull nose or ball end mill; skipped.`;
  const unit = typeof entry.unit === 'string' ? entry.unit.toLowerCase() : '';
  // Own keys only: a unit such as "constructor" is not one.
  const tenthsPerUnit = Object.hasOwn(TENTH_MM_PER_UNIT, unit) ? TENTH_MM_PER_UNIT[unit] : undefined;
  const sizedIn = Object.hasOwn(UNIT_OF, unit) ? UNIT_OF[unit] : undefined;
  if (tenthsPerUnit === undefined || sizedIn === undefined)
    return `${at}: unit "${cleanToolName(String(entry.unit ?? ''))}" is not millimeters or inches.`;
  if (!isRecord(entry.geometry)) return `${at}: geometry is missing.`;
  const dc = lengthMm(entry.geometry, 'DC', tenthsPerUnit);
  const re = lengthMm(entry.geometry, 'RE', tenthsPerUnit);
  if (dc === null) return `${at}: geometry.DC (the diameter) is missing.`;
  const corner = shape === 'ball' && re === null ? dc / 2 : shape === 'flat' && re === null ? 0 : re;
  if (corner === null) return `${at}: geometry.RE (the corner radius) is missing.`;
  const nof = entry.geometry.NOF;
  const flutes = typeof nof === 'number' && Number.isInteger(nof) && nof >= 1 && nof <= 99 ? nof : null;
  const checked = checkTool(name, dc, corner, flutes, sizedIn);
  if (checked.ok) return checked.tool;
  const field = checked.field === 'D' ? 'geometry.DC (the diameter)' : 'geometry.RE (the corner radius)';
  return `${at}: ${field} ${checked.why}.`;
}

/**
 * Reads a Fusion 360 tool library (its JSON export: `{ "data": [ { "type": "bull nose end mill",
 * "unit": "millimeters" | "inches", "description": ..., "geometry": { "DC": D, "RE": corner
 * radius, "NOF": flutes } }, ... ] }`), each tool in its own unit (kept as the tool's `unit`, the
 * lengths in mm). Flat, bull nose and ball end mills are read (a flat end
 * without RE has 0, a ball end without RE has D/2); every other type (drills, chamfer mills,
 * holders...) and every tool that cannot be read gets one line naming the tool and the field, the
 * rest are kept. A file that is not JSON, not such a library, or over {@link LIBRARY_MAX_CHARS}
 * characters gives no tools and one line.
 */
export function parseFusionLibrary(text: string): LibraryRead {
  if (text.length > LIBRARY_MAX_CHARS)
    return { tools: [], problems: [`The file is over ${LIBRARY_MAX_CHARS / 1e6} MB: not a tool library.`] };
  let json: unknown;
  try {
    json = JSON.parse(text);
  } catch {
    return { tools: [], problems: ['The file is not JSON: export the library from Fusion 360 as JSON.'] };
  }
  const data = isRecord(json) ? json.data : undefined;
  if (!Array.isArray(data))
    return { tools: [], problems: ['The file has no "data" list of tools: not a Fusion 360 tool library.'] };
  const tools: LibraryTool[] = [];
  const problems: string[] = [];
  data.slice(0, LIBRARY_MAX_TOOLS).forEach((entry, i) => {
    const read = readEntry(entry, i);
    if (typeof read === 'string') problems.push(read);
    else tools.push(read);
  });
  if (data.length > LIBRARY_MAX_TOOLS)
    problems.push(`Only the first ${LIBRARY_MAX_TOOLS} of ${data.length} tools were read.`);
  return { tools, problems };
}
