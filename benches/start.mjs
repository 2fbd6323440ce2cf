// Start-up (issues 8 and 13): cold navigation → first drawing for the gallery and every demo, side by side with a
// JSXGraph page drawing a cardinal spline through 7 points (benches/start-jsxgraph.mjs), in the same headless
// Chromium run, on loopback and over emulated links, gzip-served.
//
// Usage: node benches/start.mjs [demo-id …]     (after scripts/build-wasm.sh and `cd benches && npm ci --ignore-scripts`)
//   RUNS=5               navigations per page and link (medians reported; ≥ 5)
//   LINKS=loopback,4g,3g  which links (4g: 100 ms round trip, 4 Mbit/s; 3g: 300 ms, 1.6 Mbit/s; CDP
//                        Network.emulateNetworkConditions: the latency is added to every response)
//   GZIP=0               serve uncompressed          JSON=file   also write every sample to a file
//   SITE=both            source (www/ as it is), built (dist/site/, scripts/build-site.mjs) or both side by side
//                        (default: both when dist/site/ exists, else source)
//   STATE_LINKS=0        leave out the state-link rows (default: one per demo, see below)
//   H2=1                 also serve the sites and the peer over HTTP/2 (TLS, a throwaway self-signed certificate,
//                        Chromium with --ignore-certificate-errors) as extra columns; H2=only: HTTP/2 alone.
//                        HTTP/1.1 (Chromium: 6 connections per host) stays the default and the reference
//
// Cold: every navigation is a new browser context (empty HTTP cache, no V8 code cache) with the cache disabled
// through CDP (Network.setCacheDisabled). The pages are visited in interleaved order (run 1: peer, gallery, demo 1,
// …; run 2: the same, rotated) so that the machine's load affects all of them alike.
//
// First drawing (ms from navigation start, the page's own performance.now()):
//   SplineLab demo  the second animation frame after #demo-root[data-mounted="true"]: the demo's plots and 3D
//                   views paint in the first animation frame after mounting (www/lib/plot2d.js, view3d.js), so the
//                   first drawing is on screen by then and the handles accept input
//   gallery         the second animation frame after <html data-ready="true"> (the cards are in the DOM)
//   peer            the second animation frame after JSXGraph created the board, the points and the spline
//                   (JSXGraph draws into SVG synchronously)
//   state link      "<id> (link)": the same demo opened as a course page embeds it, embed.html#<id>/<payload>
//                   with a saved non-default state (STATE_LINK below, encoded by www/lib/state.js as the page's
//                   Share panel does); the page must show that state (checked after each navigation: no
//                   damaged-link notice, the mounted state's payload is the link's), else the navigation fails
// Also reported: requests and bytes on the wire (CDP Network events), when the wasm request started and ended
// (Resource Timing).
import { chromium } from 'playwright-core';
import { writeFileSync, existsSync } from 'node:fs';
import { join } from 'node:path';
import { machine, median, demoIds, demoExists, CHROMIUM_ARGS, ROOT } from './common.mjs';
import { serveBench, PEER } from './start-jsxgraph.mjs';

const RUNS = Number(process.env.RUNS || 5);
const LINKS = {
  loopback: null,
  '4g': { latency: 100, downloadThroughput: 4e6 / 8, uploadThroughput: 4e6 / 8 },
  '3g': { latency: 300, downloadThroughput: 1.6e6 / 8, uploadThroughput: 1.6e6 / 8 },
};
const links = (process.env.LINKS || 'loopback,4g,3g').split(',').filter((l) => l in LINKS);
const only = process.argv.slice(2);
if (!PEER.available()) { console.error('the peer is missing: cd benches && npm ci --ignore-scripts'); process.exit(1); }

// readiness marks only (no export timing, no extra imports: the page loads exactly what it loads for a visitor)
function marks() {
  const M = (window.__start = {});
  const raf = window.requestAnimationFrame.bind(window);
  const twoFrames = (name) => raf(() => raf(() => { M[name] = M[name] || performance.now(); }));
  const check = () => {
    if (document.documentElement.dataset.ready === 'true' && !M.ready) { M.ready = performance.now(); twoFrames('readyFrame'); }
    if (document.documentElement.dataset.ready === 'error') M.error = true;
    const root = document.getElementById('demo-root');
    if (root && root.dataset.mounted === 'true' && !M.mounted) { M.mounted = performance.now(); twoFrames('mountedFrame'); }
  };
  new MutationObserver(check).observe(document, { subtree: true, attributes: true, attributeFilter: ['data-ready', 'data-mounted'] });
}

