/**
 * The procedures' colours from the one registry, as CSS custom properties (`--proc-<key>`) set
 * through the CSSOM: stylesheets colour swatches, curves and headings by class, so the page needs
 * no inline style attribute (a strict Content-Security-Policy allows no `style-src-attr`).
 */
import { CURVATURE_ROW_KEYS, CURVATURE_ROWS, PROCEDURE_KEYS, PROCEDURES } from '../core/procedures';

export function applyProcedureColours(root: HTMLElement): void {
  for (const key of PROCEDURE_KEYS) root.style.setProperty(`--proc-${key}`, PROCEDURES[key].colour);
  // The rows a cylinder adds (the plane's answer, the corrected procedures): `--curv-<key>`.
  for (const key of CURVATURE_ROW_KEYS) root.style.setProperty(`--curv-${key}`, CURVATURE_ROWS[key].colour);
}
