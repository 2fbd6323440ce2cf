// "Play u": a Play/Pause toggle button that runs a demo's evaluation parameter u along its domain.
//
//   const player = uPlayer({ range: () => [0, 1], get: () => state.u, set(u) { state.u = u; …redraw… },
//                            onPause() { ctx.save(); } });
//   controls.append(player.el);   …   player.destroy() in the demo's destroy()
//
// The button's accessible name stays "Play u" (a toggle: aria-pressed says whether it plays). It loops from
// the start of the domain to its end in `duration` ms. With prefers-reduced-motion it does not animate: it
// steps u by 1/`steps` of the domain about once a second. Pauses on destroy, when the page is hidden and when
// the user takes the u control (call player.pause()).

import { t } from './i18n.js';

const prefersReducedMotion = () => typeof matchMedia === 'function' && matchMedia('(prefers-reduced-motion: reduce)').matches;

/**
 * @param {{ range?: () => number[], get?: () => number, set?: (u: number) => void, onPause?: () => void,
 *   duration?: number, steps?: number, label?: string }} options
 */
export function uPlayer({ range, get, set, onPause, duration = 6000, steps = 20, label = 'Play u' } = {}) {
  const btn = document.createElement('button');
  btn.type = 'button';
  btn.className = 'btn btn-secondary play-u';
  btn.setAttribute('aria-pressed', 'false');
  const pauseLabel = t(label.replace(/^Play\b/, 'Pause'));
  label = t(label);
  btn.setAttribute('aria-label', label);
  btn.title = t('Animate the evaluation point along the curve (again to pause)');
  const icon = document.createElement('span');
  icon.setAttribute('aria-hidden', 'true');
  icon.className = 'play-u-icon';
  const txt = document.createElement('span');
  btn.append(icon, txt);
  let raf = 0, timer = 0, playing = false, last = 0, destroyed = false;

  function show() {
    icon.textContent = playing ? '❚❚' : '▶';
    txt.textContent = ` ${playing ? pauseLabel : label}`;
    btn.setAttribute('aria-pressed', String(playing));
    btn.dataset.playing = String(playing);
  }

  function advance(du) {
    const [a, b] = range();
    if (!(b > a)) return;
    let u = Number(get());
    if (!Number.isFinite(u)) u = a;
    u += du * (b - a);
    if (u > b + 1e-12) u = a + ((u - b) % (b - a)); // loop
    set(Math.min(b, Math.max(a, u)));
  }

  function frame(t) {
    raf = 0;
    if (!playing || destroyed) return;
    const dt = last ? Math.min(100, t - last) : 16;
    last = t;
    const [a, b] = range();
    // at the end: jump back to the start (a visible restart, not a wrap-around in the middle of a frame)
    if (Number(get()) >= b - 1e-9) set(a); else advance(dt / duration);
    raf = requestAnimationFrame(frame);
  }

  function play() {
    if (playing || destroyed) return;
    playing = true;
    last = 0;
    const [, b] = range();
    if (Number(get()) >= b - 1e-9) set(range()[0]);
    if (prefersReducedMotion()) {
      advance(1 / steps);
      timer = setInterval(() => advance(1 / steps), 1000);
    } else {
      raf = requestAnimationFrame(frame);
    }
    show();
  }

  function pause() {
    if (!playing) return;
    playing = false;
    cancelAnimationFrame(raf); raf = 0;
    clearInterval(timer); timer = 0;
    show();
    if (typeof onPause === 'function') onPause();
  }

  const onVisibility = () => { if (document.hidden) pause(); };
  btn.addEventListener('click', () => (playing ? pause() : play()));
  document.addEventListener('visibilitychange', onVisibility);
  show();

  return {
    el: btn,
    play, pause,
    toggle: () => (playing ? pause() : play()),
    get playing() { return playing; },
    destroy() {
      destroyed = true;
      playing = false;
      cancelAnimationFrame(raf); clearInterval(timer);
      document.removeEventListener('visibilitychange', onVisibility);
    },
  };
}
