// One small driver interface over three browser engines for the cross-engine smoke suite (tests/cross/).
//
//   firefox  Debian firefox-esr driven by npm puppeteer-core over WebDriver BiDi (no geckodriver)
//   webkit   Debian webkit2gtk-driver (WebKitWebDriver + MiniBrowser) driven by npm webdriverio (classic WebDriver)
//   chromium Debian chromium driven by puppeteer-core (CDP) — only for comparing numbers; CI covers Chromium with
//            the playwright e2e suite
//
// Firefox and WebKit run headful so that WebGL2 is real: run the suite under `xvfb-run -a` (scripts/test.sh does).
// Interface: { name, goto(url), eval(fn, ...args), waitFor(fn, arg, timeout), mouseDrag([x0, y0], [x1, y1], steps),
//             press(...keys), setViewport(w, h), close() }. Keys use the names 'ArrowRight', 'ArrowUp', 'Tab', 'PageDown' (the next point of a 2D plot).

import { spawn } from 'node:child_process';
import { createServer } from 'node:net';

export const FIREFOX = process.env.FIREFOX || '/usr/bin/firefox-esr';
export const MINIBROWSER = process.env.MINIBROWSER || '/usr/lib/x86_64-linux-gnu/webkit2gtk-4.1/MiniBrowser';
export const WEBKIT_DRIVER = process.env.WEBKIT_DRIVER || 'WebKitWebDriver';
export const CHROMIUM = process.env.CHROMIUM || '/usr/bin/chromium';

const sleep = (ms) => new Promise((ok) => setTimeout(ok, ms));

export function freePort() {
  return new Promise((ok, bad) => {
    const s = createServer();
    s.on('error', bad);
    s.listen(0, '127.0.0.1', () => { const p = s.address().port; s.close(() => ok(p)); });
  });
}

/** Serialises fn so every engine evaluates the same source: (fn)(...args). */
const callSrc = (fn) => `return (${fn.toString()}).apply(null, arguments)`;

async function puppeteerEngine(name, launchOpts) {
  const { default: puppeteer } = await import('puppeteer-core');
  const browser = await puppeteer.launch(launchOpts);
  const page = (await browser.pages())[0] || await browser.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e?.message || e)));
  page.on('console', (m) => { if (m.type() === 'error') errors.push(`console: ${m.text()}`); });
  await page.setViewport({ width: 1280, height: 900 });
  const KEY = { ArrowRight: 'ArrowRight', ArrowLeft: 'ArrowLeft', ArrowUp: 'ArrowUp', ArrowDown: 'ArrowDown', Tab: 'Tab', PageDown: 'PageDown', PageUp: 'PageUp' };
  return {
    name, errors,
    async goto(url) { await page.goto(url, { waitUntil: 'load' }); },
    eval: (fn, ...args) => page.evaluate(fn, ...args),
    /** Runs a script's source in the page (by the driver, so the page's CSP does not apply). */
    run: (src) => page.evaluate(`${src}\n;0`),
    async waitFor(fn, arg, timeout = 20000) { await page.waitForFunction(fn, { timeout, polling: 50 }, arg); },
    async mouseDrag([x0, y0], [x1, y1], steps = 8) {
      await page.mouse.move(x0, y0);
      await page.mouse.down();
      for (let i = 1; i <= steps; i++) await page.mouse.move(x0 + (x1 - x0) * i / steps, y0 + (y1 - y0) * i / steps);
      await page.mouse.up();
    },
    async press(...keys) { for (const k of keys) await page.keyboard.press(KEY[k] || k); },
    async setViewport(width, height) { await page.setViewport({ width, height }); },
    async close() { await browser.close().catch(() => {}); },
  };
}

export function launchFirefox() {
  return puppeteerEngine('firefox', {
    browser: 'firefox', executablePath: FIREFOX, headless: false, protocol: 'webDriverBiDi',
    extraPrefsFirefox: { 'browser.download.useDownloadDir': true, 'browser.download.dir': '/tmp', 'browser.download.folderList': 2 },
  });
}

export function launchChromium() {
  return puppeteerEngine('chromium', {
    browser: 'chrome', executablePath: CHROMIUM, headless: true,
    args: ['--no-sandbox', '--no-first-run', '--disable-background-networking', '--disable-component-update'],
  });
}

export async function launchWebKit() {
  const { remote } = await import('webdriverio');
  const port = await freePort();
  const driver = spawn(WEBKIT_DRIVER, [`--port=${port}`], { stdio: ['ignore', 'ignore', 'pipe'] });
  let driverLog = '';
  driver.stderr.on('data', (d) => { driverLog = (driverLog + d).slice(-4000); });
  // wait for the driver to listen
  for (let i = 0; ; i++) {
    const up = await fetch(`http://127.0.0.1:${port}/status`).then((r) => r.ok, () => false);
    if (up) break;
    if (i > 100) { driver.kill(); throw new Error(`WebKitWebDriver did not start: ${driverLog}`); }
    await sleep(100);
  }
  let b;
  try {
    b = await remote({
      hostname: '127.0.0.1', port, path: '/', logLevel: 'error', connectionRetryCount: 1,
      capabilities: { 'webkitgtk:browserOptions': { binary: MINIBROWSER, args: ['--automation'] } },
    });
  } catch (e) { driver.kill(); throw e; }
  const errors = []; // classic WebDriver has no console events: the suite reads window.__errors (see smoke.mjs)
  const KEY = { ArrowRight: '\uE014', ArrowLeft: '\uE012', ArrowUp: '\uE013', ArrowDown: '\uE015', Tab: '\uE004', PageDown: '\uE00F', PageUp: '\uE00E' };
  const api = {
    name: 'webkit', errors,
    async goto(url) { await b.url(url); },
    eval: (fn, ...args) => b.execute(callSrc(fn), ...args),
    /** Runs a script's source in the page (by the driver, so the page's CSP does not apply). */
    run: (src) => b.execute(`${src}\n;return 0;`),
    async waitFor(fn, arg, timeout = 20000) {
      await b.waitUntil(() => b.execute(callSrc(fn), arg), { timeout, interval: 50, timeoutMsg: `waitFor timed out: ${fn}` });
    },
    async mouseDrag([x0, y0], [x1, y1], steps = 8) {
      const r = Math.round;
      let a = b.action('pointer', { parameters: { pointerType: 'mouse' } }).move({ x: r(x0), y: r(y0), origin: 'viewport', duration: 0 }).down({ button: 0 });
      for (let i = 1; i <= steps; i++) a = a.move({ x: r(x0 + (x1 - x0) * i / steps), y: r(y0 + (y1 - y0) * i / steps), origin: 'viewport', duration: 20 });
      await a.up({ button: 0 }).perform();
    },
    async press(...keys) { for (const k of keys) await b.keys([KEY[k] || k]); },
    async setViewport(width, height) {
      // MiniBrowser's window has chrome around the page: size the window so the page viewport matches
      await b.setWindowSize(width, height);
      const [iw, ih] = await b.execute('return [innerWidth, innerHeight]');
      await b.setWindowSize(width + (width - iw), height + (height - ih));
    },
    async close() { await b.deleteSession().catch(() => {}); driver.kill(); },
  };
  return api;
}

export const LAUNCH = { firefox: launchFirefox, webkit: launchWebKit, chromium: launchChromium };
