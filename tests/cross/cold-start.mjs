// Measures the cold start of dist/splinelab.html from file:// in each engine (not a test): a fresh browser per
// run opens file://…/dist/splinelab.html#bspline-basics; the figure is "up" when the demo is mounted and two frames
// have been drawn. The time is the page's own clock (performance.now(), 0 = navigation start).
//   xvfb-run -a node tests/cross/cold-start.mjs [runs=5] [engines=chromium,firefox,webkit] [hosted]
// With `hosted`, the same demo from www/ over the local static server (for comparison).

import { pathToFileURL } from 'node:url';
import { stat } from 'node:fs/promises';
import { gzipSync } from 'node:zlib';
import { readFile } from 'node:fs/promises';
import { LAUNCH } from './engines.mjs';
import { DIST } from './smoke.mjs';

const runs = Number(process.argv[2] || 5);
const engines = (process.argv[3] || 'chromium,firefox,webkit').split(',');
const hosted = process.argv[4] === 'hosted';
let srv = null;
if (hosted) srv = await (await import('../e2e/harness.mjs')).startServer();
const url = hosted ? `${srv.base}index.html#bspline-basics` : `${pathToFileURL(DIST).href}#bspline-basics`;
if (hosted) console.log('hosted www/ over http://127.0.0.1');
const size = (await stat(DIST)).size;
console.log(`dist/splinelab.html: ${(size / 1024).toFixed(1)} KB, ${(gzipSync(await readFile(DIST)).length / 1024).toFixed(1)} KB gzip`);

function upAt() {
  return new Promise((ok) => {
    const poll = () => {
      if (document.querySelector('#demo-root[data-mounted="true"]')) requestAnimationFrame(() => requestAnimationFrame(() => ok(performance.now())));
      else requestAnimationFrame(poll);
    };
    poll();
  });
}

for (const name of engines) {
  const times = [];
  for (let i = 0; i < runs; i++) {
    const E = await LAUNCH[name]();
    try {
      await E.goto(url);
      times.push(await E.eval(upAt));
    } finally { await E.close(); }
  }
  times.sort((a, b) => a - b);
  console.log(`${name}: median ${times[times.length >> 1].toFixed(0)} ms, min ${times[0].toFixed(0)} ms (${times.map((t) => t.toFixed(0)).join(', ')})`);
}
await srv?.close();
