// End-to-end harness for SplineLab pages (node:test + playwright-core + Debian chromium).
//
//   import { test, before, after } from 'node:test';
//   import { startHarness } from './harness.mjs';
//   let H; before(async () => { H = await startHarness(); }); after(() => H.close());
//   test('draws', async () => { const t = await H.open('#bspline-basics'); … t.assertClean(); await t.close(); });
//
// The static server (scripts/static-server.mjs) serves www/ on 127.0.0.1 with a free port; one browser per
// test file; every request that does not go to 127.0.0.1 is blocked (by the browser's proxy setting) and recorded (t.outside).

import { chromium } from 'playwright-core';
import { mkdir, access, readFile, appendFile } from 'node:fs/promises';
import { createHash } from 'node:crypto';
import { execFileSync } from 'node:child_process';
import { join, dirname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import assert from 'node:assert/strict';
import { serve } from '../../scripts/static-server.mjs';

export const ROOT = resolve(dirname(fileURLToPath(import.meta.url)), '../..');
export const WWW = join(ROOT, 'www');
export const OUT = join(ROOT, 'tests/e2e/out');

export const CHROMIUM_ARGS = [
  '--headless', '--no-sandbox', '--disable-gpu', '--no-first-run', '--disable-background-networking',
  '--disable-component-update', '--disable-sync', '--disable-quic',
];

// E2E_PROFILE=<file>: every open() appends one JSON line { file, route, fresh (new context), ms } to <file>, so
// a run says where its time goes (page opens dominate the e2e step).
const PROFILE = process.env.E2E_PROFILE || '';
const profileOpen = (route, fresh, ms) => appendFile(PROFILE, `${JSON.stringify({ file: process.argv[1]?.split('/').pop(), route, fresh, ms: Math.round(ms) })}\n`);

const exists = (p) => access(p).then(() => true, () => false);

/** Builds www/pkg (the complete module and one per group, www/lib/wasm-groups.js) with scripts/build-wasm.sh if
 * any is missing (once). */
export async function ensureWasm() {
  const { WASM_GROUPS } = await import(join(WWW, 'lib/wasm-groups.js'));
  const dirs = ['pkg', ...Object.keys(WASM_GROUPS).map((g) => `pkg/${g}`)];
  let all = true;
  for (const d of dirs) all = all && await exists(join(WWW, d, 'splinelab.js')) && await exists(join(WWW, d, 'splinelab_bg.wasm'));
  if (all) return;
  execFileSync(join(ROOT, 'scripts/build-wasm.sh'), [], { cwd: ROOT, stdio: 'inherit' });
}

/** Starts the static server on 127.0.0.1 (free port). Returns { server, base, close() }. */
export async function startServer(dir = WWW) {
  const server = await serve(dir, 0, '127.0.0.1');
  const base = `http://127.0.0.1:${server.address().port}/`;
  return { server, base, close: () => new Promise((ok) => { server.closeAllConnections?.(); server.close(() => ok()); }) };
}

/** Does the demo module www/demos/<id>.js exist? (gallery tests skip demos not written yet) */
export async function demoExists(id) { return exists(join(WWW, 'demos', `${id}.js`)); }

/** The ids listed in www/demos/index.js. */
export async function demoIds() {
  const { DEMO_IDS } = await import(join(WWW, 'demos/index.js'));
  return DEMO_IDS;
}

/**
 * Starts server + browser. Options: { viewport: { width, height }, deviceScaleFactor, reducedMotion, dir, serviceWorkers ('block' by default),
 * warm (the demos' idle warm-up: off by default), fresh (every open in a new browser context: see open(); E2E_FRESH=1 forces it
 * for every file, to tell an isolation problem from a real one) }.
 * Returns { base, browser, open(route, opts), close() }.
 */
export async function startHarness(opts = {}) {
  await ensureWasm();
  const srv = await startServer(opts.dir || WWW); // opts.dir: serve another folder (the built site, dist/site)
  // playwright's launch() starts Chromium with its own fresh temporary --user-data-dir (created with mkdtemp,
  // removed on close); passing --user-data-dir in args is refused by playwright, so it is not repeated here.
  const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    headless: true,
    // every request that does not go to the loopback address goes to a proxy that is a closed port, so it fails at
    // once (Chromium never sends loopback requests through a proxy); wrap() records those requests
    args: [...CHROMIUM_ARGS, '--proxy-server=http://127.0.0.1:9'],
  });
  const pages = new Set();
  // 404s of demo modules that are not written yet are expected (the gallery marks them unavailable)
  const missing = [];
  for (const id of await demoIds()) if (!(await demoExists(id))) missing.push(id);
  const expected = missing.map((id) => new RegExp(`/demos/${id}\\.js$`));

  /**
   * Opens `route` (e.g. '', '#bspline-basics', 'embed.html#bspline-basics?controls=0') and waits until the
   * shell is ready (html[data-ready]) and, for a demo route, until the demo is mounted.
   * opts: { viewport, waitFor (selector), ready (default true), context (reuse a browser context),
   *         reducedMotion ('reduce' | 'no-preference'), warm (the idle warm-up; default off, see below) }
   */
  // Pages share a browser context per set of context options (and so its HTTP cache: the modules and the wasm are
  // fetched, parsed and compiled from the cache after the first open, as for a visitor's second page). Measured
  // with the 11 demos opened 3 times each: 1.28 s and 0.95 s of CPU per open against 1.5 s and 1.13 s with a new
  // context each (load 4-7). Each open clears the origin's localStorage first (the only storage the pages use;
  // sessionStorage is per page), so a page starts as in a fresh context. `{ fresh: true }` (per open, or for the
  // whole harness) gives a new context instead: the files that time a cold start or count requests use it.
  // Context options beyond those (a phone's touch, forced colours) and init scripts (`init`: a function run before
  // the page's scripts, with `initArg`; e.g. storage that throws) are part of that set: the files that opened every
  // demo in a context of their own for those (storage, touch, phone, notation, forced-colors) share one per set too.
  const shared = new Map();   // JSON of the context options → Promise<BrowserContext>
  const EXTRA = ['hasTouch', 'isMobile', 'forcedColors', 'colorScheme'];
  async function newContext(o) {
    const extra = Object.fromEntries(EXTRA.filter((k) => o[k] !== undefined).map((k) => [k, o[k]]));
    const context = await browser.newContext({
      ...extra,
      viewport: o.viewport || opts.viewport || { width: 1280, height: 900 },
      deviceScaleFactor: o.deviceScaleFactor || opts.deviceScaleFactor || 1,
      reducedMotion: o.reducedMotion || opts.reducedMotion || 'no-preference',
      // No service worker unless a test asks for one (offline.test and site.test make their own contexts): in a fresh
      // context the worker installs and precaches every wasm build (2.8 MB) in the background of each open, ~12 % of
      // an open's CPU time (measured by the e2e-speed helper, load 21-25), for nothing a test here looks at.
      serviceWorkers: o.serviceWorkers || opts.serviceWorkers || 'block',
    });
    // No idle warm-up (www/lib/warm.js) unless the harness or the open asks for it ({ warm: true }): it recomputes
    // and redraws the demo up to 24 times after its first frame, with the same pixels (tests/e2e/warm-start.test
    // checks that for every demo), CPU that each of the suite's ~1000 opens paid for nothing a test looks at
    // (curve-networks: open + 20 frames 2.9 s with it, 2.2 s without). The files that time what a person feels
    // (main-thread, startup, blended-interpolation, warm-start) keep it, as a visitor has it. A context passed in
    // by the test is left as the test made it.
    if (!(o.warm ?? opts.warm)) await context.addInitScript(() => { /** @type {any} */ (window).splinelabWarm = 0; });
    if (o.init) await context.addInitScript(o.init, o.initArg);
    return context;
  }
  async function sharedContext(o) {
    const key = JSON.stringify([o.deviceScaleFactor || opts.deviceScaleFactor || 1, o.reducedMotion || opts.reducedMotion || 'no-preference',
      o.serviceWorkers || opts.serviceWorkers || 'block', !!(o.warm ?? opts.warm), ...EXTRA.map((k) => o[k] ?? null),
      o.init ? String(o.init) : null, o.initArg ?? null]);
    if (!shared.has(key)) {
      const made = newContext({ ...o, viewport: undefined });
      shared.set(key, made);
      // a test that closes its page's context (t.context.close()) takes it out of the pool
      made.then((c) => c.on('close', () => { if (shared.get(key) === made) shared.delete(key); }));
    }
    return shared.get(key);
  }
  const origin = srv.base.replace(/\/$/, '');

  /**
   * Opens `route` (e.g. '', '#bspline-basics', 'embed.html#bspline-basics?controls=0') and waits until the
   * shell is ready (html[data-ready]) and, for a demo route, until the demo is mounted.
   * opts: { viewport, waitFor (selector), ready (default true), context (reuse a browser context),
   *         reducedMotion ('reduce' | 'no-preference'), warm (the idle warm-up; default off, see above),
   *         fresh (a new browser context, nothing cached; default: the shared one, see above),
   *         hasTouch, isMobile, deviceScaleFactor, forcedColors, colorScheme (context options),
   *         init, initArg (a script run before the page's own, see above) }
   */
  async function open(route = '', o = {}) {
    const t0 = PROFILE ? performance.now() : 0;
    const fresh = !o.context && !!(o.fresh ?? opts.fresh ?? process.env.E2E_FRESH === '1');
    const context = o.context || (fresh ? await newContext(o) : await sharedContext(o));
    const page = await context.newPage();
    if (!o.context && !fresh) {
      await page.setViewportSize(o.viewport || opts.viewport || { width: 1280, height: 900 });
      const cdp = await context.newCDPSession(page);
      await cdp.send('Storage.clearDataForOrigin', { origin, storageTypes: 'local_storage' });
      await cdp.detach();
    }
    const t = wrap(page, context, fresh);
    pages.add(t);
    await page.goto(srv.base + route.replace(/^\//, ''));
    if (o.ready !== false) await t.ready(o.waitFor);
    if (PROFILE) await profileOpen(route, fresh, performance.now() - t0);
    return t;
  }

  function wrap(page, context, ownContext) {
    const consoleErrors = [];   // { text, url }
    const pageErrors = [];      // Error messages
    const outside = [];         // URLs of blocked requests
    page.on('console', (m) => { if (m.type() === 'error') consoleErrors.push({ text: m.text(), url: m.location()?.url || '' }); });
    page.on('pageerror', (e) => pageErrors.push(String(e && e.stack || e)));
    // Requests that leave 127.0.0.1 are blocked by the browser itself (its proxy, below, is a closed port) and
    // recorded here. Not with context.route(): routing every request through playwright disables the HTTP cache
    // and pauses each of an open's ~60 requests for a round trip to Node (measured: opens took 15-20 % longer).
    const onRequest = (r) => {
      const url = r.url();
      let host = '';
      try { host = new URL(url).hostname; } catch { /* data:, blob: */ }
      if (!(url.startsWith('data:') || url.startsWith('blob:') || host === '127.0.0.1')) outside.push(url);
    };
    // (on the context, so that the page's workers' requests count too; taken off at close: contexts are shared)
    context.on('request', onRequest);

    const t = {
      page, context, consoleErrors, pageErrors, outside, base: srv.base,
      /** Waits for the shell (and the mounted demo, if the URL names one). */
      async ready(selector) {
        await page.waitForFunction(() => document.documentElement.dataset.ready, null, { timeout: 20000 });
        const st = await page.evaluate(() => document.documentElement.dataset.ready);
        if (st !== 'true') throw new Error(`shell did not start: ${await page.textContent('main')}`);
        if (await page.evaluate(() => document.body.dataset.view === 'demo')) {
          await page.waitForSelector('#demo-root[data-mounted="true"]', { timeout: 20000 });
        }
        if (selector) await page.waitForSelector(selector, { timeout: 20000 });
        await t.settled();
        await t.frames(2);
      },
      /** Waits until no demo computes in its worker (www/lib/compute-client.js marks its status line from the
       * request to the shown result): a readout or export read before would be the previous state's or missing. */
      async settled() {
        await page.waitForFunction(() => !document.querySelector('.compute-status[data-computing="true"]'), null, { timeout: 30000, polling: 'raf' });
      },
      /** Waits n animation frames (plots redraw on the next frame). */
      async frames(n = 2) {
        await page.evaluate((k) => new Promise((ok) => { const f = () => (k-- <= 0 ? ok() : requestAnimationFrame(f)); f(); }), n);
      },
      /**
       * Console errors except those matched by `ignore` (array of RegExp tested against text and url) and the
       * 404s of demo modules that do not exist yet; plus uncaught page errors.
       */
      errors(ignore = []) {
        const all = [...ignore, ...expected];
        const bad = consoleErrors.filter((e) => !all.some((r) => r.test(e.text) || r.test(e.url))).map((e) => `${e.text} (${e.url})`);
        return [...bad, ...pageErrors];
      },
      /** Asserts: no console error, no page error, no request outside 127.0.0.1. */
      assertClean(ignore = []) {
        assert.deepEqual(t.errors(ignore), [], 'console/page errors');
        assert.deepEqual(outside, [], 'requests that left 127.0.0.1');
      },
      /** SHA-256 of a canvas' pixels (to check that a drawing changed). Default: the first canvas. */
      async canvasHash(selector = 'canvas') {
        // a result computed in the worker (a loaded machine sends even small work there) is drawn when it is in
        await t.settled();
        await t.frames(2);
        const data = await page.$eval(selector, (c) => c.toDataURL('image/png'));
        return createHash('sha256').update(data).digest('hex');
      },
      /** The plot2d API object of a canvas (evaluated in the page): runs fn(plot, arg) there. */
      async plotEval(selector, fn, arg) {
        return page.$eval(selector, (c, [src, a]) => (0, eval)(`(${src})`)(c.splinePlot, a), [fn.toString(), arg]);
      },
      /** Page coordinates of a world point in a plot2d canvas. */
      async worldToPage(selector, [x, y]) {
        return page.$eval(selector, (c, [wx, wy]) => {
          const r = c.getBoundingClientRect();
          const [sx, sy] = c.splinePlot.toScreen(wx, wy);
          return [r.left + sx, r.top + sy];
        }, [x, y]);
      },
      /** World coordinates of a page point in a plot2d canvas. */
      async pageToWorld(selector, [px, py]) {
        return page.$eval(selector, (c, [x, y]) => { const r = c.getBoundingClientRect(); return c.splinePlot.toWorld(x - r.left, y - r.top); }, [px, py]);
      },
      /** The handles of a plot: [{ name, index, point: [x, y] }]. */
      async handles(selector = 'canvas') {
        return page.$eval(selector, (c) => c.splinePlot.handles());
      },
      /** Drags with the mouse between page coordinates in `steps` moves. */
      async dragScreen([x0, y0], [x1, y1], steps = 8) {
        await page.mouse.move(x0, y0);
        await page.mouse.down();
        for (let i = 1; i <= steps; i++) await page.mouse.move(x0 + (x1 - x0) * i / steps, y0 + (y1 - y0) * i / steps);
        await page.mouse.up();
        await t.settled();
        await t.frames(2);
      },
      /** Drags in world coordinates of the plot2d canvas `selector`. */
      async dragWorld(selector, from, to, steps = 8) {
        const a = await t.worldToPage(selector, from), b = await t.worldToPage(selector, to);
        await page.$eval(selector, (c) => c.scrollIntoView({ block: 'center' }));
        const a2 = await t.worldToPage(selector, from), b2 = await t.worldToPage(selector, to);
        await t.dragScreen(a2 || a, b2 || b, steps);
      },
      /**
       * Synthetic Pointer Events (pointerType 'touch' | 'pen' | 'mouse') along a straight line between two world
       * points of a plot2d canvas: exercises the touch/pen paths that the mouse cannot.
       */
      async pointerDrag(selector, from, to, { pointerType = 'touch', steps = 8, pointerId = 7 } = {}) {
        await page.$eval(selector, (c, [a, b, type, n, id]) => {
          const r = c.getBoundingClientRect();
          const at = (w) => { const [x, y] = c.splinePlot.toScreen(w[0], w[1]); return { clientX: r.left + x, clientY: r.top + y }; };
          const ev = (name, w) => c.dispatchEvent(new PointerEvent(name, { bubbles: true, cancelable: true, pointerId: id, pointerType: type, isPrimary: true, button: 0, buttons: name === 'pointerup' ? 0 : 1, ...at(w) }));
          ev('pointerdown', a);
          for (let i = 1; i <= n; i++) ev('pointermove', [a[0] + (b[0] - a[0]) * i / n, a[1] + (b[1] - a[1]) * i / n]);
          ev('pointerup', b);
        }, [from, to, pointerType, steps, pointerId]);
        await t.settled();
        await t.frames(2);
      },
      /** Synthetic two-finger pinch around a world point: factor > 1 spreads the fingers (zoom in). */
      async pinch(selector, center, factor = 2, steps = 6) {
        await page.$eval(selector, (c, [w, f, n]) => {
          const r = c.getBoundingClientRect();
          const [cx, cy] = c.splinePlot.toScreen(w[0], w[1]);
          const ev = (name, id, dx) => c.dispatchEvent(new PointerEvent(name, { bubbles: true, cancelable: true, pointerId: id, pointerType: 'touch', button: 0, buttons: name === 'pointerup' ? 0 : 1, clientX: r.left + cx + dx, clientY: r.top + cy }));
          ev('pointerdown', 11, -30); ev('pointerdown', 12, 30);
          for (let i = 1; i <= n; i++) { const d = 30 * (1 + (f - 1) * i / n); ev('pointermove', 11, -d); ev('pointermove', 12, d); }
          ev('pointerup', 11, -30 * f); ev('pointerup', 12, 30 * f);
        }, [center, factor, steps]);
        await t.frames(2);
      },
      /** Mouse wheel over a world point (deltaY < 0 zooms in when the plot has focus or ctrl is held). */
      async wheel(selector, at, deltaY, { ctrl = false } = {}) {
        const [x, y] = await t.worldToPage(selector, at);
        await page.mouse.move(x, y);
        if (ctrl) await page.keyboard.down('Control');
        await page.mouse.wheel(0, deltaY);
        if (ctrl) await page.keyboard.up('Control');
        await t.frames(3);
      },
      /**
       * Runs axe-core in the page (injected through the debugging protocol, so the page's CSP stays as it is).
       * Returns the violations with impact in `impacts` (default serious and critical), WCAG 2.2's target size included.
       */
      async axe({ impacts = ['serious', 'critical'] } = {}) {
        if (!(await page.evaluate(() => typeof window.axe === 'object'))) {
          const src = await readFile(join(ROOT, 'node_modules/axe-core/axe.min.js'), 'utf8');
          await page.evaluate(src + '\n;0');
        }
        const res = await page.evaluate(async () => {
          // axe's default rules (WCAG 2.0/2.1 A and AA, best practices) and WCAG 2.2's target size (SC 2.5.8, AA), which
          // axe leaves off by default (issue 25)
          const r = await window.axe.run(document, { resultTypes: ['violations'], rules: { 'target-size': { enabled: true } } });
          return r.violations.map((v) => ({ id: v.id, impact: v.impact, help: v.help, nodes: v.nodes.map((n) => n.target.join(' ')).slice(0, 5) }));
        });
        return res.filter((v) => impacts.includes(v.impact));
      },
      /** Presses keys in order (playwright key names: 'Tab', 'ArrowRight', 'Shift+ArrowUp'). */
      async press(...keys) { for (const k of keys) await page.keyboard.press(k); await t.settled(); await t.frames(2); },
      /** Presses Tab until `selector` has focus (at most `max` times). Returns true if it got there. */
      async tabTo(selector, max = 40) {
        for (let i = 0; i < max; i++) {
          if (await page.evaluate((s) => document.activeElement && document.activeElement.matches(s), selector)) return true;
          await page.keyboard.press('Tab');
        }
        return page.evaluate((s) => document.activeElement && document.activeElement.matches(s), selector);
      },
      /** Text content of the first match (trimmed), or null. */
      async text(selector) { const el = await page.$(selector); return el ? (await el.textContent()).trim() : null; },
      /** Sets a range/number input's value and fires input + change (like a user moving it). */
      async setInput(selector, value) {
        await page.$eval(selector, (el, v) => {
          el.value = String(v);
          el.dispatchEvent(new Event('input', { bubbles: true }));
          el.dispatchEvent(new Event('change', { bubbles: true }));
        }, value);
        // the change may have gone to the compute worker: what a test reads next is the new state's
        await t.settled();
        await t.frames(2);
      },
      /** Writes the demo's pending (debounced) state save to the URL now; returns the hash. */
      async flushState() { await page.evaluate(() => window.splinelab.flush()); return t.hash(); },
      /** The mounted demo's state (a plain copy) or null. */
      async state() { return page.evaluate(() => window.splinelab.current()?.state ?? null); },
      /** Current URL hash. */
      async hash() { return page.evaluate(() => location.hash); },
      /** Waits until the hash satisfies pred(hash) (state saves are debounced). */
      async waitHash(pred = (h) => h.includes('/'), timeout = 5000) {
        const t0 = Date.now();
        for (;;) {
          const hh = await t.hash();
          if (pred(hh)) return hh;
          if (Date.now() - t0 > timeout) throw new Error(`hash did not change as expected: ${hh}`);
          await new Promise((ok) => setTimeout(ok, 50));
        }
      },
      /** Screenshot to tests/e2e/out/<name>.png (full page by default). Returns the path. */
      async screenshot(name, o = {}) {
        await mkdir(OUT, { recursive: true });
        const path = join(OUT, `${name}.png`);
        await t.frames(2);
        if (o.selector) await (await page.$(o.selector)).screenshot({ path });
        else await page.screenshot({ path, fullPage: o.fullPage !== false });
        return path;
      },
      async close() { pages.delete(t); context.off('request', onRequest); if (ownContext) await context.close().catch(() => {}); else await page.close().catch(() => {}); },
    };
    return t;
  }

  return {
    base: srv.base, browser, open, missing,
    async close() {
      for (const t of [...pages]) await t.close();
      for (const c of shared.values()) await (await c).close().catch(() => {});
      await browser.close().catch(() => {});
      await srv.close();
    },
  };
}
