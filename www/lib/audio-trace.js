// "Figures in sound" (issue 25, as Desmos's audio trace does for graphs): a plot's curve or basis function played
// as sound with the Web Audio API, no dependency. Over TRACE_SECONDS the parameter runs from its first sample to
// its last: the pitch follows y (yRange → LOW_HZ … HIGH_HZ, exponential, so equal steps in y sound like equal
// musical steps), the stereo pan follows x (xRange → left … right, where StereoPannerNode exists), a short click
// sounds at every knot strictly inside the parameter domain (the end knots are where the sound starts and stops:
// a click there says nothing, and a clamped vector's ends would count as joints of multiplicity p + 1), and the
// timbre says how smooth the curve is after the last joint passed: 'sine' from the start and after a C² (or
// smoother) joint, 'triangle' after a C¹ joint, 'square' after a C⁰ joint, 'sawtooth' after a break (C⁻¹).
// The gain stays at GAIN with FADE-second fades (no clicks but the knots'). No AudioContext exists until the
// user asks (the ♪ button or S), and the sound stops when the plot goes.
//
//   const sound = attachAudioTrace({ canvas, row, trace: () => ({ name, param: 'u', samples: [{ t, x, y }],
//     knots: [{ t, continuity }], yRange, xRange, at(t) → [x, y] }), announce });
//   Keys on the canvas: S plays / stops; , and . step back / on by 1/STEPS of the domain, with a short tone and
//   "u = 0.35: (1.20, 0.50)" in the plot's live region.   sound.dispose() stops and closes.
import { h, pairSep } from './dom.js';
import { t as tt, tn, localDigits } from './i18n.js';

export const TRACE_SECONDS = 3;     // how long a whole trace plays
export const LOW_HZ = 220;          // the pitch of yRange[0] (A3) …
export const HIGH_HZ = 880;         // … and of yRange[1] (A5): two octaves
export const GAIN = 0.15;           // the voice's loudness (at most 0.2: the page should never be loud)
export const FADE = 0.02;           // s: fades at every start and stop of a voice
export const STEPS = 20;            // , and . move by 1/STEPS of the parameter domain
export const STEP_TONE = 0.25;      // s: the tone of one step
export const SOUND_HELP = 'Sound: the ♪ button or S plays the figure as sound (pitch follows y, left–right follows x, '
  + 'a click at each knot, a harsher tone after a less smooth joint); comma and period step along it.';

const clamp01 = (v) => Math.min(1, Math.max(0, v));

/** The pitch (Hz) of height y: LOW_HZ at yRange[0], HIGH_HZ at yRange[1], exponential in between. */
export function pitchOf(y, [lo, hi]) {
  const s = hi > lo ? clamp01((y - lo) / (hi - lo)) : 0.5;
  return LOW_HZ * (HIGH_HZ / LOW_HZ) ** s;
}

/** The stereo pan (−1 left … 1 right) of x in xRange. */
export function panOf(x, [lo, hi]) {
  return hi > lo ? 2 * clamp01((x - lo) / (hi - lo)) - 1 : 0;
}

/** The oscillator type after a joint of continuity C^c: sine (C² or smoother), triangle (C¹), square (C⁰), sawtooth (a break). */
export function timbreOf(c) {
  if (c >= 2) return 'sine';
  if (c === 1) return 'triangle';
  if (c === 0) return 'square';
  return 'sawtooth';
}

/** The distinct knots of a knot vector with their continuity (degree − multiplicity). */
export function knotsWithContinuity(knotVector, degree) {
  const out = [];
  for (const k of knotVector) {
    const last = out[out.length - 1];
    if (last && Math.abs(last.t - k) < 1e-12) { last.continuity--; continue; }
    out.push({ t: k, continuity: degree - 1 });
  }
  return out;
}

/**
 * @typedef {{ t: number, x: number, y: number }} TracePoint
 * @typedef {{ name: string, param?: string, samples: TracePoint[], knots?: { t: number, continuity: number }[],
 *   yRange: number[], xRange: number[], at?: (t: number) => number[] }} Trace
 */

/**
 * A trace from a demo's samples: `params` and flat `points` (x, y, x, y, …); the ranges are the samples' bounds.
 * @param {{ name: string, param?: string, params: ArrayLike<number>, points: ArrayLike<number>,
 *   knots: { t: number, continuity: number }[], at?: (t: number) => number[], stride?: number }} o
 * @returns {Trace}
 */
export function traceOf({ name, param = 'u', params, points, knots, at, stride = 2 }) {
  const samples = [];
  for (let j = 0; j < params.length; j++) samples.push({ t: params[j], x: points[stride * j], y: points[stride * j + 1] });
  const xs = samples.map((s) => s.x), ys = samples.map((s) => s.y);
  return { name, param, samples, knots, at, xRange: [Math.min(...xs), Math.max(...xs)], yRange: [Math.min(...ys), Math.max(...ys)] };
}

