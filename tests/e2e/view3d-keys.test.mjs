// The 3D views from the keyboard (issue 25, "the 3D views are a trap"): in every demo with a 3D view (found on
// the demo pages, not listed by hand) the view is one Tab stop (Tab enters it, the next Tab leaves it, Shift+Tab
// likewise), a keyboard rotation is said in words once (not every key), N selects a draggable point and the live
// region names it by its paper name, and in b2-surfaces and curve-networks the selected point's fields move it
// like a drag (state, link, undo), with a message naming the field for a non-number.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startHarness, demoIds } from './harness.mjs';

const IGNORE = [/GPU stall due to ReadPixels/];
let H;
before(async () => { H = await startHarness(); });
after(async () => { await H?.close(); });

/** Marks the first 3D view of the page (showing its tab first when it sits in a hidden "Surface" tab); false when none. */
async function markView(t) {
  const has = await t.page.evaluate(() => !!document.querySelector('canvas.sl-view3d-canvas'));
  if (!has) return false;
  const hidden = await t.page.evaluate(() => !document.querySelector('canvas.sl-view3d-canvas').getClientRects().length);
  if (hidden) {
    await t.page.getByRole('radio', { name: /^Surface/ }).first().evaluate((el) => /** @type {HTMLElement} */ (el).click());
    await t.settled();
    await t.frames(3);
  }
  await t.page.evaluate(() => {
    const c = [...document.querySelectorAll('canvas.sl-view3d-canvas')].find((e) => e.getClientRects().length);
    c.id = 'v3d';
    c.closest('.sl-view3d').querySelector('[aria-live]').id = 'v3d-live';
    c.scrollIntoView({ block: 'center' });
  });
  return true;
}

/** Where the focus is: 'view' (the canvas), 'inside' (elsewhere in the view, e.g. its fields) or 'outside'. */
const focusAt = (t) => t.page.evaluate(() => {
  const a = document.activeElement, c = document.getElementById('v3d');
  return a === c ? 'view' : c.closest('.sl-view3d').contains(a) ? 'inside' : 'outside';
});
const live = (t) => t.page.$eval('#v3d-live', (e) => e.textContent);

/**
 * The first 3D view's words: its description (the element its aria-describedby names first) and its table,
 * opened ({ shown, rows: [[name, x, y, z]], points: the view's named/draggable points [name, x, y, z] }).
 */
const words = (t) => t.page.evaluate(async () => {
  const c = document.getElementById('v3d'), v = c.view3d;
  const desc = document.getElementById(c.getAttribute('aria-describedby').split(' ')[0]).textContent;
  const d = c.closest('.sl-view3d').nextElementSibling;   // the table follows the view
  if (!d?.matches('details.plot-table') || d.hidden) return { desc, shown: false, rows: [], points: [] };
  if (!d.open) d.querySelector('summary').click();
  await new Promise((ok) => setTimeout(ok, 50));
  const tb = [...d.querySelectorAll('table')].find((x) => x.caption?.textContent.startsWith('Points'));
  const rows = tb ? [...tb.tBodies[0].rows].map((r) => [...r.cells].map((x) => x.textContent)) : [];
  return { desc, shown: true, rows, points: v._tablePoints().map((p) => [p.name, p.x, p.y, p.z]) };
});
const num = (s) => Number(String(s).replace('−', '-'));

