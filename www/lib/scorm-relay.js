// The relay package (issue 27): for a teacher whose SplineLab is hosted (a site the students can reach), a SCORM 1.2
// package of a few kilobytes instead of the whole of SplineLab. Its launch page shows the hosted exercise in an
// iframe and turns the exercise's `splinelab:result` messages into the same SCORM calls as the self-contained
// package (./scorm.js, inlined into the page as text), accepting messages only from the exercise's frame and the
// host it was made for (`event.origin`). What it cannot do, and says: keep the student's view for a relaunch (the
// hosted frame does not tell it), and stop a Check past the allowed number (that Check is shown in the frame but
// not recorded).

/** The relay launch page: `scormSource` is the text of www/lib/scorm.js; `host` the origin of the hosted site. */
export function relayPage({ title, passMark, attempts, hintCost, items, host }, scormSource) {
  const esc = (s) => String(s).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');
  const json = (x) => JSON.stringify(x).replace(/</g, '\\u003c');
  // the module's exports become plain declarations of the page's script
  const lib = scormSource.replace(/^export /gm, '');
  const config = { title, passMark, attempts, hintCost, host, items };
  return `<!doctype html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>${esc(title)}</title>
<style>
  body { margin: 0; font-family: system-ui, sans-serif; color: #1a1a1a; }
  .bar { padding: 0.4rem 1rem; border-bottom: 1px solid #ccc; background: #fff; }
  .bar p { margin: 0.2rem 0; }
  .bar ol { list-style: none; margin: 0.3rem 0 0; padding: 0; display: flex; flex-wrap: wrap; gap: 0.4rem; }
  .bar button { font: inherit; min-height: 32px; padding: 0.2rem 0.7rem; border: 2px solid #1a1a1a; border-radius: 6px; background: #fff; cursor: pointer; }
  .bar button[aria-current="step"] { background: #1a1a1a; color: #fff; }
  iframe { display: block; border: 0; width: 100%; height: calc(100vh - 5rem); min-height: 600px; }
</style>
</head>
<body>
<div class="bar"><p id="head"></p><ol id="items"></ol><p id="status" role="status"></p></div>
<iframe id="exercise" title="${esc(title)}" allow="fullscreen"></iframe>
<script>
${lib}
(() => {
  const C = ${json(config)};
  const frame = document.getElementById('exercise');
  const status = document.getElementById('status');
  const say = (text) => { status.textContent = text; };
  const session = scormSession({ api: findAPI(window), count: C.items.length, passMark: C.passMark, attempts: C.attempts, hintCost: C.hintCost, say });
  const rules = ['pass mark ' + C.passMark + ' of 100', C.attempts ? C.attempts + ' Check' + (C.attempts === 1 ? '' : 's') + ' per exercise' : '', C.hintCost ? 'a hint costs ' + C.hintCost + ' points' : ''].filter(Boolean).join('; ');
  let current = (session.resumed && session.resumed.i) || 0;
  const buttons = C.items.length > 1 ? C.items.map((x, k) => {
    const li = document.createElement('li');
    const b = document.createElement('button');
    b.type = 'button';
    b.addEventListener('click', () => show(k));
    li.append(b);
    document.getElementById('items').append(li);
    return b;
  }) : [];
  function show(k) {
    current = k;
    frame.src = C.items[k].url;
    frame.title = C.items[k].title;
    session.setView(k, '');
    paint();
  }
  function paint() {
    const it = C.items[current];
    document.getElementById('head').textContent = (C.items.length > 1 ? 'Exercise ' + (current + 1) + ' of ' + C.items.length + ': ' : '') + it.title
      + ' (from ' + C.host + '). ' + (C.items.length > 1 ? 'The set\\'s score: ' + session.total() + ' of 100 so far; ' : '') + rules + '.';
    buttons.forEach((b, j) => {
      const s = session.best[j];
      b.textContent = (j + 1) + '. ' + C.items[j].title + (s >= 0 ? ' — ' + s : '');
      if (j === current) b.setAttribute('aria-current', 'step'); else b.removeAttribute('aria-current');
    });
  }
  window.addEventListener('message', (e) => {
    // only the exercise's own frame, from the site it was made for
    if (e.origin !== C.host || e.source !== frame.contentWindow) return;
    const d = e.data;
    if (!d || d.type !== 'splinelab:result') return;
    const k = C.items.findIndex((x) => x.id === d.exercise);
    const idx = k >= 0 ? k : current;
    if (session.connected && session.left(idx) <= 0) { say('No Check left: this exercise allowed ' + C.attempts + '. This Check is not recorded; your best score, ' + Math.max(0, session.best[idx]) + ' of 100, is.'); return; }
    const r = session.report(idx, d);
    if (!r) return;
    document.documentElement.dataset.scormStatus = r.status;
    document.documentElement.dataset.scormScore = String(r.raw);
    paint();
    say('Recorded in the course: ' + (r.status === 'passed' ? 'passed' : 'not passed yet') + ', score ' + r.raw + ' of 100; ' + rules + '.'
      + (Number.isFinite(r.left) ? ' ' + r.left + ' Check' + (r.left === 1 ? '' : 's') + ' left.' : ''));
  });
  window.addEventListener('pagehide', () => session.finish());
  document.documentElement.dataset.scorm = session.connected ? 'connected' : 'none';
  show(current);
})();
</script>
</body>
</html>
`;
}