/** The parameter domain [first sample's t, last sample's t]. */
const domainOf = (trace) => [trace.samples[0].t, trace.samples[trace.samples.length - 1].t];

/** The knots strictly inside the domain (those that tick), in order. */
export function innerKnots(trace) {
  const [a, b] = domainOf(trace), eps = 1e-9 * Math.max(1, b - a);
  return (trace.knots || []).filter((k) => k.t > a + eps && k.t < b - eps).sort((p, q) => p.t - q.t);
}

/** The point at parameter t: trace.at(t) when the demo gives it (exact), else between the two nearest samples. */
export function pointAt(trace, t) {
  if (trace.at) { const [x, y] = trace.at(t); return { t, x, y }; }
  const S = trace.samples;
  let j = 1;
  while (j < S.length - 1 && S[j].t < t) j++;
  const p = S[j - 1], q = S[j], s = q.t > p.t ? clamp01((t - p.t) / (q.t - p.t)) : 0;
  return { t, x: p.x + s * (q.x - p.x), y: p.y + s * (q.y - p.y) };
}

/**
 * What a trace sounds like, in seconds from its start: `voices` [{ type, from, to, points: [{ time, hz, pan }] }]
 * (a new voice where the timbre changes), `ticks` [{ time, continuity }] (the inner knots), `duration`.
 */
export function planTrace(trace) {
  const [a, b] = domainOf(trace);
  const timeOf = (t) => (b > a ? (t - a) / (b - a) : 0) * TRACE_SECONDS;
  const sound = (p) => ({ time: timeOf(p.t), hz: pitchOf(p.y, trace.yRange), pan: panOf(p.x, trace.xRange) });
  const ticks = innerKnots(trace).map((k) => ({ time: timeOf(k.t), continuity: k.continuity }));
  // stretches between timbre changes: sine at the start, then each joint's timbre until the next one that differs
  const cuts = [{ t: a, type: 'sine' }];
  for (const k of innerKnots(trace)) {
    const type = timbreOf(k.continuity);
    if (type !== cuts[cuts.length - 1].type) cuts.push({ t: k.t, type });
  }
  const voices = cuts.map((c, i) => {
    const to = i + 1 < cuts.length ? cuts[i + 1].t : b;
    const inside = trace.samples.filter((s) => s.t > c.t && s.t < to);
    const points = [pointAt(trace, c.t), ...inside, pointAt(trace, to)].map(sound);
    return { type: c.type, from: timeOf(c.t), to: timeOf(to), points };
  });
  return { voices, ticks, duration: TRACE_SECONDS };
}

/** "u = 0.35: (1.20, 0.50)" with Unicode minus signs. */
export function pointText(param, { t, x, y }) {
  const f = (v) => { const s = v.toFixed(2); return localDigits((/^-0\.00$/.test(s) ? '0.00' : s).replace('-', '−')); };
  return `${param} = ${f(t)}: (${f(x)}${pairSep()}${f(y)})`;
}