/** One Tab stop, a spoken keyboard rotation (once for several keys) and N's selection, on one demo page. */
async function checkView(t, id) {
  await t.page.focus('#v3d');
  await t.page.keyboard.press('Tab');
  assert.equal(await focusAt(t), 'outside', `${id}: one Tab from the view leaves it`);
  await t.page.keyboard.press('Shift+Tab');
  assert.equal(await focusAt(t), 'view', `${id}: Shift+Tab from the next control enters the view`);
  await t.page.keyboard.press('Shift+Tab');
  assert.equal(await focusAt(t), 'outside', `${id}: Shift+Tab from the view leaves it backwards`);
  await t.page.keyboard.press('Tab');
  assert.equal(await focusAt(t), 'view', `${id}: Tab from the previous control enters the view`);

  // five quick rotations: the view is said once, after the keys pause, in words
  await t.page.evaluate(() => {
    const el = document.getElementById('v3d-live');
    /** @type {any} */ (window).__said = [];
    // every text the region was given (one record each, even when the same text comes again)
    new MutationObserver((records) => {
      for (const r of records) for (const n of r.addedNodes) /** @type {any} */ (window).__said.push(n.textContent);
    }).observe(el, { childList: true });
  });
  const yaw0 = await t.page.$eval('#v3d', (c) => c.view3d.getView().yaw);
  // five, as a held key sends them (in one go: this software renderer is slower than a key's auto-repeat)
  await t.page.$eval('#v3d', (c) => { for (let i = 0; i < 5; i++) c.dispatchEvent(new KeyboardEvent('keydown', { key: 'ArrowLeft', bubbles: true, cancelable: true })); });
  const yaw1 = await t.page.$eval('#v3d', (c) => c.view3d.getView().yaw);
  assert.ok(Math.abs(yaw1 - yaw0 - 25) < 1e-6, `${id}: five arrow keys rotate the view by 25° (${yaw0} → ${yaw1})`);
  await t.page.waitForTimeout(700);
  const said = await t.page.evaluate(() => /** @type {any} */ (window).__said.filter((s) => /^view /.test(s)));
  assert.equal(said.length, 1, `${id}: one announcement for five keys (${JSON.stringify(said)})`);
  // x is east, y north: the eye at azimuth `yaw` (degrees from +x) looks from that compass point
  const { yaw, pitch } = await t.page.$eval('#v3d', (c) => c.view3d.getView());
  const from = ['east', 'north-east', 'north', 'north-west', 'west', 'south-west', 'south', 'south-east'][Math.round((((yaw % 360) + 360) % 360) / 45) % 8];
  const el = Math.round(pitch);
  assert.match(said[0], new RegExp(`^view from the ${from}, ${Math.abs(el)}° ${el >= 0 ? 'above' : 'below'}; zoom [\\d.]+×$`), `${id}: ${said[0]}`);
}

/** The demos with a 3D view: every demo of the gallery visited in one page (by its route), those whose page holds one. */
async function demosWith3D() {
  const t = await H.open('');
  const found = [];
  for (const id of await demoIds()) {
    await t.page.evaluate((d) => { location.hash = `#${d}`; }, id);
    await t.page.waitForSelector(`#demo-root[data-demo="${id}"][data-mounted="true"]`, { timeout: 30000 });
    if (await t.page.evaluate(() => !!document.querySelector('#demo-root canvas.sl-view3d-canvas'))) found.push(id);
  }
  t.assertClean(IGNORE);
  await t.close();
  return found;
}

