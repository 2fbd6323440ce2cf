// The yardstick of benches/start.mjs (issue 13) and the bench's own server.
//
// Peer: benches/pages/jsxgraph.html, a JSXGraph board with a cardinal spline through 7 draggable points, using npm
// `jsxgraph` (a benches-only dependency: `cd benches && npm ci --ignore-scripts`). Its files are served from
// benches/ under /__peer/ by the same server and the same gzip as SplineLab's www/, never from www/ itself.
//
// Server: www/ at /, the peer at /__peer/, `cache-control: no-cache`, gzip (level 6, like a default nginx/Apache
// `gzip on`) for text, JS and wasm when the request accepts it. Compressed bodies are cached in memory, so the
// compression is not part of what is measured.
import { createServer } from 'node:http';
import { createSecureServer } from 'node:http2';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { readFile, stat } from 'node:fs/promises';
import { existsSync } from 'node:fs';
import { gzipSync } from 'node:zlib';
import { extname, join, normalize, resolve, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';

const HERE = dirname(fileURLToPath(import.meta.url));
export const WWW = resolve(process.env.WWW_DIR || join(HERE, '../www')); // WWW_DIR: measure another copy (e.g. a baseline)
const JSX = join(HERE, 'node_modules/jsxgraph/distrib');

export const PEER = {
  name: 'JSXGraph 1.13.3 (cardinal spline, 7 points)',
  route: '__peer/jsxgraph.html',
  /** true when the page's first drawing is on screen (set by the page itself: the second frame after drawing) */
  drawn: () => window.__peerFirstDrawing,
  available: () => existsSync(join(JSX, 'jsxgraphcore.js')),
};

const TYPES = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript; charset=utf-8', '.mjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8', '.wasm': 'application/wasm', '.json': 'application/json', '.svg': 'image/svg+xml',
  '.png': 'image/png', '.csv': 'text/csv',
};
const COMPRESS = new Set(['.html', '.js', '.mjs', '.css', '.wasm', '.json', '.svg', '.csv']);

function fileFor(path, WWW) {
  if (path.startsWith('/__peer/')) {
    const name = path.slice('/__peer/'.length);
    if (name === 'jsxgraph.html') return join(HERE, 'pages/jsxgraph.html');
    if (name === 'jsxgraphcore.js' || name === 'jsxgraph.css') return join(JSX, name);
    return null;
  }
  const f = normalize(join(WWW, path));
  return f.startsWith(WWW) ? f : null;
}

/**
 * Serves www/ (or `root`, e.g. the built site dist/site) and the peer on 127.0.0.1 (free port). gzip: compress
 * responses (default true).
 */
export async function serveBench({ gzip = true, port = 0, root = WWW, http2 = false } = {}) {
  const cache = new Map(); // file → { mtime, gz }
  const handler = async (req, res) => {
    try {
      const path = decodeURIComponent(new URL(req.url, 'http://x').pathname);
      let file = fileFor(path, resolve(root));
      if (!file) { res.writeHead(403).end(); return; }
      const st = await stat(file).catch(() => null);
      if (st?.isDirectory()) file = join(file, 'index.html');
      const body = await readFile(file);
      const ext = extname(file);
      const headers = { 'content-type': TYPES[ext] || 'application/octet-stream', 'cache-control': 'no-cache' };
      let out = body;
      if (gzip && COMPRESS.has(ext) && /\bgzip\b/.test(req.headers['accept-encoding'] || '')) {
        const key = file, mtime = st?.mtimeMs ?? 0;
        let c = cache.get(key);
        if (!c || c.mtime !== mtime) { c = { mtime, gz: gzipSync(body, { level: 6 }) }; cache.set(key, c); }
        out = c.gz;
        headers['content-encoding'] = 'gzip';
        headers.vary = 'accept-encoding';
      }
      headers['content-length'] = out.length;
      res.writeHead(200, headers);
      res.end(out);
    } catch {
      res.writeHead(404, { 'content-type': 'text/plain' }).end('not found');
    }
  };
  // http2: HTTP/2 over TLS with a throwaway self-signed certificate made now (the browser needs
  // --ignore-certificate-errors); the real hosts teachers use speak HTTP/2, this bench's default is HTTP/1.1
  const server = http2 ? createSecureServer({ ...selfSigned(), allowHTTP1: false }, handler) : createServer(handler);
  const sessions = new Set();
  server.on(http2 ? 'session' : 'connection', (s) => { sessions.add(s); s.on('close', () => sessions.delete(s)); });
  await new Promise((ok) => server.listen(port, '127.0.0.1', ok));
  const base = `${http2 ? 'https' : 'http'}://127.0.0.1:${server.address().port}/`;
  return { base, close: () => new Promise((ok) => { for (const s of sessions) s.destroy(); server.close(() => ok()); }) };
}

/** A self-signed certificate for 127.0.0.1, valid one day, made with the openssl CLI in a temporary folder. */
function selfSigned() {
  const dir = mkdtempSync(join(tmpdir(), 'sl-cert-'));
  try {
    execFileSync('openssl', ['req', '-x509', '-newkey', 'ec', '-pkeyopt', 'ec_paramgen_curve:prime256v1', '-nodes',
      '-subj', '/CN=127.0.0.1', '-addext', 'subjectAltName=IP:127.0.0.1', '-days', '1',
      '-keyout', join(dir, 'k.pem'), '-out', join(dir, 'c.pem')], { stdio: 'ignore' });
    return { key: readFileSync(join(dir, 'k.pem')), cert: readFileSync(join(dir, 'c.pem')) };
  } finally { rmSync(dir, { recursive: true, force: true }); }
}

// `node benches/start-jsxgraph.mjs [port]`: serve www/ and the peer with gzip, to look at them by hand
if (import.meta.url === `file://${process.argv[1]}`) {
  const s = await serveBench({ port: Number(process.argv[2] || 0) });
  console.log(`SplineLab: ${s.base}   peer: ${s.base}${PEER.route}`);
}
