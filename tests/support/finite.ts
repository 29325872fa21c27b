/**
 * True when every number reachable from `value` (object fields, array and typed-array items,
 * recursively) is finite. Checks the numbers themselves: JSON.stringify would turn NaN and
 * Infinity into null and hide them.
 */
export function everyNumberFinite(value: unknown, seen: Set<object> = new Set()): boolean {
  if (typeof value === 'number') return Number.isFinite(value);
  if (typeof value !== 'object' || value === null) return true;
  if (seen.has(value)) return true;
  seen.add(value);
  if (ArrayBuffer.isView(value) && !(value instanceof DataView)) {
    const items = value as unknown as ArrayLike<number>;
    for (let i = 0; i < items.length; i++) if (!Number.isFinite(items[i])) return false;
    return true;
  }
  return Object.values(value).every((v) => everyNumberFinite(v, seen));
}