test('every demo with a 3D view: one Tab stop, its rotation said once, N names a point by its paper name', async (tc) => {
  const ids = await demosWith3D();
  // (a floor, so that a broken search cannot pass with nothing found)
  for (const known of ['b2-surfaces', 'curve-networks', 'criss-cross-basis', 'quasi-cubic-surfaces', 'bezier-remodel', 'knot-modification']) {
    assert.ok(ids.includes(known), `${known} is found to have a 3D view (found: ${ids.join(', ')})`);
  }
  for (const id of ids) await tc.test(id, async () => {
    const t = await H.open(`#${id}`);
    assert.ok(await markView(t), `${id}: its 3D view`);
    await checkView(t, id);
    // the view's buttons turn it with one click (SC 2.5.1), ≥ 24 px (SC 2.5.8), and the new view is said
    const yaw0 = await t.page.$eval('#v3d', (c) => c.view3d.yaw);
    const turn = t.page.locator('.sl-view3d:has(#v3d) button[aria-label="Turn left"]');
    const tb = await turn.boundingBox();
    assert.ok(tb.width >= 24 && tb.height >= 24, `${id}: the Turn left button is ${tb.width}×${tb.height} px`);
    await turn.click();
    await t.page.waitForFunction(() => /^view from the /.test(document.getElementById('v3d-live').textContent));
    const yaw1 = await t.page.$eval('#v3d', (c) => c.view3d.yaw);
    assert.ok(Math.abs(Math.abs(yaw1 - yaw0) - Math.PI / 12) < 1e-9, `${id}: one click turns the view by 15° (${yaw0} → ${yaw1})`);
    assert.match(await live(t), /^view from the /, `${id}: the turn is said`);
    // ✥ makes the arrow buttons pan (SC 2.5.7: panning is otherwise a drag): Pan left moves the view's target
    // sideways, the direction of view stays; ✥ again brings Turn left back
    const tool = (label) => t.page.locator(`.sl-view3d:has(#v3d) button[aria-label="${label}"]`);
    await tool('Arrow buttons pan').click();
    assert.equal(await live(t), 'The arrow buttons now pan the view.', `${id}: the switch is said`);
    assert.equal(await tool('Arrow buttons pan').getAttribute('aria-pressed'), 'true');
    const cam0 = await t.page.$eval('#v3d', (c) => ({ target: [...c.view3d.target], yaw: c.view3d.yaw, pitch: c.view3d.pitch }));
    await tool('Pan left').click();
    const cam1 = await t.page.$eval('#v3d', (c) => ({ target: [...c.view3d.target], yaw: c.view3d.yaw, pitch: c.view3d.pitch }));
    const moved = Math.hypot(...cam1.target.map((v, k) => v - cam0.target[k]));
    assert.ok(moved > 1e-6 && cam1.yaw === cam0.yaw && cam1.pitch === cam0.pitch, `${id}: Pan left moves the target by ${moved}, the view's direction stays`);
    await tool('Arrow buttons pan').click();
    assert.equal(await tool('Turn left').count(), 1, `${id}: ✥ again: the arrows turn again`);
    // the figure in words: a description, and a table of its named points (by name, with x, y, z)
    await t.page.waitForFunction(() => { const c = document.getElementById('v3d'); return document.getElementById(c.getAttribute('aria-describedby').split(' ')[0]).textContent.length > 20; });
    const w = await words(t);
    assert.ok(w.desc.length > 20, `${id}: the view has a description (${w.desc})`);
    assert.doesNotMatch(w.desc, /\b[A-Za-z][0-9]/u, `${id}: no ASCII index in the description`);
    if (w.points.length) {
      assert.ok(w.shown, `${id}: a table of its ${w.points.length} points`);
      assert.equal(w.rows.length, w.points.length, `${id}: one row per point`);
      w.points.forEach(([name, ...xyz], i) => {
        assert.equal(w.rows[i][0], name, `${id}: row ${i} names ${name}`);
        xyz.forEach((v, j) => assert.ok(Math.abs(num(w.rows[i][j + 1]) - v) <= 5.1e-5, `${id}: ${name} ${'xyz'[j]} ${w.rows[i][j + 1]} vs ${v}`));
      });
    }
    const draggable = await t.page.$eval('#v3d', (c) => c.view3d._draggables().length);
    await t.page.keyboard.press('n');
    if (draggable && !(await t.page.$eval('#v3d', (c) => c.view3d.locked))) {
      const first = { 'b2-surfaces': 'W₋₁,₋₁', 'curve-networks': 'P₀⁽⁰⁾' }[id];
      const text = await live(t);
      assert.match(text, /^Selected /, `${id}: N selects a point (${text})`);
      assert.doesNotMatch(text, /point \d/, `${id}: the point has a paper name (${text})`);
      if (first) assert.ok(text.startsWith(`Selected ${first} (`), `${id}: the first point is ${first} (${text})`);
      await t.page.keyboard.press('Escape');
      assert.equal(await live(t), 'Selection cleared');
      await t.page.keyboard.press('Tab');
      assert.equal(await focusAt(t), 'outside', `${id}: after Escape, Tab leaves the view`);
    }
    t.assertClean(IGNORE);
    await t.close();
  });
});

