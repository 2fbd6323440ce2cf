// SplineLab service worker: after one visit the hosted playground works offline.
//
// Strategy: network first, cache as fallback, for every same-origin GET. Online, each response refreshes the cache,
// so a new build is picked up on the next online visit (nothing stale is served while the network works);
// offline, the cached copy answers. The cache is filled
//   - on install with the two pages and the shell (index.html, embed.html, guide.html, style.css, app.js), and
//   - by the page (www/lib/offline.js) right after it starts: it posts the list of files it loaded (modules of
//     every demo, the wasm module, data), which the page fetched before this worker controlled it.
// Only same-origin URLs inside this worker's scope are cached; the hash (demo and state) is not part of a URL
// the worker sees, so every link state works offline.

const CACHE = 'splinelab-v1';
const SHELL = ['./', 'index.html', 'embed.html', 'guide.html', 'style.css', 'app.js'];
/** This service worker's global scope (`self` in a service worker). */
const sw = /** @type {ServiceWorkerGlobalScope} */ (/** @type {unknown} */ (self));
const scope = () => sw.registration.scope;
const inScope = (url) => url.startsWith(scope()) && !url.includes('/dev/');
/** The cache key: the URL without query (?load= etc.) and hash; './' is index.html. */
const keyOf = (url) => {
  const u = new URL(url);
  u.search = ''; u.hash = '';
  if (u.href === scope()) u.href = new URL('index.html', scope()).href;
  return u.href;
};

async function store(cache, url, response) {
  if (response && response.ok && response.type === 'basic') await cache.put(keyOf(url), response.clone());
  return response;
}

sw.addEventListener('install', (event) => {
  event.waitUntil((async () => {
    const cache = await caches.open(CACHE);
    await Promise.all(SHELL.map(async (p) => {
      const url = new URL(p, scope()).href;
      try { await store(cache, url, await fetch(url, { cache: 'no-cache' })); } catch { /* offline during install */ }
    }));
    await sw.skipWaiting();
  })());
});

sw.addEventListener('activate', (event) => {
  event.waitUntil((async () => {
    for (const k of await caches.keys()) if (k.startsWith('splinelab-') && k !== CACHE) await caches.delete(k);
    await sw.clients.claim();
  })());
});

sw.addEventListener('message', (event) => {
  const d = event.data;
  if (!d || d.type !== 'splinelab:cache' || !Array.isArray(d.urls)) return;
  event.waitUntil((async () => {
    const cache = await caches.open(CACHE);
    const urls = [...new Set(d.urls.filter((u) => typeof u === 'string' && inScope(u)).map(keyOf))];
    let n = 0;
    await Promise.all(urls.map(async (url) => {
      if (await cache.match(url)) { n++; return; }
      try { await store(cache, url, await fetch(url)); n++; } catch { /* ignore */ }
    }));
    event.source?.postMessage({ type: 'splinelab:cached', count: n, total: urls.length });
  })());
});

sw.addEventListener('fetch', (event) => {
  const req = event.request;
  if (req.method !== 'GET' || !inScope(req.url)) return;
  event.respondWith((async () => {
    const cache = await caches.open(CACHE);
    try {
      return await store(cache, req.url, await fetch(req));
    } catch (e) {
      const hit = await cache.match(keyOf(req.url));
      if (hit) return hit;
      throw e;
    }
  })());
});
