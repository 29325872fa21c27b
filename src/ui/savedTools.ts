/**
 * The tools a shop saves in its browser (name, unit, D, corner radius, flutes), kept in localStorage as
 * JSON. Whatever the storage holds is checked as a tool library is (toolLibrary.ts): a corrupt or
 * hostile entry is dropped with a line saying so, a storage that throws (disabled, private mode,
 * full) leaves the list in memory with a line saying so, and nothing else is lost.
 */
import { checkTool, type LibraryTool } from '../core/input/toolLibrary';

/** The storage key (versioned: a later form gets another key). */
export const SAVED_TOOLS_KEY = 'path-interval.saved-tools.v1';

/** The most tools kept (the oldest go first). */
export const SAVED_TOOLS_MAX = 200;

/** The part of the Web Storage API used (localStorage; a Map-backed stand-in in tests). */
export interface ToolStorage {
  getItem(key: string): string | null;
  setItem(key: string, value: string): void;
}

/**
 * The saved tools read from `text` (the stored JSON; null when none), newest first, and a line when
 * some were left out: those that could not be read, and, apart from them, those beyond the
 * {@link SAVED_TOOLS_MAX} newest readable ones kept (over the cap, not unreadable).
 */
export function readSavedTools(text: string | null): { tools: LibraryTool[]; problem: string | null } {
  if (text === null) return { tools: [], problem: null };
  let json: unknown;
  try {
    json = JSON.parse(text);
  } catch {
    return {
      tools: [],
      problem: 'The saved tools in this browser could not be read (not JSON); the list starts empty.',
    };
  }
  const list = typeof json === 'object' && json !== null && 'tools' in json ? json.tools : undefined;
  if (!Array.isArray(list))
    return { tools: [], problem: 'The saved tools in this browser could not be read; the list starts empty.' };
  const tools: LibraryTool[] = [];
  let unreadable = 0;
  let read = 0;
  for (; read < list.length && tools.length < SAVED_TOOLS_MAX; read++) {
    const e: unknown = list[read];
    const entry = typeof e === 'object' && e !== null ? (e as Record<string, unknown>) : {};
    const name = typeof entry.name === 'string' ? entry.name : '';
    // Tools saved before units were kept have none: they were saved in mm, as the page then listed them.
    const unit = entry.unit === 'in' ? 'in' : 'mm';
    const checked = checkTool(name, entry.diameterMm, entry.cornerRadiusMm, entry.flutes ?? null, unit);
    if (checked.ok && checked.tool.name !== '') tools.push(checked.tool);
    else unreadable++;
  }
  const lines = [unreadableLine(unreadable), overCapLine(list.length - read, tools.length)].filter((l) => l !== '');
  return { tools, problem: lines.length === 0 ? null : lines.join(' ') };
}

/** `n` saved tool(s), and the verb's form that goes with it. */
const savedCount = (n: number, singular: string, plural: string) =>
  `${n} saved tool${n === 1 ? '' : 's'} ${n === 1 ? singular : plural}`;

/** The line for saved tools that could not be read ('' for none). */
function unreadableLine(count: number): string {
  return count === 0 ? '' : `${savedCount(count, 'could not be read and was', 'could not be read and were')} left out.`;
}

/** The line for saved tools beyond the cap ('' for none): how many were left out, how many kept. */
function overCapLine(count: number, kept: number): string {
  return count === 0
    ? ''
    : `${savedCount(count, 'was', 'were')} over the limit of ${SAVED_TOOLS_MAX} and left out (the ${kept} newest are kept).`;
}

/** The JSON the saved tools are stored as. */
export function savedToolsText(tools: readonly LibraryTool[]): string {
  return JSON.stringify({ tools });
}

/**
 * The saved tools with `tool` added: a tool of the same name is replaced (saving again updates
 * it), the newest first, at most {@link SAVED_TOOLS_MAX}.
 */
export function withSavedTool(tools: readonly LibraryTool[], tool: LibraryTool): LibraryTool[] {
  return [tool, ...tools.filter((t) => t.name !== tool.name)].slice(0, SAVED_TOOLS_MAX);
}

/** The saved tools of a browser: read once, written on each change; a storage that throws is tolerated. */
export class SavedTools {
  private list: LibraryTool[];
  /** The last thing that went wrong with the storage (shown to the user), or null. */
  problem: string | null;

  constructor(private readonly storage: ToolStorage | null) {
    let text: string | null = null;
    let blocked = storage === null;
    try {
      text = storage?.getItem(SAVED_TOOLS_KEY) ?? null;
    } catch {
      blocked = true;
    }
    const read = readSavedTools(text);
    this.list = read.tools;
    this.problem = blocked
      ? 'This browser does not let the page keep saved tools; they last until the page closes.'
      : read.problem;
  }

  get tools(): readonly LibraryTool[] {
    return this.list;
  }

  /** Saves a tool (replacing one of the same name); false with a problem when the storage refused (kept in memory). */
  save(tool: LibraryTool): boolean {
    return this.store(withSavedTool(this.list, tool));
  }

  /** Forgets the tool named `name`. */
  remove(name: string): boolean {
    return this.store(this.list.filter((t) => t.name !== name));
  }

  private store(tools: LibraryTool[]): boolean {
    this.list = tools;
    try {
      if (this.storage === null) throw new Error('no storage');
      this.storage.setItem(SAVED_TOOLS_KEY, savedToolsText(tools));
      this.problem = null;
      return true;
    } catch {
      this.problem =
        'This browser did not keep the tool (storage full or not allowed); it lasts until the page closes.';
      return false;
    }
  }
}
