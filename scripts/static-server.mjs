// A tiny static file server for the playground (no dependencies): node scripts/static-server.mjs DIR PORT
//
// It sends what a host of SplineLab must send so that course pages on OTHER origins can use the playground
// (the <spline-lab> element loads module scripts, the .wasm file, style.css and data/*.json with CORS):
//   Access-Control-Allow-Origin: *            module scripts, fetch() of wasm/json/css across origins
//   Cross-Origin-Resource-Policy: cross-origin pages that isolate themselves (COEP) may still load the files
//   Content-Type: application/wasm for .wasm  WebAssembly.instantiateStreaming refuses anything else
//   Content-Type: text/javascript for .js/.mjs module scripts refuse other types
// serve(dir, port, host, { cors: false }) leaves the CORS headers out (tests of the failure path use it).
import { createServer } from 'node:http';
import { readFile, stat } from 'node:fs/promises';
import { extname, isAbsolute, join, normalize, relative, resolve, sep } from 'node:path';

export const TYPES = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript; charset=utf-8', '.mjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8', '.wasm': 'application/wasm', '.json': 'application/json', '.svg': 'image/svg+xml',
  '.png': 'image/png', '.ico': 'image/x-icon', '.md': 'text/plain; charset=utf-8', '.csv': 'text/csv; charset=utf-8',
  '.txt': 'text/plain; charset=utf-8', '.map': 'application/json', '.obj': 'text/plain; charset=utf-8',
  '.jpg': 'image/jpeg', '.jpeg': 'image/jpeg', '.webp': 'image/webp', '.woff2': 'font/woff2',
};

/** The cross-origin headers every response carries (unless `cors` is false). */
export const CORS_HEADERS = {
  'access-control-allow-origin': '*',
  'cross-origin-resource-policy': 'cross-origin',
  'timing-allow-origin': '*',
};

/**
 * Is `file` (an absolute, normalised path) inside `root` or `root` itself? By the relative path from the root, not
 * by a string prefix: `/srv/www-secret/key.txt` starts with `/srv/www` but is outside it (a request for
 * `/..%2fwww-secret/key.txt` decodes to exactly that).
 */
export function insideRoot(root, file) {
  const rel = relative(root, file);
  return rel === '' || (!isAbsolute(rel) && rel !== '..' && !rel.startsWith(`..${sep}`));
}

export function serve(dir, port = 0, host = '127.0.0.1', { cors = true } = {}) {
  const root = resolve(dir);
  const extra = cors ? CORS_HEADERS : {};
  const server = createServer(async (req, res) => {
    if (req.method === 'OPTIONS') {
      // a CORS preflight (not needed for plain GETs, but cheap to answer)
      res.writeHead(204, { ...extra, 'access-control-allow-methods': 'GET, HEAD, OPTIONS', 'access-control-max-age': '86400' }).end();
      return;
    }
    try {
      const path = decodeURIComponent(new URL(req.url, 'http://x').pathname);
      let file = normalize(join(root, path));
      if (!insideRoot(root, file)) { res.writeHead(403, extra).end(); return; }
      if ((await stat(file).catch(() => null))?.isDirectory()) file = join(file, 'index.html');
      const st = await stat(file);
      // a validator: the browser asks again every time (no-cache: an edited file is seen on the next load) and
      // gets 304 for a file that has not changed, so it keeps its cached copy and its compiled code
      const etag = `"${st.size.toString(36)}-${Math.floor(st.mtimeMs).toString(36)}"`;
      const head = {
        ...extra,
        'content-type': TYPES[extname(file).toLowerCase()] || 'application/octet-stream',
        'x-content-type-options': 'nosniff',
        'cache-control': 'no-cache',
        etag,
      };
      if (req.headers['if-none-match'] === etag) { res.writeHead(304, head).end(); return; }
      const body = await readFile(file);
      res.writeHead(200, head);
      res.end(req.method === 'HEAD' ? undefined : body);
    } catch {
      res.writeHead(404, { ...extra, 'content-type': 'text/plain; charset=utf-8' }).end('not found');
    }
  });
  return new Promise((ok) => server.listen(port, host, () => ok(server)));
}

if (import.meta.url === `file://${process.argv[1]}`) {
  const [dir = 'www', port = '8080'] = process.argv.slice(2);
  serve(dir, Number(port)).then((s) => console.log(`serving ${dir} on http://127.0.0.1:${s.address().port}/`));
}
