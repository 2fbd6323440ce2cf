// Reflow, text spacing and zoom (WCAG 2.2 SC 1.4.10, 1.4.12, 1.4.4) over the gallery, three demos (one 3D) and
// the exercises page. One open per page, three looks at it:
//   - 320×256 CSS px (1280×1024 at 400 %): the page does not scroll sideways (only what needs two dimensions may:
//     a canvas, a figure table's scroller), and no text is cut off (an element with overflow hidden and text
//     wider or taller than its box);
//   - WCAG's text spacing (line height 1.5, paragraphs 2em apart, letters 0.12em, words 0.16em, !important):
//     still nothing cut off, and no two texts of the controls and readouts overlap;
//   - 200 % zoom (683×450 at device scale 2, what 1366×900 at 200 % is): every control of the demo can be
//     scrolled to and is the element under its own centre (not covered), nothing cut off.
// Run: node --test tests/e2e/reflow.test.mjs   (SHOTS=1 writes tests/e2e/out/reflow-*.png)
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { writeFileSync } from 'node:fs';
import { startHarness, OUT } from './harness.mjs';

let H;
before(async () => { H = await startHarness(); });
after(async () => { await H?.close(); });

const PAGES = ['', '#blended-interpolation', '#knot-modification', '#b2-surfaces', 'exercises.html'];

const SPACING = `*, *::before, *::after { line-height: 1.5 !important; letter-spacing: 0.12em !important; word-spacing: 0.16em !important; }
p { margin-bottom: 2em !important; }`;

/** In the page: what scrolls the page sideways, and the texts cut off by their boxes (short descriptions). */
function layoutFaults() {
  const W = document.documentElement.clientWidth;
  const shown = (el) => el.getClientRects().length && getComputedStyle(el).visibility !== 'hidden';
  const name = (el) => `${el.tagName.toLowerCase()}${el.id ? `#${el.id}` : ''}${el.className && typeof el.className === 'string' ? `.${el.className.trim().split(/\s+/).join('.')}` : ''} "${(el.textContent || '').trim().slice(0, 30)}"`;
  // a box that scrolls or clips (a figure's table scroller, the controls sheet) holds what is in it
  const held = (el) => {
    for (let p = el.parentElement; p && p !== document.body; p = p.parentElement) {
      const s = getComputedStyle(p);
      if (s.overflowX !== 'visible' || s.position === 'fixed') return true;
    }
    return false;
  };
  const wide = [];
  if (document.documentElement.scrollWidth > W + 1) {
    for (const el of document.body.querySelectorAll('*')) {
      if (!shown(el) || el.closest('canvas, svg, .visually-hidden')) continue;
      const r = el.getBoundingClientRect();
      if (r.right > W + 1 && !held(el)) wide.push(`${name(el)} reaches ${Math.round(r.right)} px`);
    }
    if (!wide.length) wide.push(`the page is ${document.documentElement.scrollWidth} px wide`);
  }
  const cut = [];
  for (const el of document.body.querySelectorAll('*')) {
    if (!shown(el) || el.closest('.visually-hidden, [aria-hidden="true"], canvas')) continue;
    const s = getComputedStyle(el);
    if (s.clip !== 'auto' || s.clipPath !== 'none' || el.clientWidth <= 2) continue;   // visually hidden on purpose
    const text = [...el.childNodes].some((n) => n.nodeType === 3 && n.textContent.trim());
    if (!text) continue;
    const hidX = s.overflowX === 'hidden' || s.overflowX === 'clip', hidY = s.overflowY === 'hidden' || s.overflowY === 'clip';
    if ((hidX && el.scrollWidth > el.clientWidth + 1) || (hidY && el.scrollHeight > el.clientHeight + 1)) {
      // a text cut on purpose with its whole one click away: a shown button that unfolds it (the demo summary's More)
      const unfold = el.id && document.querySelector(`[aria-controls="${el.id}"][aria-expanded="false"]`);
      if (unfold && shown(unfold) && !unfold.hidden) continue;
      cut.push(`${name(el)}: text ${el.scrollWidth}×${el.scrollHeight} in a box of ${el.clientWidth}×${el.clientHeight}`);
    }
  }
  return { wide, cut };
}

