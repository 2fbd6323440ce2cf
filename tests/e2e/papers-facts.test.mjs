// "Every paper figure asserts its facts": each figure (and theorem) of www/papers.js states in `expect` what its
// live view must show — the preset pressed, the network chosen, the handles and their names, the numbers on the
// readouts — and this test opens every figure link and reads those facts on the opened page, as a reader sees
// them (readout texts, checked buttons, the selected option, the handles and labels of the plots, the points of
// the 3D view). A readout that says "fails" or "broken" is allowed only where the figure lists it in
// `expect.fails` and its card on the papers page explains it; the link names the demo by the title it shows.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startHarness } from './harness.mjs';

let H;
before(async () => { H = await startHarness(); });
after(async () => { await H?.close(); });

/**
 * Every live link of the page (figures, theorems, corrections): its href, the partial state it encodes (decoded
 * with the app's own decoder), its card's text and link text, and for a figure or theorem its entry's `expect`.
 */
function pageLinks(t) {
  return t.page.evaluate(async () => {
    const { FIGURES, THEOREMS } = await import('./papers.js');
    const { decodeState, parseHash } = await import('./lib/state.js');
    const entries = new Map();
    for (const [key, figs] of Object.entries(FIGURES)) for (const f of figs) entries.set(`paper-${key}-fig-${f.n}`, f);
    for (const f of THEOREMS) entries.set(`paper-002-thm-${f.n}`, f);
    const out = [];
    for (const a of document.querySelectorAll('a.paper-demo-link')) {
      const card = a.closest('figure, article');
      const { id, payload } = parseHash(new URL(a.href).hash);
      const f = entries.get(card.id);
      out.push({ id: card.id, href: a.getAttribute('href'), demo: id, state: payload ? await decodeState(payload) : null, linkText: a.textContent, card: card.textContent, figure: !!f, expect: f?.expect ?? null });
    }
    const missing = [...entries].filter(([id, f]) => !f.nr && !out.some((l) => l.id === id)).map(([id]) => id);
    return { links: out, missing };
  });
}

/** What the opened demo shows: readouts, checked buttons, selects, 2D handles/labels/markers, 3D point sets. */
function readFacts(d, points3d) {
  return d.page.evaluate((ids3d) => {
    const root = document.getElementById('demo-root') || document.body;
    const visible = (el) => !!el.getClientRects().length;
    const readouts = [...root.querySelectorAll('.ctl-readout')].filter(visible).map((r) => ({
      label: r.querySelector('.ctl-readout-label')?.textContent.trim() ?? '',
      value: r.querySelector('.ctl-readout-value')?.textContent.trim() ?? '',
    }));
    const checked = [...root.querySelectorAll('input[type="radio"]:checked')].map((i) => root.querySelector(`label[for="${i.id}"]`)?.textContent.trim());
    const selects = {};
    for (const s of root.querySelectorAll('.ctl-select')) selects[s.querySelector('label').textContent.trim()] = s.querySelector('select').selectedOptions[0]?.textContent.trim();
    // the demo's main 2D plot: the first visible plot2d canvas with handles
    let plot = null;
    for (const c of root.querySelectorAll('canvas')) {
      const p = c.splinePlot;
      if (!p || !visible(c) || !p.handles().length) continue;
      p.paintNow();
      const r = c.getBoundingClientRect();
      const groups = {};
      for (const hd of p.handles()) (groups[hd.name] ??= []).push(hd.point.slice(0, 2));
      plot = {
        name: c.dataset.plot, groups, labels: p.lastLabels.map((l) => l.text),
        outside: [...p.lastMarkers, ...p.lastLabels.map((l) => ({ x: l.x + l.w / 2, y: l.y + l.h / 2 }))].filter((m) => !(m.x >= 0 && m.y >= 0 && m.x <= r.width && m.y <= r.height)).length,
      };
      break;
    }
    const view = root.querySelector('canvas')?.splineView || [...root.querySelectorAll('canvas')].map((c) => c.splineView).find(Boolean);
    const pts3d = {};
    for (const id of ids3d) { const p = view?.getPoints(id); pts3d[id] = p ? p.length / 3 : null; }
    return { view: document.body.dataset.view, draws: [...root.querySelectorAll('canvas')].some((x) => x.width > 0 && x.height > 0), state: window.splinelab.current()?.state ?? null, title: document.title, readouts, checked, selects, plot, pts3d, text: root.innerText, notices: [...document.querySelectorAll('.notice-error, .notice-warning')].map((n) => n.textContent) };
  }, points3d);
}

/**
 * The largest distance of the interpolating curve on screen from the data edge WᵢWᵢ₊₁ each of its pieces spans
 * (Kuklišová Figs. 13–14), measured with the view's own wasm module on the mounted demo's state.
 */
