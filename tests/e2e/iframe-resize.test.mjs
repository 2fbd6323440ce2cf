// LMS iframes that size themselves: embed.html in a cross-origin iframe speaks the H5P resizer protocol (as loaded
// by Moodle / WordPress pages for H5P content) and posts { type: 'splinelab:resize', height }. The parent pages
// here are written from the protocol (no H5P code): one plays h5p-resizer (hello → hello, prepareResize →
// resizePrepared, resize → set the height), the other is the guide's short script for pages without H5P.

import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtemp, writeFile, rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { startHarness, startServer } from './harness.mjs';

// the H5P side, from the protocol: answers hello, acknowledges prepareResize, applies resize
const H5P_PARENT = `
window.log = [];
addEventListener('message', (e) => {
  const d = e.data;
  if (!d || d.context !== 'h5p') return;
  const frame = [...document.querySelectorAll('iframe')].find((f) => f.contentWindow === e.source);
  if (!frame) return;
  window.log.push(d.action + (d.scrollHeight !== undefined ? ':' + d.scrollHeight : ''));
  const reply = (action) => e.source.postMessage({ context: 'h5p', action }, '*');
  if (d.action === 'hello') reply('hello');
  else if (d.action === 'prepareResize') { frame.style.height = d.clientHeight + 'px'; reply('resizePrepared'); }
  else if (d.action === 'resize') frame.style.height = d.scrollHeight + 'px';
});
addEventListener('resize', () => { for (const f of document.querySelectorAll('iframe')) f.contentWindow.postMessage({ context: 'h5p', action: 'resize' }, '*'); });
`;

// the guide's parent script (keep in step with www/guide.html)
const PLAIN_PARENT = `
window.log = [];
addEventListener('message', (e) => {
  if (!e.data || e.data.type !== 'splinelab:resize') return;
  for (const f of document.querySelectorAll('iframe')) {
    if (f.contentWindow === e.source) { f.style.height = e.data.height + 'px'; window.log.push(e.data.height); }
  }
});
`;

const page = (script, src, height) => `<!doctype html><html><head><meta charset="utf-8"><title>course page</title><link rel="icon" href="data:,">
<style>body { margin: 0; font: 16px sans-serif } iframe { width: 100%; border: 0; display: block }</style></head>
<body><p>Course text above the figure.</p><iframe id="f" src="${src}" title="SplineLab figure" height="${height}"></iframe>
<p>Course text below.</p><script src="parent.js"></script></body></html>`;

let H, dir, parentSrv;
before(async () => {
  H = await startHarness();
  dir = await mkdtemp(join(tmpdir(), 'splinelab-parent-'));
  parentSrv = await startServer(dir); // another port: another origin, like an LMS page
});
after(async () => {
  await H?.close();
  await parentSrv?.close();
  if (dir) await rm(dir, { recursive: true, force: true });
});

async function openParent(kind, route, height = 150) {
  const sub = join(dir, kind);
  await (await import('node:fs/promises')).mkdir(sub, { recursive: true });
  await writeFile(join(sub, 'parent.js'), kind === 'h5p' ? H5P_PARENT : PLAIN_PARENT);
  await writeFile(join(sub, 'index.html'), page(kind, H.base + route, height));
  const t = await H.open(`../`, { ready: false }); // a page from the harness (its guard and error recording)
  await t.page.goto(`${parentSrv.base}${kind}/index.html`);
  const frame = await (await t.page.waitForSelector('#f')).contentFrame();
  await frame.waitForFunction(() => document.documentElement.dataset.ready === 'true' && !!document.querySelector('#demo-root[data-mounted="true"]'), null, { timeout: 20000 });
  return { t, frame };
}

/** Waits until the iframe's height equals the content height inside it (±1 px); returns [frameHeight, content]. */
async function settled(t, frame, timeout = 10000) {
  const t0 = Date.now();
  for (;;) {
    const fh = await t.page.$eval('#f', (f) => f.getBoundingClientRect().height);
    const ch = await frame.evaluate(() => Math.ceil(document.body.scrollHeight));
    if (Math.abs(fh - ch) <= 1 && ch > 200) return [fh, ch];
    if (Date.now() - t0 > timeout) return [fh, ch];
    await new Promise((ok) => setTimeout(ok, 50));
  }
}

