// Pure helpers of the sandbox (www/sandbox.js), kept apart so they can be tested in Node:
// the link format `sandbox.html#code=<base64url of the UTF-8 code, no padding>`, a short text form of any value
// (typed arrays summarised), which values are drawable, and where in a stack trace the visitor's code failed.

/** base64url (no padding) of the UTF-8 bytes of `text`. */
export function encodeCode(text) {
  const bytes = new TextEncoder().encode(text);
  let bin = '';
  for (let i = 0; i < bytes.length; i += 0x8000) bin += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(bin).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

/** The code of a base64url string (padding optional); throws on malformed input. */
export function decodeCode(b64) {
  const s = String(b64).replace(/-/g, '+').replace(/_/g, '/').replace(/=+$/, '');
  if (!/^[A-Za-z0-9+/]*$/.test(s) || s.length % 4 === 1) throw new Error('the link\'s code is not base64url');
  const bin = atob(s + '='.repeat((4 - (s.length % 4)) % 4));
  const bytes = Uint8Array.from(bin, (c) => c.charCodeAt(0));
  return new TextDecoder('utf-8', { fatal: true }).decode(bytes);
}

/** The code in a location hash `#code=…` (other `&key=value` parts are ignored), or null. */
export function codeFromHash(hash) {
  const h = String(hash || '').replace(/^#/, '');
  for (const part of h.split('&')) {
    const i = part.indexOf('=');
    if (i > 0 && part.slice(0, i) === 'code') return decodeCode(part.slice(i + 1));
  }
  return null;
}

const num = (x) => (Number.isInteger(x) ? String(x) : Math.abs(x) >= 1e-4 && Math.abs(x) < 1e6 ? String(+x.toPrecision(10)) : x.toExponential(6));

/**
 * A readable, bounded text of a value: numbers to 10 significant digits, typed arrays as
 * `Float64Array(400) [0, 0.1, …]`, nested objects indented up to `depth` levels.
 */
/** @param {any} v */
export function formatValue(v, depth = 2, indent = '') {
  if (v === null) return 'null';
  if (v === undefined) return 'undefined';
  if (typeof v === 'number') return num(v);
  if (typeof v === 'string') return indent ? JSON.stringify(v) : v;
  if (typeof v === 'boolean' || typeof v === 'bigint') return String(v);
  if (typeof v === 'function') return `[function ${v.name || 'anonymous'}]`;
  if (v instanceof Error) return `${v.name}: ${v.message}`;
  if (ArrayBuffer.isView(v)) {
    const t = /** @type {Float64Array} */ (v); // (a typed array: a DataView is never formatted)
    const shown = Array.from(t.slice(0, 8), num);
    const extra = Object.keys(v).filter((k) => !/^\d+$/.test(k));
    const props = extra.length ? ` { ${extra.join(', ')} }` : '';
    return `${v.constructor.name}(${t.length}) [${shown.join(', ')}${t.length > 8 ? ', …' : ''}]${props}`;
  }
  const inner = indent + '  ';
  if (Array.isArray(v)) {
    if (v.length === 0) return '[]';
    const flat = v.every((x) => typeof x === 'number');
    if (flat && v.length <= 12) return `[${v.map(num).join(', ')}]`;
    if (depth <= 0) return `Array(${v.length})`;
    if (flat) return `[${v.slice(0, 12).map(num).join(', ')}${v.length > 12 ? `, … (${v.length})` : ''}]`;
    const items = v.slice(0, 8).map((x) => formatValue(x, depth - 1, inner));
    if (items.join(', ').length < 70 && !items.some((s) => s.includes('\n'))) return `[${items.join(', ')}${v.length > 8 ? `, … (${v.length})` : ''}]`;
    return `[\n${items.map((s) => inner + s).join(',\n')}${v.length > 8 ? `,\n${inner}… (${v.length} entries)` : ''}\n${indent}]`;
  }
  if (typeof v === 'object') {
    const keys = Object.keys(v);
    if (keys.length === 0) return '{}';
    if (depth <= 0) return `{ ${keys.slice(0, 6).join(', ')}${keys.length > 6 ? ', …' : ''} }`;
    const lines = keys.slice(0, 40).map((k) => `${inner}${/^[A-Za-z_$][\w$]*$/.test(k) ? k : JSON.stringify(k)}: ${formatValue(v[k], depth - 1, inner)}`);
    return `{\n${lines.join(',\n')}${keys.length > 40 ? `,\n${inner}…` : ''}\n${indent}}`;
  }
  return String(v);
}

/** A render mesh { positions, indices } (the `mesh` of a surface result, or such an object itself), or null. */
export function meshOf(v) {
  if (!v || typeof v !== 'object') return null;
  if (v.positions != null && v.indices != null) return v;
  if (v.mesh && v.mesh.positions != null && v.mesh.indices != null) return v.mesh;
  return null;
}

/** What the sandbox draws for a returned value: 'surface' (a mesh), 'plot' (points / paths / basis), or null. */
export function drawKind(v) {
  if (!v || typeof v !== 'object' || ArrayBuffer.isView(v)) return null;
  if (meshOf(v)) return 'surface';
  if (v.surfaces && typeof v.surfaces === 'object' && Object.values(v.surfaces).some((s) => meshOf(s))) return 'surface';
  if (v.points != null && typeof v.points.length === 'number' && !Array.isArray(v.points[0]?.[0])) return 'plot';
  if (Array.isArray(v.paths)) return 'plot';
  if (v.values != null && v.params != null) return 'plot';
  return null;
}

/**
 * The line and column of the visitor's code in an error's stack, for code loaded from `url` with `offset` lines
 * of wrapper before it; null when no frame of that code is in the stack.
 */
export function codeLocation(stack, url, offset) {
  if (!stack || !url) return null;
  const esc = url.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
  const m = new RegExp(`${esc}:(\\d+):(\\d+)`).exec(String(stack));
  if (!m) return null;
  return { line: Number(m[1]) - offset, column: Number(m[2]) };
}
