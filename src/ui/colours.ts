/**
 * The procedures' colours from the one registry, as CSS custom properties set through the CSSOM:
 * `--proc-light-<key>` and `--proc-dark-<key>`, from which the stylesheet picks `--proc-<key>`
 * for the theme on screen. Stylesheets colour swatches, curves and headings by class, so the page
 * needs no inline style attribute (a strict Content-Security-Policy allows no `style-src-attr`).
 */
import {
  CURVATURE_ROW_KEYS,
  CURVATURE_ROWS,
  PROCEDURE_KEYS,
  PROCEDURES,
  type ProcedureKey,
} from '../core/procedures/procedures';
import type { Theme } from './themeChoice';

export function applyProcedureColours(root: HTMLElement): void {
  for (const key of PROCEDURE_KEYS) {
    root.style.setProperty(`--proc-light-${key}`, PROCEDURES[key].colour);
    root.style.setProperty(`--proc-dark-${key}`, PROCEDURES[key].colourDark);
  }
  // The rows a cylinder adds (the plane's answer, the corrected procedures): `--curv-<key>`.
  for (const key of CURVATURE_ROW_KEYS) root.style.setProperty(`--curv-${key}`, CURVATURE_ROWS[key].colour);
}

/** A procedure's colour on a theme (for canvas drawing, which cannot read custom properties). */
export function procedureColour(key: ProcedureKey, theme: Theme): string {
  return theme === 'dark' ? PROCEDURES[key].colourDark : PROCEDURES[key].colour;
}