const ids = only.length ? only : ['', ...(await demoIds()).filter(demoExists)];

// Non-default states, one per demo, as a teacher would share them (a moved point, another parameter or view); the
// bench encodes defaults() overlaid with these exactly as the Share panel does (www/lib/state.js encodeState)
const STATE_LINK = {
  'bspline-basics': { points: [[0, 0], [1, 2.2], [2.4, 3.1], [3.4, 0.6], [4.6, 0.2], [5.4, 2.4], [6.6, 1.8]], u: 0.7 },
  'interp-approx': { a: 0.1 },
  'noisy-data': { count: 80, sigma: 0.3, seed: 2 },
  'b2-surfaces': { a: 0.1, shape: 'hill' },
  'quasi-cubic-curves': { alpha: 0.8, u: 0.3 },
  'blended-interpolation': { beta: [1, 1, 2, 1, 1, 1, 1], selected: 2 },
  'quasi-cubic-surfaces': { alpha: 0.5, beta: 2.2 },
  'curve-networks': { show: { S: true, T: false, G: false, GB: true } },
  'criss-cross-basis': { i: 2, j: 1, cell: [2, 1] },
  'bezier-remodel': { points: [[11, 15], [7, 21], [3, 9], [0, 0], [-4, 0], [-8, 0], [-6, 3], [-4, 6], [2, 2], [8, -2], [10, 3]] },
  'knot-modification': { p: 4, up: 2 },
};
const { encodeState } = await import(join(ROOT, 'www/lib/state.js'));
/** `<id>/<payload>` of the demo's state link (defaults() overlaid with STATE_LINK[id]; a demo without an entry:
 * its first point moved by 0.25 in x, or its first number + 0.1). */
async function stateLink(id) {
  const mod = await import(join(ROOT, 'www/demos', `${id}.js`));
  const st = { ...mod.defaults(), ...(STATE_LINK[id] || {}) };
  if (!STATE_LINK[id]) {
    if (Array.isArray(st.points) && Array.isArray(st.points[0])) st.points[0][0] += 0.25;
    else { const k = Object.keys(st).find((x) => typeof st[x] === 'number'); if (k) st[k] += 0.1; }
  }
  return `${id}/${await encodeState(st)}`;
}
const withLinks = process.env.STATE_LINKS !== '0';
const links0 = {};
if (withLinks) for (const id of ids.filter(Boolean)) links0[id] = await stateLink(id);
const BUILT = join(ROOT, 'dist/site');
const siteArg = process.env.SITE || (existsSync(join(BUILT, 'app.js')) ? 'both' : 'source');
const sites = { source: ['source', 'both'].includes(siteArg), built: ['built', 'both'].includes(siteArg) };
if (sites.built && !existsSync(join(BUILT, 'app.js'))) { console.error('dist/site/ is missing: node scripts/build-site.mjs'); process.exit(1); }
const protos = process.env.H2 === 'only' ? ['h2'] : process.env.H2 === '1' ? ['h1', 'h2'] : ['h1'];
const m = machine();
const gzip = process.env.GZIP !== '0';
// one server per site and protocol; the peer is served by each protocol's first server
const servers = {};
for (const proto of protos) {
  for (const site of ['source', 'built']) {
    if (sites[site]) servers[`${site} ${proto}`] = await serveBench({ gzip, root: site === 'built' ? BUILT : undefined, http2: proto === 'h2' });
  }
}
const variants = Object.keys(servers); // e.g. 'source h1', 'built h1', 'built h2'
const targets = [];
for (const proto of protos) {
  const peerSrv = variants.find((v) => v.endsWith(proto));
  targets.push({ name: `JSXGraph (peer) ${proto}`, page: 'JSXGraph (peer)', variant: `peer ${proto}`, proto, base: servers[peerSrv].base, route: PEER.route, peer: true });
  for (const v of variants.filter((x) => x.endsWith(proto))) {
    for (const id of ids) targets.push({ name: `${id || 'gallery'} ${v}`, page: id || 'gallery', variant: v, proto, base: servers[v].base, route: id ? `#${id}` : '', demo: !!id });
    for (const id of Object.keys(links0)) {
      targets.push({ name: `${id} (link) ${v}`, page: `${id} (link)`, variant: v, proto, base: servers[v].base, route: `embed.html#${links0[id]}`, demo: true, payload: links0[id].slice(id.length + 1) });
    }
  }
}
const browser = await chromium.launch({ executablePath: process.env.CHROMIUM || '/usr/bin/chromium', headless: true,
  args: [...CHROMIUM_ARGS, ...(protos.includes('h2') ? ['--ignore-certificate-errors'] : [])] });

