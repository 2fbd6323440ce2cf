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

function fileFor(path) {
  if (path.startsWith('/__peer/')) {
    const name = path.slice('/__peer/'.length);
    if (name === 'jsxgraph.html') return join(HERE, 'pages/jsxgraph.html');
    if (name === 'jsxgraphcore.js' || name === 'jsxgraph.css') return join(JSX, name);
    return null;
  }
  const f = normalize(join(WWW, path));
  return f.startsWith(WWW) ? f : null;
}

/** Serves www/ and the peer on 127.0.0.1 (free port). gzip: compress responses (default true). */
export async function serveBench({ gzip = true, port = 0 } = {}) {
  const cache = new Map(); // file → { mtime, gz }
  const server = createServer(async (req, res) => {
    try {
      const path = decodeURIComponent(new URL(req.url, 'http://x').pathname);
      let file = fileFor(path);
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
  });
  await new Promise((ok) => server.listen(port, '127.0.0.1', ok));
  const base = `http://127.0.0.1:${server.address().port}/`;
  return { base, close: () => new Promise((ok) => { server.closeAllConnections?.(); server.close(() => ok()); }) };
}

// `node benches/start-jsxgraph.mjs [port]`: serve www/ and the peer with gzip, to look at them by hand
if (import.meta.url === `file://${process.argv[1]}`) {
  const s = await serveBench({ port: Number(process.argv[2] || 0) });
  console.log(`SplineLab: ${s.base}   peer: ${s.base}${PEER.route}`);
}