for (const kind of ['h5p', 'plain']) {
  test(`${kind === 'h5p' ? 'H5P resizer protocol' : 'splinelab:resize message'}: the iframe takes the figure's height and follows it`, async () => {
    const { t, frame } = await openParent(kind, 'embed.html#bspline-basics');
    // grows from 150 px to the whole figure: no inner scrollbar
    let [fh, ch] = await settled(t, frame);
    assert.ok(fh > 300, `the iframe grew (${fh} px)`);
    assert.ok(Math.abs(fh - ch) <= 1, `iframe ${fh} px = content ${ch} px`);
    assert.equal(await frame.evaluate(() => document.documentElement.scrollHeight <= innerHeight + 1), true, 'nothing to scroll inside the frame');
    if (kind === 'h5p') {
      const log = await t.page.evaluate(() => window.log);
      assert.equal(log[0], 'hello', `the figure says hello first: ${log.join(' ')}`);
      assert.ok(log.some((x) => x.startsWith('prepareResize:')) && log.some((x) => x.startsWith('resize:')), `prepareResize and resize follow: ${log.join(' ')}`);
    }
    // the figure grows (a panel opens) and shrinks back: the iframe follows both ways
    const before = fh;
    await frame.evaluate(() => { const d = document.createElement('div'); d.id = 'grow'; d.style.height = '400px'; document.getElementById('main').append(d); });
    [fh, ch] = await settled(t, frame);
    assert.ok(Math.abs(fh - (before + 400)) <= 2, `the iframe grew with the figure: ${before} → ${fh} px`);
    await frame.evaluate(() => document.getElementById('grow').remove());
    [fh, ch] = await settled(t, frame);
    assert.ok(Math.abs(fh - before) <= 1, `… and shrank back: ${fh} px`);
    // another demo in the same frame (another height)
    await frame.evaluate(() => { location.hash = '#noisy-data'; });
    await frame.waitForFunction(() => document.body.dataset.demo === 'noisy-data' && !!document.querySelector('#demo-root[data-mounted="true"]'));
    [fh, ch] = await settled(t, frame);
    assert.ok(Math.abs(fh - ch) <= 1 && Math.abs(fh - before) > 20, `another demo: iframe ${fh} px = content ${ch} px (was ${before})`);
    // the parent window narrows (a phone): the figure reflows and the height follows
    await t.page.setViewportSize({ width: 420, height: 800 });
    await frame.evaluate(() => new Promise((ok) => setTimeout(ok, 300)));
    [fh, ch] = await settled(t, frame);
    assert.ok(Math.abs(fh - ch) <= 1, `after a resize of the parent: iframe ${fh} px = content ${ch} px`);
    assert.deepEqual(t.errors(), [], 'no error in the parent or the figure');
    await t.close();
  });
}

test('outside an iframe embed.html posts nothing, and a page that ignores the messages keeps its fixed height', async () => {
  const t = await H.open('embed.html#bspline-basics');
  assert.equal(await t.page.evaluate(() => window.parent === window), true);
  t.assertClean();
  await t.close();
  // a parent without any listener: the iframe keeps its height attribute
  const sub = join(dir, 'none');
  await (await import('node:fs/promises')).mkdir(sub, { recursive: true });
  await writeFile(join(sub, 'parent.js'), '');
  await writeFile(join(sub, 'index.html'), page('none', H.base + 'embed.html#bspline-basics', 480));
  const t2 = await H.open('../', { ready: false });
  await t2.page.goto(`${parentSrv.base}none/index.html`);
  const frame = await (await t2.page.waitForSelector('#f')).contentFrame();
  await frame.waitForFunction(() => document.documentElement.dataset.ready === 'true', null, { timeout: 20000 });
  assert.equal(await t2.page.$eval('#f', (f) => f.getBoundingClientRect().height), 480);
  await t2.close();
});