async function once(t, link) {
  const context = await browser.newContext({ viewport: { width: 1280, height: 900 }, ignoreHTTPSErrors: true });
  await context.addInitScript(marks);
  const page = await context.newPage();
  const cdp = await context.newCDPSession(page);
  await cdp.send('Network.enable');
  await cdp.send('Network.setCacheDisabled', { cacheDisabled: true });
  if (LINKS[link]) await cdp.send('Network.emulateNetworkConditions', { offline: false, ...LINKS[link] });
  let requests = 0, bytes = 0;
  cdp.on('Network.requestWillBeSent', (e) => { if (!e.request.url.startsWith('data:')) requests++; });
  cdp.on('Network.loadingFinished', (e) => { bytes += e.encodedDataLength; });
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(t.base + t.route, { waitUntil: 'commit' });
  try {
    await page.waitForFunction(([peer, demo]) => (peer ? window.__peerFirstDrawing
      : window.__start && (window.__start.error || (demo ? window.__start.mountedFrame : window.__start.readyFrame))),
    [!!t.peer, !!t.demo], { timeout: Number(process.env.TIMEOUT || 120000), polling: 50 });
  } catch (e) {
    // say where it stopped: the shell's state, the marks, the resources that arrived, page errors
    const st = await page.evaluate(() => JSON.stringify({ ready: document.documentElement.dataset.ready, marks: window.__start,
      mounted: document.getElementById('demo-root')?.dataset.mounted, main: document.querySelector('main')?.textContent.slice(0, 80),
      arrived: performance.getEntriesByType('resource').length })).catch((x) => String(x));
    await context.close();
    throw new Error(`${e.message.split('\n')[0]} — ${st}; page errors: ${errors.join('; ') || 'none'}`);
  }
  if (t.payload) {
    // the link's state is what the page shows (not the defaults after a damaged-link notice)
    const shown = await page.evaluate(() => ({ bad: document.body.dataset.badLink === 'true', payload: window.splinelab?.current()?.payload }));
    if (shown.bad || shown.payload !== t.payload) { await context.close(); throw new Error(`${t.name}: the page did not open the link's state (${JSON.stringify(shown).slice(0, 120)})`); }
  }
  const r = await page.evaluate(([peer, demo]) => {
    const S = window.__start || {};
    const w = performance.getEntriesByType('resource').find((e) => e.name.endsWith('.wasm'));
    return { first: peer ? window.__peerFirstDrawing : demo ? S.mountedFrame : S.readyFrame, error: !!S.error,
      wasmStart: w ? w.startTime : NaN, wasmEnd: w ? w.responseEnd : NaN };
  }, [!!t.peer, !!t.demo]);
  await new Promise((ok) => setTimeout(ok, 50)); // let the last loadingFinished events arrive
  await context.close();
  if (r.error || errors.length) throw new Error(`${t.name}: ${errors.join('; ') || 'the engine did not start'}`);
  return { ...r, requests, bytes };
}

const samples = {}; // link → name → [sample]
for (let run = 0; run < RUNS; run++) {
  for (const link of links) {
    for (let k = 0; k < targets.length; k++) {
      const t = targets[(k + run) % targets.length];
      let r;
      try { r = await once(t, link); } catch (e) {
        // a navigation that does not finish in 120 s (seen once at load 44) is counted, not fatal
        process.stderr.write(`${link} ${t.name}: ${String(e.message || e).split('\n')[0]}\n`);
        r = { first: NaN, failed: true, requests: NaN, bytes: NaN, wasmStart: NaN, wasmEnd: NaN };
      }
      ((samples[link] ??= {})[t.name] ??= []).push(r);
    }
  }
  process.stderr.write(`run ${run + 1}/${RUNS} done\n`);
  if (process.env.JSON) writeFileSync(process.env.JSON, JSON.stringify({ machine: m, runs: run + 1, links, samples }, null, 1));
}
await browser.close();
for (const s of Object.values(servers)) await s.close();

