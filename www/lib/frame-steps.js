// Work split over animation frames (issue 26): an action whose work does not fit in one frame (parse 2000 pasted
// points, start the workers, paint two plots of 2000 points each) does one part now and each next part in a frame of
// its own, so no single frame of the page runs all of it.
//
//   afterNextFrame(fn)          → cancel(): fn runs in a task of its own once the next frame has been rendered
//   const steps = frameSteps();
//   steps.run([a, b, c])        a now, b after the frame a asked for is on screen, c after b's; a newer run() or
//                               steps.cancel() drops the steps not yet run (the newest action wins: a step that
//                               was superseded never draws after the newer action)
//
// Why a frame and not just a task: a frame's work is every task between two renderings plus its animation-frame
// callbacks (a plot's paint), so a part split off into the next task would still share the frame. A message posted
// from a requestAnimationFrame callback is handled after that frame's rendering: the part starts the next frame,
// and the paint it asks for (plot2d's redraw) is in that frame, not in this one. (A message, not a zero timeout:
// no 4 ms clamp, and the page's timers stay the shell's own: main-thread.test tells them apart by their invoker.)
// In a hidden tab no frames come: the steps wait and run when the page is shown again.

const raf = (f) => (typeof requestAnimationFrame === 'function' ? requestAnimationFrame(f) : setTimeout(f, 16));
const unraf = (id) => (typeof cancelAnimationFrame === 'function' ? cancelAnimationFrame(id) : clearTimeout(id));

/** Calls `fn` in a task of its own after the next frame has been rendered. Returns a function that cancels it. */
export function afterNextFrame(fn) {
  let port = null;
  const frame = raf(() => {
    const ch = new MessageChannel();
    port = ch.port1;
    port.onmessage = () => { port.close(); fn(); };
    ch.port2.postMessage(null);
  });
  return () => { unraf(frame); if (port) { port.onmessage = null; port.close(); } };
}

/**
 * A sequence of steps, one per frame. `run(steps)` drops what an earlier run has not done yet, calls the first step
 * now and each next one after the frame of the one before has been rendered. A step may end the run early with
 * `cancel()` (or by starting a new run). `pending` is true while steps are waiting.
 */
export function frameSteps() {
  let generation = 0;
  let cancelNext = null;
  function cancel() {
    generation++;
    cancelNext?.();
    cancelNext = null;
  }
  /** @param {Array<() => void>} steps */
  function run(steps) {
    cancel();
    const mine = generation;
    let i = 0;
    const step = () => {
      cancelNext = null;
      steps[i++]();
      if (mine === generation && i < steps.length) cancelNext = afterNextFrame(step);
    };
    step();
  }
  return { run, cancel, get pending() { return cancelNext !== null; } };
}