/** The ♪ button and the keys of one plot. `row`: the plot's tool row; `announce(text)`: its live region. */
export function attachAudioTrace({ canvas, row, trace, announce }) {
  const button = h('button', {
    type: 'button', class: 'plot-tool plot-sound', title: tt('Play as sound (S; comma and period step)'), 'aria-label': tt('Play as sound'),
    'aria-pressed': 'false', onclick: () => toggle(),
  }, '♪');
  row.appendChild(button);
  /** @type {AudioContext | null} */
  let ctx = null;
  let click = null;           // the tick's sound: 4 ms of a decaying pulse
  let sources = [];           // every started node of the playing trace (stop() ends them)
  let endTimer = 0, cursor = -1, tracing = false; // tracing: the whole trace plays (not a step's tone)

  function audio() {
    if (ctx) return ctx;
    const AC = window.AudioContext || /** @type {any} */ (window).webkitAudioContext;
    if (!AC) { announce(tt('This browser cannot play sound.')); return null; }
    ctx = new AC();
    click = ctx.createBuffer(1, Math.max(1, Math.round(ctx.sampleRate * 0.004)), ctx.sampleRate);
    const d = click.getChannelData(0);
    for (let i = 0; i < d.length; i++) d[i] = (i % 2 ? -1 : 1) * (1 - i / d.length);
    return ctx;
  }

  /** One voice: an oscillator of `type` through its own fading gain into `out`, following `points`. */
  function voice(ac, out, start, type, from, to, points) {
    const osc = ac.createOscillator(), g = ac.createGain();
    osc.type = type;
    const f = osc.frequency;
    f.setValueAtTime(points[0].hz, start + points[0].time);
    for (const q of points.slice(1)) f.linearRampToValueAtTime(q.hz, start + q.time);
    const fade = Math.min(FADE, (to - from) / 3);
    g.gain.setValueAtTime(0, start + from);
    g.gain.linearRampToValueAtTime(GAIN, start + from + fade);
    g.gain.setValueAtTime(GAIN, start + to - fade);
    g.gain.linearRampToValueAtTime(0, start + to);
    osc.connect(g).connect(out);
    osc.start(start + from);
    osc.stop(start + to + 0.01);
    sources.push(osc);
  }

  /** A panner (or the destination where StereoPannerNode does not exist) following `pans` [{ time, pan }]. */
  function output(ac, start, pans) {
    if (!ac.createStereoPanner) return ac.destination;
    const pan = ac.createStereoPanner();
    pan.pan.setValueAtTime(pans[0].pan, start + pans[0].time);
    for (const q of pans.slice(1)) pan.pan.linearRampToValueAtTime(q.pan, start + q.time);
    pan.connect(ac.destination);
    return pan;
  }

  function play() {
    const tr = trace();
    if (!tr || !tr.samples || tr.samples.length < 2) { announce(tt('Nothing to play.')); return; }
    const ac = audio();
    if (!ac) return;
    stop(true);
    ac.resume?.();
    const plan = planTrace(tr), start = ac.currentTime + 0.05;
    const out = output(ac, start, plan.voices.flatMap((v) => v.points));
    for (const v of plan.voices) voice(ac, out, start, v.type, v.from, v.to, v.points);
    const tickGain = ac.createGain();
    tickGain.gain.value = GAIN;
    tickGain.connect(out);
    for (const k of plan.ticks) {
      const src = ac.createBufferSource();
      src.buffer = click;
      src.connect(tickGain);
      src.start(start + k.time);
      sources.push(src);
    }
    setPressed(true);
    const smooth = plan.voices.length === 1 ? tt('smooth throughout') : tn(plan.voices.length - 1, 'tone changes at {n} less smooth joint', 'tone changes at {n} less smooth joints');
    announce(tt('Playing {name} as sound: {clicks}, {smooth}.', { name: tt(tr.name), clicks: tn(plan.ticks.length, '{n} knot click', '{n} knot clicks'), smooth }));
    endTimer = setTimeout(() => { sources = []; setPressed(false); }, (plan.duration + 0.1) * 1000);
  }

  /** Stops what plays (quiet: no announcement, before a new sound). */
  function stop(quiet = false) {
    clearTimeout(endTimer);
    const was = sources.length > 0;
    for (const s of sources) { try { s.stop(); } catch { /* already stopped */ } }
    sources = [];
    setPressed(false);
    if (was && !quiet) announce(tt('Sound stopped.'));
  }

  function setPressed(on) {
    // a toggle button keeps its name ("Play as sound"); pressed = playing, and the glyph shows the stop square
    tracing = on;
    button.setAttribute('aria-pressed', String(on));
    button.title = on ? 'Stop the sound (S)' : 'Play as sound (S; comma and period step)';
    button.textContent = on ? '■' : '♪';
  }

  const toggle = () => (tracing ? stop() : play());

  /** , and .: the point 1/STEPS of the domain before / after the last one stepped to, as a short tone and in words. */
  function step(dir) {
    const tr = trace();
    if (!tr || !tr.samples || tr.samples.length < 2) { announce(tt('Nothing to play.')); return; }
    cursor = cursor < 0 ? (dir > 0 ? 0 : STEPS) : Math.min(STEPS, Math.max(0, cursor + dir));
    const [a, b] = domainOf(tr);
    const p = pointAt(tr, a + (b - a) * cursor / STEPS);
    announce(pointText(tr.param || 'u', p));
    const ac = audio();
    if (!ac) return;
    stop(true);
    ac.resume?.();
    const start = ac.currentTime + 0.02, hz = pitchOf(p.y, tr.yRange);
    const out = output(ac, start, [{ time: 0, pan: panOf(p.x, tr.xRange) }]);
    voice(ac, out, start, 'sine', 0, STEP_TONE, [{ time: 0, hz }, { time: STEP_TONE, hz }]);
    endTimer = setTimeout(() => { sources = []; }, (STEP_TONE + 0.1) * 1000);
  }

  function onKey(e) {
    if (e.altKey || e.ctrlKey || e.metaKey) return;
    // S (sound): the ♪ button's key, on the focused plot only (a plot's keys are active only on it, SC 2.1.4)
    if (e.key === 's' || e.key === 'S') toggle();
    else if (e.key === ',') step(-1);
    else if (e.key === '.') step(1);
    else return;
    e.preventDefault();
  }
  canvas.addEventListener('keydown', onKey);

  return {
    button,
    get playing() { return tracing; },
    play, stop, step,
    dispose() { stop(true); canvas.removeEventListener('keydown', onKey); ctx?.close?.(); ctx = null; },
  };
}
