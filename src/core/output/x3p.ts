/**
 * The areal surface as an ISO 25178-72 x3p file (revision ISO 25178-72:2017/Amd 1:2020), the
 * exchange format surface-metrology software reads (MountainsMap, Gwyddion, x3pio, surfalize).
 * An x3p file is a zip of:
 * - `main.xml`: Record1 (a surface, `SUR`: incremental x and y axes with their increments and
 *   offsets in metres, an absolute z axis of float64), Record2 (date, creator, the software as
 *   the instrument, probing system `Software`: a computed surface, not a measurement), Record3
 *   (the matrix size and the link to the binary heights with their MD5), Record4 (the checksum
 *   file's name);
 * - `bindata/data.bin`: the heights in metres, little-endian float64, x fastest;
 * - `md5checksum.hex`: the MD5 of `main.xml` (as `md5sum` writes it).
 * Pure (no I/O, no DOM, no Node): the bytes are returned for the caller to save or download.
 * The zip is fflate's (only `zipSync` and `strToU8`, so the rest stays out of the bundle).
 */

import { strToU8, zipSync } from 'fflate';
import { md5Hex } from '../math/md5';

/** A height map on a regular grid, in mm. */
export interface HeightGrid {
  /** Samples along x (the columns), a whole number >= 1. */
  nx: number;
  /** Samples along y (the rows), a whole number >= 1. */
  ny: number;
  /** Spacing of the samples along x (mm, > 0). */
  dxMm: number;
  /** Spacing of the samples along y (mm, > 0). */
  dyMm: number;
  /**
   * The `nx * ny` heights (mm), row-major with x fastest: sample `(i, j)` (column `i`, row `j`) is
   * `heightsMm[j * nx + i]`, at `x = xOriginMm + i * dxMm`, `y = yOriginMm + j * dyMm`.
   */
  heightsMm: Float64Array;
  /** x of the first column (mm; default 0): the notes' grid puts sample `i` at `(i + 1/2) dx`. */
  xOriginMm?: number;
  /** y of the first row (mm; default 0). */
  yOriginMm?: number;
}

/** What the file says about where the surface comes from (Record2). */
export interface X3pMetadata {
  /** When the surface was made (default: now). */
  date?: Date;
  /** Who made it (a person or an institution); left out when absent. */
  creator?: string;
  /** Free text, e.g. the tool, the posture and the feed that give the surface. */
  comment?: string;
  /** The software that computed the surface, written as the instrument (default `path-interval`). */
  softwareName?: string;
  /** Its version (default empty). */
  softwareVersion?: string;
}

/** The revision written: ISO 25178-72:2017/Amd 1:2020, where `x = offset + (u - 1) * increment`. */
const X3P_REVISION = 'ISO25178-72:2017/DAM1';
/** The binary heights' path in the zip (the standard's recommended name). */
const X3P_DATA_PATH = 'bindata/data.bin';
/** The checksum file's path in the zip. */
const X3P_CHECKSUM_PATH = 'md5checksum.hex';

const MM_PER_M = 1000;

/**
 * The bytes of the x3p file of `grid`.
 *
 * @param grid the heights (mm) and their grid; checked: a one-line RangeError names a bad field.
 * @param metadata date, creator, comment and software for Record2.
 * @returns the zip archive's bytes (main.xml deflated, the heights stored: float64 metres, exact).
 */
export function x3pBytes(grid: HeightGrid, metadata: X3pMetadata = {}): Uint8Array {
  checkGrid(grid);
  const date = metadata.date ?? new Date();
  if (!Number.isFinite(date.getTime())) throw new RangeError('x3p date: not a valid date');
  const count = grid.nx * grid.ny;
  const data = new Uint8Array(count * 8);
  const view = new DataView(data.buffer);
  for (let k = 0; k < count; k++) view.setFloat64(k * 8, (grid.heightsMm[k] as number) / MM_PER_M, true);
  const mainXml = strToU8(x3pMainXml(grid, { ...metadata, date }, md5Hex(data)));
  return zipSync(
    {
      'main.xml': mainXml,
      // Stored: float64 heights of a smooth surface deflate by some 4 % for a second of CPU at 1024 x 1024.
      [X3P_DATA_PATH]: [data, { level: 0 }],
      [X3P_CHECKSUM_PATH]: strToU8(`${md5Hex(mainXml)} *main.xml\n`),
    },
    { level: 6, mtime: zipTime(date) },
  );
}

/**
 * The text of `main.xml` for `grid`, whose binary heights have the MD5 `dataMd5`.
 *
 * @param grid the grid (only its size, spacing and origin are read here).
 * @param metadata as for {@link x3pBytes}, with the date.
 * @param dataMd5 the MD5 (hex) of `bindata/data.bin`.
 * @returns the XML document.
 */