/** In the page: pairs of texts in the controls and readouts whose boxes overlap. */
function overlaps() {
  const boxes = [];
  for (const el of document.querySelectorAll('.demo-controls *, .exercise *, .gallery *')) {
    if (!el.getClientRects().length || el.closest('.visually-hidden, [aria-hidden="true"]')) continue;
    if (![...el.childNodes].some((n) => n.nodeType === 3 && n.textContent.trim())) continue;
    const range = document.createRange();
    for (const n of el.childNodes) {
      if (n.nodeType !== 3 || !n.textContent.trim()) continue;
      range.selectNodeContents(n);
      for (const r of range.getClientRects()) if (r.width > 1 && r.height > 1) boxes.push({ el, r, t: n.textContent.trim().slice(0, 24) });
    }
  }
  const out = [];
  for (let i = 0; i < boxes.length && out.length < 5; i++) {
    for (let j = i + 1; j < boxes.length; j++) {
      const a = boxes[i].r, b = boxes[j].r;
      // (the glyphs of one formula are placed by the browser's MathML layout, which letter spacing does not widen)
      if (boxes[i].el === boxes[j].el || (boxes[i].el.closest('math') && boxes[i].el.closest('math') === boxes[j].el.closest('math'))) continue;
      const w = Math.min(a.right, b.right) - Math.max(a.left, b.left), h = Math.min(a.bottom, b.bottom) - Math.max(a.top, b.top);
      if (w > 2 && h > 2) out.push(`"${boxes[i].t}" and "${boxes[j].t}" overlap by ${Math.round(w)}×${Math.round(h)} px`);
    }
  }
  return out;
}

/** In the page: the demo's controls that cannot be scrolled to and clicked (another element over their centre). */
function unreachable() {
  const out = [];
  const handle = document.querySelector('.drawer-handle');
  for (const el of document.querySelectorAll('.demo-controls input, .demo-controls button, .demo-controls select, .demo-controls summary, .demo-actions button, .demo-actions a')) {
    // (inside a closed disclosure a control is not shown: its summary is what is reached)
    if (!el.getClientRects().length || el === handle || el.parentElement?.closest('details:not([open])') && !el.matches('details:not([open]) > summary')) continue;
    el.scrollIntoView({ block: 'center', inline: 'center', behavior: 'instant' });
    const r = el.getBoundingClientRect();
    // a checkbox or radio drawn by its label: the label counts
    const target = el.matches('input[type=radio], input[type=checkbox]') && el.labels?.[0]?.getClientRects().length ? el.labels[0] : el;
    const t = target.getBoundingClientRect();
    const x = t.left + t.width / 2, y = t.top + t.height / 2;
    const hit = document.elementFromPoint(x, y);
    if (!(hit && (target.contains(hit) || hit.contains(target) || el.contains(hit) || hit === el.labels?.[0]))) {
      out.push(`${el.tagName.toLowerCase()} "${el.getAttribute('aria-label') || el.labels?.[0]?.textContent?.trim() || el.textContent.trim()}" at (${Math.round(r.left)}, ${Math.round(r.top)}) is under ${hit ? `${hit.tagName.toLowerCase()}.${hit.className}` : 'nothing'}`.slice(0, 160));
    }
  }
  return out;
}

