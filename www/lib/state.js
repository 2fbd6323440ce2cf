// Demo state ↔ URL hash, validation against the demo's defaults, and the last good state in localStorage.
//
// Hash format: `#<demo-id>/<payload>[?opt=val&…]`. payload = `v1.` + base64url(deflate-raw(JSON)) when the
// browser has CompressionStream, else `v0.` + base64url(UTF-8 JSON). Both versions are always readable.
// A payload is untrusted input: size-limited, parsed with JSON.parse only, then validated against defaults().

export const MAX_DECODED_BYTES = 64 * 1024;
export const MAX_PAYLOAD_CHARS = 200 * 1024;
const MAX_DEPTH = 8;
const MAX_STRING = 4096;
const ID_RE = /^[a-z0-9][a-z0-9-]{0,63}$/;

export class StateError extends Error {}

// ---------- base64url ----------
export function toBase64Url(bytes) {
  let s = '';
  for (let i = 0; i < bytes.length; i += 0x8000) s += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
  return btoa(s).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

export function fromBase64Url(str) {
  if (!/^[A-Za-z0-9_-]*$/.test(str)) throw new StateError('the link contains characters that are not base64url');
  const b64 = str.replace(/-/g, '+').replace(/_/g, '/') + '==='.slice((str.length + 3) % 4);
  let bin;
  try { bin = atob(b64); } catch { throw new StateError('the link data is not valid base64'); }
  const out = new Uint8Array(bin.length);
  for (let i = 0; i < bin.length; i++) out[i] = bin.charCodeAt(i);
  return out;
}

// ---------- (de)compression ----------
const hasCompression = typeof CompressionStream === 'function' && typeof DecompressionStream === 'function';

async function deflateRaw(bytes) {
  const cs = new CompressionStream('deflate-raw');
  const stream = new Blob([bytes]).stream().pipeThrough(cs);
  return new Uint8Array(await new Response(stream).arrayBuffer());
}

/** Inflates with a hard cap on the output size (a zip bomb stops at MAX_DECODED_BYTES + 1). */
async function inflateRaw(bytes, limit = MAX_DECODED_BYTES) {
  const ds = new DecompressionStream('deflate-raw');
  const reader = new Blob([bytes]).stream().pipeThrough(ds).getReader();
  const chunks = [];
  let total = 0;
  try {
    for (;;) {
      const { done, value } = await reader.read();
      if (done) break;
      total += value.length;
      if (total > limit) {
        reader.cancel().catch(() => {});
        throw new StateError(`the link's state is larger than ${Math.round(limit / 1024)} KB`);
      }
      chunks.push(value);
    }
  } catch (e) {
    if (e instanceof StateError) throw e;
    throw new StateError('the link data is not valid compressed data');
  }
  const out = new Uint8Array(total);
  let o = 0;
  for (const c of chunks) { out.set(c, o); o += c.length; }
  return out;
}

/** Encodes a JSON-able state to a hash payload (`v1.…` compressed, or `v0.…` if the browser cannot compress). */
export async function encodeState(state) {
  const bytes = new TextEncoder().encode(JSON.stringify(state));
  if (hasCompression) {
    try { return 'v1.' + toBase64Url(await deflateRaw(bytes)); } catch { /* fall through */ }
  }
  return 'v0.' + toBase64Url(bytes);
}

/** Decodes a payload to a plain value (not yet validated). Throws StateError with a readable reason. */
export async function decodeState(payload) {
  if (typeof payload !== 'string' || payload.length === 0) throw new StateError('the link has no state');
  if (payload.length > MAX_PAYLOAD_CHARS) throw new StateError('the link is too long');
  const dot = payload.indexOf('.');
  const version = dot > 0 ? payload.slice(0, dot) : '';
  const body = payload.slice(dot + 1);
  let bytes;
  if (version === 'v1') {
    if (!hasCompression) throw new StateError('this browser cannot read compressed links');
    bytes = await inflateRaw(fromBase64Url(body));
  } else if (version === 'v0') {
    bytes = fromBase64Url(body);
  } else {
    throw new StateError(`unknown link format "${version.slice(0, 12)}"`);
  }
  if (bytes.length > MAX_DECODED_BYTES) throw new StateError(`the link's state is larger than ${MAX_DECODED_BYTES / 1024} KB`);
  let json;
  try { json = new TextDecoder('utf-8', { fatal: true }).decode(bytes); } catch { throw new StateError('the link data is not UTF-8 text'); }
  try { return JSON.parse(json); } catch { throw new StateError('the link data is not valid JSON'); }
}

// ---------- validation ----------
const kind = (v) => (v === null ? 'null' : Array.isArray(v) ? 'array' : typeof v);

function checkPlain(v, path, depth) {
  if (depth > MAX_DEPTH) throw new StateError(`${path}: nested too deeply`);
  const k = kind(v);
  if (k === 'number') { if (!Number.isFinite(v)) throw new StateError(`${path}: not a finite number`); return v; }
  if (k === 'string') { if (v.length > MAX_STRING) throw new StateError(`${path}: string too long`); return v; }
  if (k === 'boolean' || k === 'null') return v;
  if (k === 'array') return v.map((x, i) => checkPlain(x, `${path}[${i}]`, depth + 1));
  if (k === 'object') {
    const out = {};
    for (const [key, x] of Object.entries(v)) {
      if (key === '__proto__' || key === 'constructor' || key === 'prototype') continue;
      out[key] = checkPlain(x, `${path}.${key}`, depth + 1);
    }
    return out;
  }
  throw new StateError(`${path}: unsupported value`);
}

function validateAgainst(value, def, path, depth) {
  if (depth > MAX_DEPTH) throw new StateError(`${path}: nested too deeply`);
  const dk = kind(def), vk = kind(value);
  if (dk === 'null') return checkPlain(value, path, depth); // default null: any plain JSON value (e.g. optional number)
  if (dk !== vk) throw new StateError(`${path}: expected ${dk}, got ${vk}`);
  switch (dk) {
    case 'number':
      if (!Number.isFinite(value)) throw new StateError(`${path}: not a finite number`);
      return value;
    case 'string':
      if (value.length > MAX_STRING) throw new StateError(`${path}: string too long`);
      return value;
    case 'boolean':
      return value;
    case 'array': {
      if (def.length === 0) return checkPlain(value, path, depth);
      const tmpl = def[0];
      // point lists (the default is a list of [x, y] or [x, y, z] number tuples, all of one length) keep that
      // length; other nested number arrays may vary in length
      const tupleLen = (tmpl.length === 2 || tmpl.length === 3) && def.length >= 2
        && def.every((d) => Array.isArray(d) && d.length === tmpl.length && d.every((x) => typeof x === 'number'))
        ? tmpl.length : -1;
      return value.map((x, i) => {
        if (tupleLen >= 0 && (!Array.isArray(x) || x.length !== tupleLen)) {
          throw new StateError(`${path}[${i}]: expected ${tupleLen} numbers`);
        }
        return validateAgainst(x, tmpl, `${path}[${i}]`, depth + 1);
      });
    }
    case 'object': {
      const out = {};
      for (const key of Object.keys(def)) {
        out[key] = Object.prototype.hasOwnProperty.call(value, key)
          ? validateAgainst(value[key], def[key], `${path}.${key}`, depth + 1)
          : structuredClone(def[key]);
      }
      return out; // unknown keys dropped
    }
    default:
      throw new StateError(`${path}: unsupported value`);
  }
}

/**
 * Validates `value` against `defaults`: same keys and types (recursively; arrays checked element-wise
 * against the default's first element; a default list of at least two [x, y] (or [x, y, z]) tuples makes every
 * element a tuple of that length; a default `[]` or `null` accepts any plain JSON), numbers finite, unknown keys
 * dropped, missing keys filled from the defaults (so old links keep working). Throws StateError.
 */
export function validateState(value, defaults) {
  if (kind(value) !== 'object') throw new StateError('the state is not an object');
  return validateAgainst(value, defaults, 'state', 0);
}

// ---------- hash ----------
/**
 * Parses `#<id>/<payload>?<options>` (every part optional). Returns `{ id, payload, params }` where params
 * is a URLSearchParams of the options after `?`. An id that is not `[a-z0-9-]` is returned as null.
 */
export function parseHash(hash) {
  let s = String(hash || '').replace(/^#/, '');
  let params = new URLSearchParams();
  const q = s.indexOf('?');
  if (q >= 0) { params = new URLSearchParams(s.slice(q + 1)); s = s.slice(0, q); }
  const slash = s.indexOf('/');
  let id = slash >= 0 ? s.slice(0, slash) : s;
  const payload = slash >= 0 ? s.slice(slash + 1) : '';
  try { id = decodeURIComponent(id); } catch { id = ''; }
  return { id: ID_RE.test(id) ? id : (id ? null : ''), payload, params };
}

/** Builds `#<id>/<payload>?<options>`. */
export function buildHash(id, payload, params) {
  const q = params && [...params].length ? '?' + params.toString() : '';
  return `#${id}${payload ? '/' + payload : ''}${q}`;
}

// ---------- last good state ----------
// localStorage may throw on access (storage blocked for third-party iframes, some private modes) or on write
// (quota full). The page then works on from the link alone: every failure is reported once per page through
// the `splinelab:storage` window event ({ detail: { reason: 'blocked' | 'full', error } }) and storageStatus(),
// so the shell can say that saving is off (www/lib/storage-notice.js) instead of losing work silently.
const key = (id) => `splinelab:last:${id}`;
let storageProblem = null; // null | 'blocked' | 'full'

/** null when saving works (or was not tried yet), else 'blocked' or 'full'. */
export function storageStatus() { return storageProblem; }

function storageFailed(e, writing) {
  const name = e && e.name;
  const full = writing && (name === 'QuotaExceededError' || name === 'NS_ERROR_DOM_QUOTA_REACHED' || e?.code === 22 || e?.code === 1014);
  const reason = full ? 'full' : 'blocked';
  if (storageProblem === reason) return;
  storageProblem = reason;
  try { window.dispatchEvent(new CustomEvent('splinelab:storage', { detail: { reason, error: String(e?.message || e) } })); } catch { /* no window */ }
}

/** The storage object, or null (with the failure reported) when even reading it throws. */
function store() {
  try { return window.localStorage || null; } catch (e) { storageFailed(e, false); return null; }
}

/** Tries a tiny write (at start-up, so the notice comes before any work is done). Returns storageStatus(). */
export function probeStorage() {
  const ls = store();
  if (!ls) return storageProblem;
  try { ls.setItem('splinelab:probe', '1'); ls.removeItem('splinelab:probe'); } catch (e) { storageFailed(e, true); }
  return storageProblem;
}

/** Saves the last good state of `id`. Returns true when it was saved. */
export function saveLast(id, state) {
  const ls = store();
  if (!ls) return false;
  try {
    ls.setItem(key(id), JSON.stringify(state));
    if (storageProblem) { storageProblem = null; window.dispatchEvent(new CustomEvent('splinelab:storage', { detail: { reason: null } })); }
    return true;
  } catch (e) { storageFailed(e, true); return false; }
}

/** The last good state saved for `id`, validated against defaults, or null. */
export function loadLast(id, defaults) {
  const ls = store();
  if (!ls) return null;
  try {
    const raw = ls.getItem(key(id));
    if (!raw || raw.length > MAX_DECODED_BYTES) return null;
    return validateState(JSON.parse(raw), defaults);
  } catch (e) {
    if (!(e instanceof StateError) && !(e instanceof SyntaxError)) storageFailed(e, false);
    return null;
  }
}

export function clearLast(id) {
  const ls = store();
  try { ls?.removeItem(key(id)); } catch { /* ignore */ }
}

/** Deep equality of two plain JSON values. */
export function sameState(a, b) {
  return JSON.stringify(a) === JSON.stringify(b);
}