function x3pMainXml(grid: HeightGrid, metadata: X3pMetadata & { date: Date }, dataMd5: string): string {
  const { date } = metadata;
  const software = xmlToken(metadata.softwareName ?? 'path-interval', 'software name');
  const axis = (name: string, type: 'I' | 'A', increment: number, offset: number) =>
    `      <${name}>\n        <AxisType>${type}</AxisType>\n        <DataType>D</DataType>\n` +
    `        <Increment>${xmlNumber(increment)}</Increment>\n        <Offset>${xmlNumber(offset)}</Offset>\n      </${name}>\n`;
  const lines = [
    '<?xml version="1.0" encoding="UTF-8"?>',
    '<p:ISO5436_2 xmlns:p="http://www.opengps.eu/2008/ISO5436_2" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" xsi:schemaLocation="http://www.opengps.eu/2008/ISO5436_2 http://www.opengps.eu/2008/ISO5436_2/ISO5436_2.xsd">',
    '  <Record1>',
    `    <Revision>${X3P_REVISION}</Revision>`,
    '    <FeatureType>SUR</FeatureType>',
    '    <Axes>',
    axis('CX', 'I', grid.dxMm / MM_PER_M, (grid.xOriginMm ?? 0) / MM_PER_M) +
      axis('CY', 'I', grid.dyMm / MM_PER_M, (grid.yOriginMm ?? 0) / MM_PER_M) +
      axis('CZ', 'A', 1, 0) +
      '    </Axes>',
    '  </Record1>',
    '  <Record2>',
    `    <Date>${date.toISOString().replace('Z', '+00:00')}</Date>`,
    ...(metadata.creator === undefined ? [] : [`    <Creator>${xmlToken(metadata.creator, 'creator')}</Creator>`]),
    '    <Instrument>',
    `      <Manufacturer>${software}</Manufacturer>`,
    `      <Model>${software}</Model>`,
    '      <Serial></Serial>',
    `      <Version>${xmlToken(metadata.softwareVersion ?? '', 'software version')}</Version>`,
    '    </Instrument>',
    '    <ProbingSystem>',
    '      <Type>Software</Type>',
    `      <Identification>${software} surface model (computed, not measured)</Identification>`,
    '    </ProbingSystem>',
    ...(metadata.comment === undefined ? [] : [`    <Comment>${xmlText(metadata.comment, 'comment')}</Comment>`]),
    '  </Record2>',
    '  <Record3>',
    '    <MatrixDimension>',
    `      <SizeX>${grid.nx}</SizeX>`,
    `      <SizeY>${grid.ny}</SizeY>`,
    '      <SizeZ>1</SizeZ>',
    '    </MatrixDimension>',
    '    <DataLink>',
    `      <PointDataLink>${X3P_DATA_PATH}</PointDataLink>`,
    `      <MD5ChecksumPointData>${dataMd5}</MD5ChecksumPointData>`,
    '    </DataLink>',
    '  </Record3>',
    '  <Record4>',
    `    <ChecksumFile>${X3P_CHECKSUM_PATH}</ChecksumFile>`,
    '  </Record4>',
    '</p:ISO5436_2>',
    '',
  ];
  return lines.join('\n');
}

/** Rejects a grid that cannot be written, with a one-line message naming the field and its limit. */
function checkGrid(grid: HeightGrid): void {
  for (const key of ['nx', 'ny'] as const) {
    const n = grid[key];
    if (!Number.isInteger(n) || n < 1) throw new RangeError(`x3p ${key}: must be a whole number >= 1 (got ${n})`);
  }
  for (const key of ['dxMm', 'dyMm'] as const) {
    const d = grid[key];
    if (!(Number.isFinite(d) && d > 0)) throw new RangeError(`x3p ${key}: must be a finite spacing > 0 mm (got ${d})`);
  }
  for (const key of ['xOriginMm', 'yOriginMm'] as const) {
    const o = grid[key] ?? 0;
    if (!Number.isFinite(o)) throw new RangeError(`x3p ${key}: must be a finite length in mm (got ${o})`);
  }
  const count = grid.nx * grid.ny;
  if (grid.heightsMm.length !== count)
    throw new RangeError(`x3p heightsMm: must hold nx * ny = ${count} heights (got ${grid.heightsMm.length})`);
  for (let k = 0; k < count; k++) {
    const h = grid.heightsMm[k];
    if (!Number.isFinite(h)) throw new RangeError(`x3p heightsMm: every height must be finite (index ${k} is ${h})`);
  }
}

/** A number as the shortest text that reads back to the same double (a valid xsd:double); never `-0`. */
function xmlNumber(value: number): string {
  return value === 0 ? '0' : String(value);
}

/**
 * Characters XML 1.0 cannot hold: controls other than tab, line feed and carriage return, U+FFFE,
 * U+FFFF and (the `u` flag reads a pair as one code point) lone surrogates.
 */
// biome-ignore lint/suspicious/noControlCharactersInRegex: these are the characters it rejects
const XML_FORBIDDEN = /[\u0000-\u0008\u000b\u000c\u000e-\u001f\ud800-\udfff\ufffe\uffff]/u;

/** Free text escaped for an XML element. */
function xmlText(text: string, field: string): string {
  const bad = XML_FORBIDDEN.exec(text);
  if (bad)
    throw new RangeError(
      `x3p ${field}: the character U+${bad[0].charCodeAt(0).toString(16).toUpperCase().padStart(4, '0')} cannot be written in XML`,
    );
  return text.replaceAll('&', '&amp;').replaceAll('<', '&lt;').replaceAll('>', '&gt;');
}

/** Text of an xsd:token element: escaped, runs of white space collapsed to one space, trimmed. */
function xmlToken(text: string, field: string): string {
  return xmlText(text, field)
    .replace(/[\t\n\r ]+/g, ' ')
    .trim();
}

/** A zip time (the DOS format holds 1980..2099, in local time): the date itself when it fits, else the nearest end. */
function zipTime(date: Date): Date {
  const first = new Date(1980, 0, 1).getTime();
  const last = new Date(2099, 11, 31).getTime();
  return new Date(Math.min(Math.max(date.getTime(), first), last));
}
