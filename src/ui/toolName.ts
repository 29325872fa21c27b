/**
 * The name of the tool the fields hold (a saved tool or a library's), as the page carries it: in
 * the state, in the link (`tool=`, read as hostile text: cleaned and cut as a library's names are,
 * core/input/toolLibrary.ts cleanToolName) and for the views that show it beside the answer (the
 * results' headline, the shop sheet: {@link shownToolName}). Shown only as text, never as HTML.
 */
import { urlParamOf } from '../core/input/fields';
import type { LibraryTool } from '../core/input/toolLibrary';
import { cleanToolName } from '../core/input/toolNameText';
import { type LengthUnit, unitSymbol } from '../core/input/units';
import { fieldText } from './fieldText';
import type { CalculatorState } from './stateTypes';

/** The link's parameter for the tool's name (the field registry's). */
export const TOOL_NAME_PARAM = urlParamOf('tool');

/** The tool's name a link gives (cleaned, at most 80 characters), or undefined when none or empty. */
export function toolNameOfLink(params: URLSearchParams): string | undefined {
  const text = params.get(TOOL_NAME_PARAM);
  if (text === null) return undefined;
  const name = cleanToolName(text);
  return name === '' ? undefined : name;
}

/** Writes the state's tool name into a link's parameters (nothing when it has none). */
export function writeToolName(params: URLSearchParams, state: CalculatorState): void {
  if (state.toolName !== undefined && state.toolName !== '') params.set(TOOL_NAME_PARAM, state.toolName);
}

/** The state without a tool name when `keys` set the tool's D or corner radius (the name no longer fits). */
export function dropToolName(state: CalculatorState, keys: readonly string[]): CalculatorState {
  if (state.toolName === undefined || !keys.some((k) => k === 'R' || k === 'Rcr')) return state;
  const { toolName: _dropped, ...rest } = state;
  return rest;
}

let shown: string | null = null;

/**
 * The tool name shown with the answer now (null for none): set by the results' headline as it draws
 * (the inputs on screen), read by the views that print the answer elsewhere (the shop sheet's title).
 */
export function shownToolName(): string | null {
  return shown;
}

/** Sets what {@link shownToolName} returns (the results panel, as it draws). */
export function setShownToolName(name: string | null): void {
  shown = name;
}

/**
 * The title line that names the tool shown with the answer, for a printed or saved sheet (the shop
 * sheet puts it before its own title lines): `Tool name: ...` as text, or none.
 */
export function shownToolNameLines(): string[] {
  return shown === null ? [] : [`Tool name: ${shown}`];
}

/** A length of a tool in `unit`, as a catalogue writes it (the fewest digits that give it: 0.5 in, 12.7 mm). */
export function toolLength(mm: number, unit: LengthUnit): string {
  return `${fieldText('R', mm, unit)} ${unitSymbol(unit)}`;
}

/** A tool as a list's option reads: its name, D and corner radius in the tool's own unit, flutes. */
export function toolLabel(tool: LibraryTool): string {
  const flutes = tool.flutes === null ? '' : `, ${tool.flutes} flutes`;
  return `${tool.name}: D ${toolLength(tool.diameterMm, tool.unit)}, corner R ${toolLength(tool.cornerRadiusMm, tool.unit)}${flutes}`;
}