for (const route of PAGES) {
  test(`reflow at 320 px, text spacing, 200 % zoom: ${route || 'the gallery'}`, async () => {
    const t = await H.open(route, { viewport: { width: 320, height: 256 } });
    const shot = async (what) => { if (process.env.SHOTS) await t.page.screenshot({ path: `${OUT}/reflow-${(route || 'gallery').replace(/\W+/g, '')}-${what}.png` }); };
    await t.frames(2);
    await shot('320');
    const at320 = await t.page.evaluate(layoutFaults);
    assert.deepEqual(at320.wide, [], `${route}: at 320 px nothing scrolls the page sideways`);
    assert.deepEqual(at320.cut, [], `${route}: at 320 px no text is cut off`);

    // (a constructed style sheet: the site's CSP refuses an inline <style>, as it should a bookmarklet's)
    await t.page.evaluate((css) => { const sh = new CSSStyleSheet(); sh.replaceSync(css); document.adoptedStyleSheets = [...document.adoptedStyleSheets, sh]; /** @type {any} */ (window).spacingSheet = sh; }, SPACING);
    await t.frames(3);
    await shot('spacing');
    const spaced = await t.page.evaluate(layoutFaults);
    assert.deepEqual(spaced.cut, [], `${route}: with WCAG's text spacing no text is cut off`);
    assert.deepEqual(spaced.wide, [], `${route}: with WCAG's text spacing nothing scrolls the page sideways`);
    assert.deepEqual(await t.page.evaluate(overlaps), [], `${route}: with WCAG's text spacing no texts overlap`);

    // 200 %: the same page at 683×450 CSS px, device scale 2 (the CDP override: no second open)
    const cdp = await t.context.newCDPSession(t.page);
    await cdp.send('Emulation.setDeviceMetricsOverride', { width: 683, height: 450, deviceScaleFactor: 2, mobile: false });
    await t.page.evaluate(() => { document.adoptedStyleSheets = document.adoptedStyleSheets.filter((sh) => sh !== /** @type {any} */ (window).spacingSheet); });
    await t.frames(3);
    const zoomed = await t.page.evaluate(layoutFaults);
    assert.deepEqual(zoomed.cut, [], `${route}: at 200 % no text is cut off`);
    assert.deepEqual(zoomed.wide, [], `${route}: at 200 % nothing scrolls the page sideways`);
    assert.deepEqual(await t.page.evaluate(unreachable), [], `${route}: at 200 % every control can be reached`);
    // (through CDP: playwright's own screenshot puts its viewport back)
    if (process.env.SHOTS) writeFileSync(`${OUT}/reflow-${(route || 'gallery').replace(/\W+/g, '')}-200.png`, Buffer.from((await cdp.send('Page.captureScreenshot')).data, 'base64'));
    t.assertClean();
    await t.close();
  });
}

test('a demo summary that a short screen cuts has a More button that shows it whole (SC 1.4.4, 1.4.10)', async () => {
  const t = await H.open('#knot-modification', { viewport: { width: 683, height: 450 }, deviceScaleFactor: 2 });
  const look = () => t.page.evaluate(() => {
    const p = document.querySelector('.demo-summary'), b = document.querySelector('.summary-more');
    const r = b.getBoundingClientRect();
    return { cut: p.scrollHeight > p.clientHeight + 1, shown: !b.hidden && r.width > 0, expanded: b.getAttribute('aria-expanded'), label: b.textContent, w: r.width, h: r.height };
  });
  let s = await look();
  assert.ok(s.cut && s.shown && s.expanded === 'false' && s.label === 'More', `at 200 %: cut with More shown (${JSON.stringify(s)})`);
  assert.ok(s.h >= 24 && s.w >= 24, `More is a 24 px target (${s.w}×${s.h})`);
  await t.page.click('.summary-more');
  s = await look();
  assert.ok(!s.cut && s.expanded === 'true' && s.label === 'Less', `More shows the whole summary (${JSON.stringify(s)})`);
  await t.page.click('.summary-more');
  s = await look();
  assert.ok(s.cut && s.expanded === 'false', `Less folds it again (${JSON.stringify(s)})`);
  // a tall screen shows the whole summary and no button (no extra Tab stop)
  await t.page.setViewportSize({ width: 1366, height: 900 });
  await t.page.waitForFunction(() => document.querySelector('.summary-more').hidden, null, { timeout: 5000 }).catch(() => {});
  s = await look();
  assert.ok(!s.cut && !s.shown, `1366×900: whole, no More (${JSON.stringify(s)})`);
  t.assertClean();
  await t.close();
});
