// Editing plain JSON-like values by path, for the malformed-input tests and the fuzzer
// (bench/trapfuzz-cases.mjs imports this file: it holds no test code). Moved unchanged from
// tests/node/malformed.test.mjs.

export function clone(v) {
  if (Array.isArray(v)) return v.map(clone);
  if (v && typeof v === 'object' && v.constructor === Object) {
    const o = {};
    for (const [k, x] of Object.entries(v)) o[k] = clone(x);
    return o;
  }
  return v;
}

/** All paths (arrays of keys) inside a plain object/array value. */
export function paths(v, prefix = [], out = []) {
  out.push(prefix);
  if (Array.isArray(v)) v.forEach((x, i) => paths(x, [...prefix, i], out));
  else if (v && typeof v === 'object' && v.constructor === Object) {
    for (const [k, x] of Object.entries(v)) paths(x, [...prefix, k], out);
  }
  return out;
}

export function setPath(root, path, value, del) {
  if (path.length === 0) return value;
  let o = root;
  for (const k of path.slice(0, -1)) o = o[k];
  const last = path[path.length - 1];
  if (del) {
    if (Array.isArray(o)) o.splice(last, 1);
    else delete o[last];
  } else o[last] = value;
  return root;
}