function polygonDistance(d) {
  return d.page.evaluate(async () => {
    const st = window.splinelab.current().state;
    const w = await import('./pkg/b2/splinelab.js');   // the module the demo runs on (already initialised)
    const o = { points: st.points, a: st.a, tension: st.p, knots: st.knots, c2: st.c2, construction: st.construction, samples: 4000 };
    if (st.useK) o.K = st.K;
    const r = w.b2Curve(o), W = st.points.slice(2, -2), P = r.points, U = r.params, J = r.jointParams;
    let worst = 0;
    for (let i = 0; i + 1 < W.length; i++) {
      const [ax, ay] = W[i], dx = W[i + 1][0] - ax, dy = W[i + 1][1] - ay;
      for (let k = 0; k < U.length; k++) {
        if (U[k] < J[i] || U[k] > J[i + 1]) continue;
        const s = Math.max(0, Math.min(1, ((P[2 * k] - ax) * dx + (P[2 * k + 1] - ay) * dy) / (dx * dx + dy * dy)));
        worst = Math.max(worst, Math.hypot(P[2 * k] - ax - s * dx, P[2 * k + 1] - ay - s * dy));
      }
    }
    return worst;
  });
}

const num = (s) => Number(String(s).replace(/−/g, '-').replace(/^[^0-9+\-.]*/, '').split(/[\s(:,]/)[0]);

/** The readout whose label starts with `label` (labels are read as the page shows them). */
const readout = (facts, label) => facts.readouts.find((r) => r.label.startsWith(label));

/** Problems of any opened link: a notice, nothing drawn, or a promised value (numbers, strings, booleans, also
 * in nested objects) that is not the demo's. */
function checkLink(link, facts) {
  const bad = [];
  if (facts.view !== 'demo') bad.push(`opens the ${facts.view} view, not the demo`);
  if (facts.notices.length) bad.push(`notices: ${facts.notices.join(' | ')}`);
  if (!facts.draws) bad.push('draws nothing');
  const walk = (want, got, path) => {
    for (const [k, v] of Object.entries(want || {})) {
      if (v !== null && typeof v === 'object' && !Array.isArray(v)) walk(v, got?.[k], `${path}.${k}`);
      else if (!Array.isArray(v) && got?.[k] !== v) bad.push(`${path}.${k} is ${JSON.stringify(got?.[k])}, the link says ${JSON.stringify(v)}`);
    }
  };
  walk(link.state, facts.state, 'state');
  return bad;
}

/** Problems of one opened figure against its `expect` (empty: every fact holds). */
function check(fig, facts, measured) {
  const bad = [];
  const e = fig.expect;
  const title = facts.title.replace(/ — SplineLab$/, '');
  if (!fig.linkText.endsWith(`: ${title}`)) bad.push(`the link reads “${fig.linkText}” but the demo is titled “${title}”`);
  for (const label of e.pressed ?? []) if (!facts.checked.includes(label)) bad.push(`“${label}” is not pressed (pressed: ${facts.checked.join(', ')})`);
  for (const [label, want] of Object.entries(e.selected ?? {})) if (facts.selects[label] !== want) bad.push(`${label} shows “${facts.selects[label]}”, expected “${want}”`);
  for (const [label, want] of Object.entries(e.readouts ?? {})) {
    const r = readout(facts, label);
    if (!r) { bad.push(`no readout “${label}”`); continue; }
    const v = num(r.value);
    if (want.below !== undefined && !(Math.abs(v) < want.below)) bad.push(`${label} = ${r.value}, expected below ${want.below}`);
    if (want.above !== undefined && !(v > want.above)) bad.push(`${label} = ${r.value}, expected above ${want.above}`);
    if (want.near !== undefined && !(Math.abs(v - want.near[0]) <= want.near[1])) bad.push(`${label} = ${r.value}, expected ${want.near[0]} ± ${want.near[1]}`);
    if (want.match !== undefined && !new RegExp(want.match).test(r.value)) bad.push(`${label} = “${r.value}”, expected /${want.match}/`);
  }
  for (const [group, n] of Object.entries(e.handles ?? {})) {
    const got = facts.plot?.groups[group]?.length ?? 0;
    if (got !== n) bad.push(`${got} handles “${group}”, expected ${n}`);
  }
  for (const [group, pts] of Object.entries(e.points ?? {})) {
    const got = facts.plot?.groups[group] ?? [];
    if (got.length !== pts.length || pts.some((p, i) => Math.hypot(p[0] - got[i][0], p[1] - got[i][1]) > 1e-9)) bad.push(`handles “${group}” at ${JSON.stringify(got)}, expected ${JSON.stringify(pts)}`);
  }
  for (const l of e.labels ?? []) if (!facts.plot?.labels.includes(l)) bad.push(`no label “${l}” drawn (labels: ${facts.plot?.labels.join(' ')})`);
  if (e.inView && facts.plot?.outside !== 0) bad.push(`${facts.plot?.outside} points or labels of the plot lie outside the view`);
  for (const [id, n] of Object.entries(e.points3d ?? {})) if (facts.pts3d[id] !== n) bad.push(`${facts.pts3d[id]} points in “${id}”, expected ${n}`);
  if (e.polygonDistance && !(Math.abs(measured - e.polygonDistance[0]) <= e.polygonDistance[1])) bad.push(`the curve is ${measured} from its data edges, expected ${e.polygonDistance[0]} ± ${e.polygonDistance[1]}`);
  for (const s of e.text ?? []) if (!facts.text.includes(s)) bad.push(`the demo does not show “${s}”`);
  // a readout that says the paper's claim fails (or a condition is broken) must be the point of the figure
  for (const r of facts.readouts) {
    if (!/\b(fails|broken)\b/.test(r.value)) continue;
    if (!(e.fails ?? []).some((l) => r.label.startsWith(l))) bad.push(`the readout “${r.label}” reads “${r.value}” and the figure does not say why`);
  }
  for (const l of e.fails ?? []) {
    if (!fig.card.includes(`The readout ${l} says`)) bad.push(`the card does not explain the readout “${l}”`);
    const r = readout(facts, l);
    if (!r || !/\b(fails|broken)\b/.test(r.value)) bad.push(`the card says “${l}” fails, the view reads “${r?.value}”`);
  }
  return bad;
}

test('every paper figure asserts its facts, and every live link opens the view it promises', async () => {
  const t = await H.open('papers.html');
  const { links, missing } = await pageLinks(t);
  await t.close();
  const figures = links.filter((l) => l.figure);
  assert.ok(figures.length >= 55 && links.length >= 70, `${figures.length} figures, ${links.length} links`);
  const problems = missing.map((id) => `${id}: no live link`);
  // One page for all the views: the first link is opened (the start-up path), every other one is pasted into its
  // address bar, a hash change: the same route() as a fresh page (parse the link, read the state, mount the demo),
  // without the ~1.5 s of loading the shell again for each of ~70 links (the fresh start from a state link is
  // gallery.test's round trip, for every demo). Each distinct link is opened once, and every card that uses it is
  // checked on it.
  const byHref = new Map();
  for (const l of links) byHref.set(l.href, [...(byHref.get(l.href) ?? []), l]);
  // PAPERS_FACTS_ONLY=<substring of a card id>: check only those cards (to re-run one figure quickly)
  const only = process.env.PAPERS_FACTS_ONLY;
  let d = null;
  for (const [href, users] of byHref) {
    if (only && !users.some((l) => l.id.includes(only))) continue;
    const t0 = Date.now();
    const url = new URL(href, t.base);
    if (d && new URL(d.page.url()).pathname === url.pathname) {
      d.consoleErrors.length = 0; d.pageErrors.length = 0;
      await d.page.evaluate((hash) => new Promise((ok) => {
        document.getElementById('demo-root').dataset.before = 'true';   // the demo mounted for the previous link
        addEventListener('hashchange', () => ok(), { once: true });
        location.hash = hash;
      }), url.hash);
      await d.page.waitForSelector('#demo-root[data-mounted="true"]:not([data-before])', { timeout: 20000 });
      await d.settled();
    } else {
      await d?.close();
      d = await H.open(href);
    }
    await d.frames(3);
    const fig = users.find((l) => l.figure);
    const facts = await readFacts(d, Object.keys(fig?.expect?.points3d ?? { 'net-P': 1, 'net-Q': 1 }));
    // PAPERS_FACTS_DUMP=1: print what each view shows (to write a figure's expect)
    if (process.env.PAPERS_FACTS_DUMP) console.log(users.map((l) => l.id).join(','), JSON.stringify({ checked: facts.checked, selects: facts.selects, readouts: facts.readouts, plot: facts.plot && { ...facts.plot, groups: Object.fromEntries(Object.entries(facts.plot.groups).map(([k, v]) => [k, v.length])) }, pts3d: facts.pts3d }));
    const measured = users.some((l) => l.expect?.polygonDistance) ? await polygonDistance(d) : null;
    for (const l of users) {
      const where = `${l.id} → ${l.demo}`;
      for (const p of checkLink(l, facts)) problems.push(`${where}: ${p}`);
      if (!l.figure) continue;
      if (!l.expect || !Object.keys(l.expect).length) problems.push(`${where}: the figure states no facts (expect)`);
      else for (const p of check(l, facts, measured)) problems.push(`${where}: ${p}`);
    }
    for (const e of d.errors()) problems.push(`${users[0].id}: console: ${e}`);
    if (process.env.PAPERS_FACTS_DUMP) console.log('ms', Date.now() - t0);
  }
  await d?.close();
  assert.deepEqual(problems, [], problems.join('\n'));
});
