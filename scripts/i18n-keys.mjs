// Lists the texts SplineLab asks its catalogues for (www/lib/i18n.js t() and tn()), page by page, and which of
// them each language's catalogue lacks: what a translator works from. It opens the pages in headless Chromium
// in English, presses what shows more text (the steppers' steps, the Share panel), and reads the page's
// splinelab.i18n.askedKeys(); each catalogue (www/lang/<code>.js) is then read in Node.
//
//   node scripts/i18n-keys.mjs [routes]            e.g. '#,#bspline-basics' (default: the gallery and every demo)
//   node scripts/i18n-keys.mjs --json out.json     writes { texts: [...], plurals: { other: one }, missing: { sk: [...] } }
//
// The end-to-end check (tests/e2e/i18n.test.mjs) is what fails on an English text in a page; this is a tool.

import { writeFileSync } from 'node:fs';
import { pathToFileURL } from 'node:url';
import { join } from 'node:path';
import { startHarness, ROOT } from '../tests/e2e/harness.mjs';
import { DEMO_IDS } from '../www/demos/index.js';

const args = process.argv.slice(2);
const jsonAt = args.indexOf('--json');
const jsonOut = jsonAt >= 0 ? args.splice(jsonAt, 2)[1] : null;
const routes = args[0] ? args[0].split(',') : ['#', ...DEMO_IDS.map((id) => `#${id}`)];

const H = await startHarness();
const texts = new Set();
const plurals = {};
/** @type {Map<string, string[]>} route → the texts it asked for */
const perRoute = new Map();
try {
  for (const route of routes) {
    const t = await H.open(route, { viewport: { width: 1366, height: 900 } });
    const p = t.page;
    if (await p.$('.share-toggle')) await p.click('.share-toggle');
    // every stepper, every step; then each choice of every radio group (e.g. a stepper's algorithm), and the
    // steppers again
    const stepAll = async () => {
      for (const st of await p.$$('section.stepper')) {
        const n = Number(await st.getAttribute('data-steps')) || 0;
        for (let i = 0; i < n; i++) { const b = await st.$('.step-forward'); if (b && await b.isEnabled()) await b.click(); }
      }
    };
    await stepAll();
    for (const r of await p.$$('fieldset.ctl-group input[type=radio]')) {
      if (await r.isEnabled() && await r.isVisible().catch(() => false)) { await r.check({ force: true }).catch(() => {}); }
    }
    await stepAll();
    // a point chosen and moved with the keyboard (the plot's announcements, the point's fields)
    const canvas = await p.$('canvas.plot-canvas');
    if (canvas) { await canvas.focus(); await p.keyboard.press('PageDown'); await p.keyboard.press('ArrowRight'); await p.waitForTimeout(400); }
    const k = await p.evaluate(() => window.splinelab.i18n.askedKeys());
    for (const s of k.texts) texts.add(s);
    Object.assign(plurals, k.plurals);
    perRoute.set(route, [...k.texts, ...Object.keys(k.plurals)]);
    await t.close();
  }
} finally { await H.close(); }

const missing = {};
for (const code of ['sk', 'ro', 'hu', 'it']) {
  const cat = (await import(pathToFileURL(join(ROOT, `www/lang/${code}.js`)).href)).default;
  missing[code] = [...texts].filter((s) => !Object.hasOwn(plurals, s) && typeof cat[s] !== 'string')
    .concat(Object.keys(plurals).filter((s) => typeof cat[s] !== 'object'));
}
const out = { texts: [...texts].filter((s) => !Object.hasOwn(plurals, s)), plurals, missing };
if (jsonOut) writeFileSync(jsonOut, `${JSON.stringify(out, null, 1)}\n`);
for (const [code, m] of Object.entries(missing)) console.log(`${code}: ${m.length} of ${out.texts.length + Object.keys(plurals).length} texts missing`);
// page by page (the texts each page asks for that the Slovak catalogue lacks)
const skMissing = new Set(missing.sk);
for (const [route, asked] of perRoute) console.log(`  ${route.padEnd(24)} ${asked.filter((s) => skMissing.has(s)).length} of ${new Set(asked).size} missing in sk`);