/** Clicks Undo and waits (up to 5 s) for the re-mounted demo's state to equal `s0`; returns the last state read. */
async function undoTo(t, s0) {
  await t.page.getByRole('button', { name: 'Undo', exact: true }).click();
  const same = (a) => JSON.stringify(a) === JSON.stringify(s0);
  let s = await t.state();
  for (let k = 0; k < 50 && !same(s); k++) { await t.page.waitForTimeout(100); s = await t.state(); }
  await t.settled();
  return s;
}

/** Types `value` into the `axis` field of the selected point `name` and presses Enter. */
async function typeField(t, name, axis, value) {
  const input = t.page.getByRole('textbox', { name: new RegExp(`^${axis} of ${name}`) });
  await input.fill(String(value));
  await input.press('Enter');
  await t.settled();
  await t.frames(3);
  return input;
}

test('b2-surfaces: the selected point\'s z field moves it like a drag (state, link, undo); x, y are read-only; a non-number is refused', async () => {
  const t = await H.open('#b2-surfaces');
  await markView(t);
  // a mouse orbit (from the empty top-left corner) is said once, when the button is released
  await t.page.evaluate(() => {
    const el = document.getElementById('v3d-live');
    /** @type {any} */ (window).__said = [];
    new MutationObserver((records) => {
      for (const r of records) for (const n of r.addedNodes) /** @type {any} */ (window).__said.push(n.textContent);
    }).observe(el, { childList: true });
  });
  const box = await t.page.locator('#v3d').boundingBox();
  await t.page.mouse.move(box.x + 12, box.y + 12);
  await t.page.mouse.down();
  for (let k = 1; k <= 6; k++) await t.page.mouse.move(box.x + 12 + 20 * k, box.y + 12);
  const during = await t.page.evaluate(() => /** @type {any} */ (window).__said.length);
  await t.page.mouse.up();
  await t.page.waitForTimeout(700);
  const said = await t.page.evaluate(() => /** @type {any} */ (window).__said);
  assert.equal(during, 0, 'nothing is said during the orbit');
  assert.equal(said.length, 1, `one announcement after it (${JSON.stringify(said)})`);
  assert.match(said[0], /^view from the /);

  await t.page.focus('#v3d');
  await t.press('n', 'n', 'n');                       // W₋₁,₁ (row −1, column 1)
  const name = 'W₋₁,₁';
  assert.match(await live(t), new RegExp(`^Selected ${name} \\(`));
  await t.page.keyboard.press('Tab');
  const fx = t.page.getByRole('textbox', { name: new RegExp(`^x of ${name}`) });
  assert.equal(await fx.evaluate((e) => e === document.activeElement), true, 'Tab from the view reaches the x field');
  assert.equal(await fx.evaluate((e) => e.readOnly), true, 'x is read-only (the grid points move along z)');
  assert.equal(await t.page.getByRole('textbox', { name: new RegExp(`^y of ${name}`) }).evaluate((e) => e.readOnly), true);
  const s0 = await t.state(), h0 = await t.flushState();
  const z0 = await t.page.$eval('#v3d', (c) => c.view3d.getPoints('W')[8]);

  const fz = await typeField(t, name, 'z', 'abc');
  assert.equal(await fz.getAttribute('aria-invalid'), 'true');
  const msg = await t.page.$eval(`#${await fz.getAttribute('aria-describedby')}`, (e) => e.textContent);
  assert.match(msg, new RegExp(`^z of ${name}: “abc” is not a number`), msg);
  assert.deepEqual(await t.state(), s0, 'a non-number changes nothing');
  assert.equal(await fz.inputValue(), 'abc', 'the typed text stays for correcting');

  await typeField(t, name, 'z', z0 + 0.75);
  assert.equal(await fz.getAttribute('aria-invalid'), null, 'the message is gone');
  const z1 = await t.page.$eval('#v3d', (c) => c.view3d.getPoints('W')[8]);
  assert.ok(Math.abs(z1 - (z0 + 0.75)) < 1e-5, `the point moved to z = ${z0 + 0.75} (${z1})`);
  const s1 = await t.state();
  const edit = s1.edits.find((e) => e[0] === 0 && e[1] === 2);
  assert.ok(edit && Math.abs(edit[2] - 0.75) < 1e-5, `the state records W₋₁,₁ +0.75 (${JSON.stringify(s1.edits)})`);
  assert.match((await t.page.$$eval('.ctl-readout-value', (els) => els.map((e) => e.textContent)))[1], /W₋₁,₁ \+0\.75/);
  const h1 = await t.flushState();
  assert.notEqual(h1, h0, 'the link follows');
  assert.match(await live(t), new RegExp(`^Moved ${name} \\(`));

  assert.deepEqual(await undoTo(t, s0), s0, 'Undo restores the grid');
  assert.equal(await t.flushState(), h0, 'and the link');

  // screenshots of a selected point with its fields, at three sizes (undo re-mounted the demo: a new view)
  await markView(t);
  for (const [w, hgt] of [[1366, 900], [1280, 720], [390, 844]]) {
    await t.page.setViewportSize({ width: w, height: hgt });
    await t.frames(3);
    await t.page.focus('#v3d');
    await t.press('n', 'n', 'n', 'n', 'n', 'n', 'n', 'n');
    await t.page.$eval('.sl-view3d-fields', (e) => e.scrollIntoView({ block: 'center' }));
    await t.frames(2);
    // the panel shows, fits the width and is on top where its z field is (not under the phone's controls sheet)
    const vis = await t.page.$eval('.sl-view3d-fields', (e) => {
      const r = e.getBoundingClientRect(), z = e.querySelectorAll('input')[2].getBoundingClientRect();
      const top = document.elementFromPoint(z.left + z.width / 2, z.top + z.height / 2);
      return { shown: !e.hidden, w: r.width, right: r.right, inner: innerWidth, onTop: !!top && e.contains(top) };
    });
    assert.ok(vis.shown && vis.w > 100 && vis.right <= vis.inner + 1 && vis.onTop, `the fields show, fit and are on top at ${w}×${hgt}: ${JSON.stringify(vis)}`);
    await t.screenshot(`view3d-fields-${w}x${hgt}`, { fullPage: false });
  }
  t.assertClean(IGNORE);
  await t.close();
});

