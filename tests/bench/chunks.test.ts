import { describe, expect, it } from 'vitest';
import { importClosure, staticImports } from '../../src/bench/chunks';

describe('the import graph of built chunks', () => {
  it('finds static imports and re-exports, not dynamic imports or other strings', () => {
    const code =
      'import{a as b,c}from"./core-1.js";import"./side-2.js";export{d}from"./more-3.js";' +
      'const s="./not-an-import.js";const p=()=>import("./lazy-4.js");x.from("./nope.js");';
    expect(staticImports(code)).toEqual(['core-1.js', 'side-2.js', 'more-3.js']);
    expect(staticImports("import {\n a } from './spaced-5.js';")).toEqual(['spaced-5.js']);
  });

  it('follows imports transitively, once each, only through known scripts', () => {
    const files: Record<string, string> = {
      'index.js': 'import{a}from"./core.js";const v=()=>import("./views.js");',
      'worker.js': 'import{a}from"./core.js";import{b}from"./geo.js";',
      'core.js': 'import"./index.js";export const a=1;',
      'geo.js': 'import{t}from"./missing.js";',
      'views.js': 'import{c}from"./three.js";',
      'three.js': '',
    };
    const names = Object.keys(files);
    const read = (n: string) => files[n] as string;
    expect([...importClosure(['index.js'], names, read)].sort()).toEqual(['core.js', 'index.js']);
    expect([...importClosure(['index.js', 'worker.js'], names, read)].sort()).toEqual([
      'core.js',
      'geo.js',
      'index.js',
      'worker.js',
    ]);
  });
});