console.log(`start-up: cold navigation → first drawing, headless Chromium (--disable-gpu), 1280×900, ${process.env.GZIP === '0' ? 'uncompressed' : 'gzip-served'}; median (min) of ${RUNS} — ${m.date}`);
console.log(`machine: ${m.cpus} CPUs, load ${m.load} at the start, ${machine().load} at the end; ${m.lscpu}; ${m.chromium}`);
const f0 = (x) => (Number.isFinite(x) ? x.toFixed(0) : '—');
const summary = [];
const linkRatios = {}; // 'link|label' → [[page, ratio, ms]] of the state-link rows
const side = {}; // link → page → variant → ratio
for (const link of links) {
  const L = LINKS[link];
  for (const proto of protos) {
    const peerT = targets.find((t) => t.peer && t.proto === proto);
    const peer = median(samples[link][peerT.name].filter((x) => !x.failed).map((x) => x.first));
    for (const v of variants.filter((x) => x.endsWith(proto))) {
      const label = `${v.startsWith('built') ? 'built site (dist/site)' : 'source (www/)'}, ${proto === 'h2' ? 'HTTP/2' : 'HTTP/1.1'}`;
      console.log(`\n${link}${L ? ` (${L.latency} ms added per response, ${(L.downloadThroughput * 8 / 1e6).toFixed(1)} Mbit/s)` : ' (no emulation)'} — ${label}`);
      console.log(`${'page'.padEnd(30)} ${'first drawing ms'.padStart(17)} ${'÷ peer'.padStart(7)}  requests   KB on the wire   wasm request start → end ms`);
      const ratios = [];
      for (const t of [peerT, ...targets.filter((x) => x.variant === v)]) {
        const all = samples[link][t.name], xs = all.filter((x) => !x.failed);
        if (!xs.length) { console.log(`${t.page.padEnd(30)} every navigation failed`); continue; }
        const med = (k) => median(xs.map((x) => x[k]));
        const first = med('first'), ratio = first / peer;
        if (t.demo && !t.payload) ratios.push([t.page, ratio, first]);
        if (t.payload) (linkRatios[`${link}|${label}`] ??= []).push([t.page, ratio, first]);
        if (!t.peer) ((side[link] ??= {})[t.page] ??= {})[v] = ratio;
        console.log(`${t.page.padEnd(30)} ${`${f0(first)} (${f0(Math.min(...xs.map((x) => x.first)))})`.padStart(17)} ${ratio.toFixed(2).padStart(7)}  ${String(med('requests')).padStart(8)}   ${(med('bytes') / 1024).toFixed(1).padStart(14)}   ${f0(med('wasmStart'))} → ${f0(med('wasmEnd'))}${all.length > xs.length ? `   (${all.length - xs.length} of ${all.length} timed out)` : ''}`);
      }
      if (ratios.length) {
        const worst = ratios.reduce((a, b) => (b[1] > a[1] ? b : a));
        const over = ratios.filter((r) => r[1] > 1).length;
        const lr = linkRatios[`${link}|${label}`] || [];
        if (lr.length) {
          const w = lr.reduce((a, b) => (b[1] > a[1] ? b : a));
          summary.push(`${link}, ${label}, state links (embed.html): ${f0(Math.min(...lr.map((r) => r[2])))}–${f0(Math.max(...lr.map((r) => r[2])))} ms; ratio ${Math.min(...lr.map((r) => r[1])).toFixed(2)}–${w[1].toFixed(2)}× (worst ${w[0]}); ${lr.filter((r) => r[1] > 1).length} of ${lr.length} over 1.0×`);
        }
        summary.push(`${link}, ${label}: demos ${f0(Math.min(...ratios.map((r) => r[2])))}–${f0(Math.max(...ratios.map((r) => r[2])))} ms vs peer ${f0(peer)} ms; ratio ${Math.min(...ratios.map((r) => r[1])).toFixed(2)}–${worst[1].toFixed(2)}× (worst ${worst[0]}); ${over} of ${ratios.length} over 1.0×`);
      }
    }
  }
}
if (variants.length > 1) {
  console.log(`\nside by side: first drawing ÷ the peer's (same link, same protocol, same run)`);
  for (const link of links) {
    console.log(`\n${link.padEnd(30)} ${variants.map((v) => v.padStart(11)).join(' ')}`);
    for (const [page, r] of Object.entries(side[link] || {})) console.log(`${page.padEnd(30)} ${variants.map((v) => (r[v] ? `${r[v].toFixed(2)}×` : '—').padStart(11)).join(' ')}`);
  }
}
console.log('\ntarget ≤ 1.0× the peer for every demo:');
for (const s of summary) console.log('  ' + s);
if (process.env.JSON) writeFileSync(process.env.JSON, JSON.stringify({ machine: m, runs: RUNS, links, samples }, null, 1));