test('curve-networks: the x, y, z fields of P₀⁽⁰⁾ move it like a drag (state, link, undo)', async () => {
  const t = await H.open('#curve-networks');
  await markView(t);
  await t.page.focus('#v3d');
  await t.press('n');
  const name = 'P₀⁽⁰⁾';
  assert.match(await live(t), new RegExp(`^Selected ${name} \\(`));
  const s0 = await t.state(), h0 = await t.flushState();
  const pointNow = () => t.page.$eval('#v3d', (c) => Array.from(c.view3d.getPoints('net-P').slice(0, 3)));
  const p0 = await pointNow();
  for (const axis of ['x', 'y']) {
    assert.equal(await t.page.getByRole('textbox', { name: new RegExp(`^${axis} of ${name}`) }).evaluate((e) => e.readOnly), false);
  }
  const z = Number((p0[2] + 0.5).toFixed(4));
  await typeField(t, name, 'z', z);
  const s1 = await t.state(), p1 = await pointNow();
  assert.ok(s1.network && Math.abs(s1.network.P[0][0][2] - z) < 1e-4, `P₀⁽⁰⁾ has z = ${z} in the state (${s1.network?.P[0][0]})`);
  assert.ok(Math.abs(p1[2] - z) < 1e-4 && Math.abs(p1[0] - p0[0]) < 1e-6 && Math.abs(p1[1] - p0[1]) < 1e-6, `the drawn point moved up only (${p0} → ${p1})`);
  const h1 = await t.flushState();
  assert.notEqual(h1, h0, 'the link follows');
  assert.deepEqual(await undoTo(t, s0), s0, 'Undo restores the network');
  t.assertClean(IGNORE);
  await t.close();
});

