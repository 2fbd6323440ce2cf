// The state rules of "Quasi-cubic curves": what a link may hold (a known preset, α in [−3, 3], 4…MAX_POINTS
// points, a valid step) and the shape each preset fixes (ellipse and circle: closed, 4 points; parabola: open,
// 4 points; sine: open). A link that names a preset but no points of its own takes the preset's polygon.
import { PRESETS, FREE_POINTS, MAX_POINTS, samePoints } from './data.js';
import { presetData } from './compute.js';
/** @typedef {import('../../lib/host.js').SplineLab} SplineLab the wasm module's exports (types/splinelab.d.ts) */

/** Puts preset `name`'s polygon, closedness and α into the state (false, reported, when the call fails). @param {SplineLab} wasm */
export function takePreset(wasm, state, name, notify) {
  try {
    Object.assign(state, { preset: name }, presetData(wasm, name));
    return true;
  } catch (e) { notify(e, 'error'); return false; }
}

/** Brings a state (from a link or an import) within the rules. @param {SplineLab} wasm */
export function sanitize(wasm, state, notify) {
  const loadPreset = (name) => takePreset(wasm, state, name, notify);
  if (!PRESETS.includes(state.preset)) state.preset = 'free';
  if (!(state.alpha >= -3 && state.alpha <= 3)) state.alpha = 0.5;
  if (!Array.isArray(state.points) || state.points.length < 4) state.points = FREE_POINTS.map((p) => p.slice());
  if (state.points.length > MAX_POINTS) state.points.length = MAX_POINTS;
  // A link that names a preset but no points gets the defaults' free polygon, which no preset's condition
  // holds for (a sine preset on it reads "broken"): such a state takes the preset's own points (and α).
  // Points a user dragged are never the free polygon exactly, so they stay.
  if (state.preset !== 'free' && samePoints(state.points, FREE_POINTS)) loadPreset(state.preset);
  if (state.preset === 'ellipse' || state.preset === 'circle') { state.closed = true; if (state.points.length !== 4) loadPreset(state.preset); }
  if (state.preset === 'parabola') { state.closed = false; if (state.points.length !== 4) loadPreset('parabola'); }
  if (state.preset === 'sine') state.closed = false;
  if (!Number.isInteger(state.step) || state.step < -1 || state.step > 4) state.step = -1;
}
