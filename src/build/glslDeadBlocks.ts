/**
 * A partial GLSL preprocessor for the build (src/build/threeTrim.ts): removes the conditional
 * blocks (`#ifdef`, `#ifndef`, `#if defined(...)`, their `#elif` and `#else`) that a set of macros
 * known never to be defined decides, and keeps every other line and directive as it stands. What
 * the shader compiles to is unchanged for every definition of the other macros: a block whose
 * condition is known is replaced by the branch the preprocessor would take, one whose condition
 * depends on anything else is kept whole (its known-false `#elif` branches dropped).
 */

/** true, false, or null: depends on a macro not in the dead set (or on a value). */
type Known = boolean | null;

const DEFINED = /^!?\s*defined\s*(?:\(\s*(\w+)\s*\)|(\w+))$/;

/**
 * The value of a `#if` / `#elif` expression when it is `defined(X)` terms (optionally negated)
 * joined by only `||` or only `&&`, outer brackets allowed, given that no macro in `dead` is defined;
 * null for anything else (values, comparisons, mixed operators) or when an unknown term decides.
 */
export function knownCondition(expression: string, dead: ReadonlySet<string>): Known {
  let e = expression.trim();
  while (e.startsWith('(') && e.endsWith(')') && balanced(e.slice(1, -1))) e = e.slice(1, -1).trim();
  const or = splitTop(e, '||');
  const and = splitTop(e, '&&');
  if (or.length > 1 && and.length === 1)
    return combine(
      or.map((t) => knownCondition(t, dead)),
      'or',
    );
  if (and.length > 1 && or.length === 1)
    return combine(
      and.map((t) => knownCondition(t, dead)),
      'and',
    );
  if (or.length > 1 || and.length > 1) return null;
  const m = DEFINED.exec(e);
  if (m === null) return null;
  const name = (m[1] ?? m[2]) as string;
  if (!dead.has(name)) return null;
  return e.startsWith('!');
}

function combine(values: Known[], op: 'or' | 'and'): Known {
  const decisive = op === 'or';
  if (values.includes(decisive)) return decisive;
  return values.includes(null) ? null : !decisive;
}

/** Whether `s` has no bracket closed before it opens (so stripping an outer pair keeps its meaning). */
function balanced(s: string): boolean {
  let depth = 0;
  for (const ch of s) {
    if (ch === '(') depth++;
    else if (ch === ')' && --depth < 0) return false;
  }
  return depth === 0;
}

/** `s` split at `op` outside brackets. */
function splitTop(s: string, op: string): string[] {
  const parts: string[] = [];
  let depth = 0;
  let from = 0;
  for (let i = 0; i < s.length; i++) {
    if (s[i] === '(') depth++;
    else if (s[i] === ')') depth--;
    else if (depth === 0 && s.startsWith(op, i)) {
      parts.push(s.slice(from, i));
      from = i + op.length;
      i += op.length - 1;
    }
  }
  parts.push(s.slice(from));
  return parts;
}

const DIRECTIVE = /^\s*#\s*(ifdef|ifndef|if|elif|else|endif)\b\s*(.*?)\s*$/;

/**
 * One open conditional: `open` when its directives are kept (some branch depends on an unknown
 * macro), else its branches are decided here. `active`: the current branch's lines are emitted;
 * `taken`: a branch was chosen (the later ones are dropped); `outer`: the enclosing region emits.
 */
interface Frame {
  open: boolean;
  active: boolean;
  taken: boolean;
  outer: boolean;
  /** In an open frame: a branch was decided true; the rest is dropped (its `#endif` kept). */
  closedTrue: boolean;
}

/** The condition of an `#ifdef X` / `#ifndef X` / `#if expr` line. */
function opening(kind: string, rest: string, dead: ReadonlySet<string>): Known {
  if (kind === 'ifdef') return dead.has(rest) ? false : null;
  if (kind === 'ifndef') return dead.has(rest) ? true : null;
  return knownCondition(rest, dead);
}

/** `glsl` without the blocks that the macros in `dead` (never defined) decide. */
export function dropDeadBlocks(glsl: string, dead: ReadonlySet<string>): string {
  const out: string[] = [];
  const stack: Frame[] = [];
  const emitting = () => stack.length === 0 || (stack.at(-1) as Frame).active;
  for (const line of glsl.split('\n')) {
    const m = DIRECTIVE.exec(line);
    if (m === null) {
      if (emitting()) out.push(line);
      continue;
    }
    const kind = m[1] as string;
    const rest = m[2] as string;
    if (kind === 'ifdef' || kind === 'ifndef' || kind === 'if') {
      const outer = emitting();
      const value = outer ? opening(kind, rest, dead) : false;
      if (!outer) stack.push({ open: false, active: false, taken: true, outer, closedTrue: false });
      else if (value === null) {
        out.push(line);
        stack.push({ open: true, active: true, taken: false, outer, closedTrue: false });
      } else stack.push({ open: false, active: value, taken: value, outer, closedTrue: false });
      continue;
    }
    const frame = stack.at(-1);
    if (frame === undefined) throw new Error(`glslDeadBlocks: #${kind} without #if`);
    if (kind === 'endif') {
      stack.pop();
      if (frame.open) out.push(line);
      continue;
    }
    const value = kind === 'else' ? true : knownCondition(rest, dead);
    if (!frame.outer || frame.taken || frame.closedTrue) {
      frame.active = false;
    } else if (frame.open) {
      if (value === false) frame.active = false;
      else {
        out.push(value === true && kind === 'elif' ? line.replace(/#\s*elif\b.*/, '#else') : line);
        frame.active = true;
        frame.closedTrue = value === true;
      }
    } else if (value === null) {
      // The first branch that may be taken: it opens the block (`#elif` becomes `#if`).
      out.push(line.replace(/#\s*elif\b/, '#if'));
      frame.open = true;
      frame.active = true;
    } else {
      frame.active = value;
      frame.taken = value;
    }
  }
  if (stack.length > 0) throw new Error('glslDeadBlocks: #if without #endif');
  return out.join('\n');
}