/**
 * Click-then-click (or tap-then-tap) on the first 3D view: picks the middle draggable point, then clicks `off`
 * px away (a place clear of the other points); checks the move like a drag (state, link, live region, undo).
 * `press(x, y)` clicks or taps at viewport coordinates.
 */
async function clickThenClick(t, id, press) {
  const s0 = await t.state(), h0 = await t.flushState();
  const plan = await t.page.$eval('#v3d', (c) => {
    const v = c.view3d, list = v._draggables(), r = c.getBoundingClientRect();
    const sp = (o) => v.screenPosition(o.id, o.index);
    // a point near the middle of the list that no other point hides (network curves share their intersections)
    const alone = (o) => list.every((q) => q === o || Math.hypot(sp(q)[0] - sp(o)[0], sp(q)[1] - sp(o)[1]) >= 16);
    const order = list.map((o, k) => [Math.abs(k - list.length / 2), o]).sort((a, b) => a[0] - b[0]).map((e) => e[1]);
    const d = order.find(alone) ?? order[0];
    const at = sp(d);
    const others = list.filter((o) => o !== d).map(sp);
    // the first destination 30–60 px away that is inside the view and 24 px or more from every other point
    let to = null;
    for (const [dx, dy] of [[40, -30], [-40, -30], [40, 30], [-40, 30], [60, 0], [-60, 0], [0, -50], [0, 50]]) {
      const q = [at[0] + dx, at[1] + dy];
      if (q[0] < 12 || q[1] < 12 || q[0] > r.width - 12 || q[1] > r.height - 12) continue;
      if (others.every((o) => Math.hypot(o[0] - q[0], o[1] - q[1]) >= 24)) { to = q; break; }
    }
    const p0 = Array.from(v.getPoints(d.id).slice(3 * d.index, 3 * d.index + 3));
    return { set: d.id, index: d.index, name: v.pointName(d.id, d.index), axis: v.objects.get(d.id).axis, p0,
      at: [r.left + at[0], r.top + at[1]], to: to && [r.left + to[0], r.top + to[1]], to0: to };
  });
  assert.ok(plan.to, `${id}: a free place to click near ${plan.name}`);
  await press(...plan.at);
  assert.match(await live(t), new RegExp(`^${plan.name} \\(.*\\) selected\\. Click or tap where it should go`), `${id}: the click picks ${plan.name}`);
  assert.deepEqual(await t.state(), s0, `${id}: picking moves nothing`);
  await press(...plan.to);
  await t.settled();
  await t.frames(3);
  const now = await t.page.$eval('#v3d', (c, p) => {
    const v = c.view3d;
    const q = Array.from(v.getPoints(p.set).slice(3 * p.index, 3 * p.index + 3)), f = v._camera().forward;
    // how far the point moved towards or away from the camera (0: it stayed in the plane facing the camera)
    const depth = (q[0] - p.p0[0]) * f[0] + (q[1] - p.p0[1]) * f[1] + (q[2] - p.p0[2]) * f[2];
    // the axis's line on the screen (through the point before the move): an axis move lands on it, nearest the click
    const A = p.axis ? [0, 1, 2].map((j) => (j === 'xyz'.indexOf(p.axis) ? 1 : 0)) : null;
    const line = A && [v._project(p.p0, v._camera()), v._project(p.p0.map((x, j) => x + A[j]), v._camera())];
    return { p: q, screen: v.screenPosition(p.set, p.index), depth, line };
  }, plan);
  if (!plan.axis) {
    // in the plane facing the camera through the point: it lands under the click
    const miss = Math.hypot(now.screen[0] - plan.to0[0], now.screen[1] - plan.to0[1]);
    assert.ok(miss < 1.5, `${id}: ${plan.name} is drawn where the click was (${miss.toFixed(2)} px off)`);
    assert.ok(Math.abs(now.depth) < 1e-4, `${id}: ${plan.name} moved in the plane facing the camera (depth change ${now.depth})`);
  } else {
    const k = 'xyz'.indexOf(plan.axis);
    for (let j = 0; j < 3; j++) {
      if (j === k) assert.ok(Math.abs(now.p[j] - plan.p0[j]) > 1e-3, `${id}: ${plan.name} moved along ${plan.axis}`);
      else assert.ok(Math.abs(now.p[j] - plan.p0[j]) < 1e-6, `${id}: ${plan.name} kept its ${'xyz'[j]}`);
    }
    const [a, b] = now.line, d = [b[0] - a[0], b[1] - a[1]];
    const s = ((plan.to0[0] - a[0]) * d[0] + (plan.to0[1] - a[1]) * d[1]) / (d[0] * d[0] + d[1] * d[1]);
    const foot = [a[0] + s * d[0], a[1] + s * d[1]];
    const miss = Math.hypot(now.screen[0] - foot[0], now.screen[1] - foot[1]);
    assert.ok(miss < 3, `${id}: ${plan.name} lands on its axis nearest the click (${miss.toFixed(2)} px off)`);
  }
  assert.match(await live(t), new RegExp(`^${plan.name} \\(.*\\): moved\\.$`), `${id}: the move is said`);
  // the description names it first, and the table shows where it is now
  // (the description follows 400 ms after a change: a short wait, then the assertion says what was read — not a
  // 30 s test timeout)
  await t.page.waitForFunction(() => { const c = document.getElementById('v3d'); return document.getElementById(c.getAttribute('aria-describedby').split(' ')[0]).textContent.includes('moved there last'); }, null, { timeout: 3000 })
    .catch(() => {});
  const w = await words(t);
  assert.ok(w.desc.startsWith(`${plan.name} (`) && w.desc.includes('moved there last'), `${id}: the description names the moved point first (${w.desc.slice(0, 80)})`);
  const row = w.rows.find((r) => r[0] === plan.name);
  assert.ok(row && Math.abs(num(row[3]) - now.p[2]) <= 5.1e-5, `${id}: the table shows ${plan.name}'s new z (${row} vs ${now.p})`);
  assert.notDeepEqual(await t.state(), s0, `${id}: the state changed`);
  assert.notEqual(await t.flushState(), h0, `${id}: the link changed`);
  assert.deepEqual(await undoTo(t, s0), s0, `${id}: Undo restores it`);
  assert.equal(await t.flushState(), h0, `${id}: and the link`);
}

test('3D views without dragging: click a point, click where it should go (curve-networks: free; b2-surfaces: along z); tap-then-tap at 390×844', async () => {
  for (const id of ['curve-networks', 'b2-surfaces']) {
    const t = await H.open(`#${id}`);
    await markView(t);
    await clickThenClick(t, id, (x, y) => t.page.mouse.click(x, y));
    t.assertClean(IGNORE);
    await t.close();
  }
  const context = await H.browser.newContext({ viewport: { width: 390, height: 844 }, deviceScaleFactor: 2, isMobile: true, hasTouch: true });
  const t = await H.open('#curve-networks', { context });
  await markView(t);
  const y0 = await t.page.evaluate(() => window.scrollY);
  await clickThenClick(t, 'curve-networks (touch)', async (x, y) => {
    await t.page.touchscreen.tap(x, y);
    await t.frames(2);
  });
  assert.equal(await t.page.evaluate(() => window.scrollY), y0, 'the taps did not scroll the page');
  t.assertClean(IGNORE);
  await t.close();
  await context.close();
});
