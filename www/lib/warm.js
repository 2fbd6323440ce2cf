// Warm start (issue 26): after a demo's first frame, in idle time, run the demo's own drawing path a few dozen
// times with its current state, so that the first drag runs in optimized code.
//
// Why: V8 runs new code in a baseline tier first — wasm in Liftoff until a function has done enough work (then
// TurboFan compiles it in the background), JavaScript in its interpreter and baseline compilers until it is hot.
// Measured: the first calls of 1M B-spline points take 15–55 ms, then 3.7 ms; a person's first drag frames pay
// the same price at drag sizes.
//
// What it runs: `instance.warm()` of the mounted demo (the object its `mount()` returned), when the demo gives
// one — a function that recomputes and redraws the demo from its current state exactly as a drag frame does (e.g.
// the demo's `recompute()`): the same wasm calls and drawing code, the same pixels, no `ctx.save()`, so nothing
// visible, no undo step and no change of the link. A demo without `warm` is left alone.
//
// How it stays out of the way: it starts two animation frames after the call (the first drawing is on screen),
// runs one warm call per requestIdleCallback slice (a setTimeout fallback where there is none; a call starts
// only when the idle period has as long left as the previous call took, up to SLICE_MS), and stops for good on
// the first user input (pointer, key, wheel, touch), when the demo is unmounted, after ROUNDS calls, or when two
// calls in a row take longer than MAX_CALL_MS (too heavy to run unasked).
// `?warm=0` in the page's query turns it off (benches/interaction.mjs compares both); `?warm=<n>` sets ROUNDS;
// `window.splinelabWarm = <n>` (set before SplineLab starts) does the same where the query is not the page's own.
// `document.documentElement.dataset.warm` says where it is: 'waiting' | 'running' | 'done' | 'stopped' | 'failed'
// (a warm call threw) | 'off'
// (`dataset.warmCalls`: the calls so far).

const SLICE_MS = 8;
const ROUNDS = 24;
const MAX_CALL_MS = 25;
const INPUTS = ['pointerdown', 'keydown', 'wheel', 'touchstart'];

/** Rounds asked for by the page's query (`?warm=0` off, `?warm=<n>` n calls), else by `globalThis.splinelabWarm`
 * (the same number, set by a script before SplineLab starts: a course page, or the e2e harness, which turns the
 * warm-up off except in the tests that look at it), else ROUNDS. */
function roundsAsked() {
  const q = new URLSearchParams(globalThis.location?.search || '').get('warm');
  const g = /** @type {any} */ (globalThis).splinelabWarm;
  const n = q !== null ? Number(q) : g !== undefined && g !== null ? Number(g) : ROUNDS;
  return Number.isFinite(n) && n >= 0 ? Math.min(Math.floor(n), 1000) : ROUNDS;
}

/** Calls `fn(deadline)` when the page is idle (deadline.timeRemaining() in ms); returns a cancel function. */
function whenIdle(fn) {
  if (typeof requestIdleCallback === 'function') {
    const id = requestIdleCallback(fn, { timeout: 500 });
    return () => cancelIdleCallback(id);
  }
  const id = setTimeout(() => fn({ timeRemaining: () => SLICE_MS, didTimeout: true }), 50);
  return () => clearTimeout(id);
}

const setStatus = (s) => { if (globalThis.document) document.documentElement.dataset.warm = s; };

/**
 * Warms the mounted demo (`mounted` from www/lib/host.js: { root, instance }) in idle time; returns a function that
 * stops it. Safe to call for any demo: it does nothing for one without `instance.warm`. `rounds`: the number of
 * calls (default: the page query's, else ROUNDS).
 * @param {{ root?: Element, instance?: { warm?: () => void } } | null | undefined} mounted
 */
export function warmStart(mounted, rounds = roundsAsked()) {
  const warm = mounted?.instance?.warm;
  if (typeof warm !== 'function' || rounds === 0) { setStatus('off'); return () => {}; }
  let done = 0, cancel = null, stopped = false;
  const stop = (status = 'stopped') => {
    if (stopped) return;
    stopped = true;
    cancel?.();
    for (const t of INPUTS) removeEventListener(t, onInput, true);
    setStatus(status);
  };
  const onInput = () => stop('stopped');
  for (const t of INPUTS) addEventListener(t, onInput, { capture: true, passive: true });

  let slow = 0; // consecutive calls over MAX_CALL_MS
  let last = 0; // ms of the previous call: a slice starts one only when the idle period has that much left
  function slice(deadline) {
    cancel = null;
    if (stopped) return;
    if (!mounted.root?.isConnected) { stop('stopped'); return; }
    if (!deadline.didTimeout && deadline.timeRemaining() < Math.min(last, SLICE_MS)) { cancel = whenIdle(slice); return; }
    const t0 = performance.now();
    try { warm(); } catch { stop('failed'); return; }
    last = performance.now() - t0;
    done++;
    document.documentElement.dataset.warmCalls = String(done);
    if (done >= rounds) { stop('done'); return; }
    // two long calls in a row: too heavy to run unasked (one alone may be this busy machine, not the call)
    slow = last > MAX_CALL_MS ? slow + 1 : 0;
    if (slow >= 2) { stop('stopped'); return; }
    // one call per slice: the redraw it asked for paints in the next animation frame, so the drawing code warms
    // up as well as the computation
    cancel = whenIdle(slice);
  }

  setStatus('waiting');
  const raf = typeof requestAnimationFrame === 'function' ? requestAnimationFrame : (f) => setTimeout(f, 16);
  raf(() => raf(() => { if (!stopped) { setStatus('running'); cancel = whenIdle(slice); } }));
  return () => stop('stopped');
}
