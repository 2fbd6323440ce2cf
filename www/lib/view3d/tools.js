// The tool row of a 3D view (top right): turn, tilt, zoom and frame with single clicks or taps, and a ✥ switch that
// makes the four arrow buttons pan instead (WCAG 2.2 SC 2.5.1 and 2.5.7: orbiting and panning are otherwise drags,
// zooming a pinch or the wheel). Each click goes through the view's own _orbit / _pan / _zoom / fit, then
// _viewChanged (the demo's view listeners: state and link; the camera said in words), like the keys.
import { DEG } from './constants.js';

/** The row's element for `view` (a View3D). @param {any} view */
export function viewTools(view) {
  // Turning, tilting and zooming with single clicks or taps (WCAG 2.2 SC 2.5.1: orbiting is a path-based drag and
  // zooming a pinch or the wheel). Not Tab stops: the keyboard has its keys (arrows, + −, F), and the view stays
  // one Tab stop; a screen reader still finds them as buttons.
  const tool = (label, text, run, { camera = true } = {}) => {
    const b = document.createElement('button');
    b.type = 'button'; b.className = 'sl-view3d-tool'; b.tabIndex = -1; b.textContent = text;
    // (inline: the <spline-lab> element's shadow root has no site stylesheet) 28 px: ≥ 24 px targets (SC 2.5.8)
    b.style.cssText = 'width:28px;height:28px;padding:0;border-radius:6px;cursor:pointer;font:700 15px/1 system-ui,sans-serif;'
      + 'background:rgba(255,255,255,0.92);border:1px solid #c9c9c4;color:#111;';
    b.setAttribute('aria-label', label); b.title = label;
    b.addEventListener('click', () => { run(); if (camera) view._viewChanged(); });
    // a click leaves the focus where it was (on the view: its keys keep working after a click on a tool)
    b.addEventListener('mousedown', (e) => e.preventDefault());
    return b;
  };
  const tools = document.createElement('div');
  tools.className = 'sl-view3d-tools';
  tools.style.cssText = 'position:absolute;top:8px;right:8px;display:flex;gap:4px;';
  // Panning with single clicks too (SC 2.5.7: it is otherwise a right-button, Shift or two-finger drag): the ✥
  // button switches the four arrow buttons from turning and tilting to moving the view, as Shift+arrows do.
  let panning = false;
  const arrow = (turn, pan, text, orbit, move) => {
    const b = tool(turn, text, () => (panning ? move() : orbit()));
    b.dataset.turn = turn; b.dataset.pan = pan;
    return b;
  };
  const arrows = [
    arrow('Turn left', 'Pan left', '↶', () => view._orbit(15 * DEG, 0), () => view._pan(40, 0)),
    arrow('Turn right', 'Pan right', '↷', () => view._orbit(-15 * DEG, 0), () => view._pan(-40, 0)),
    arrow('Tilt up', 'Pan up', '↑', () => view._orbit(0, -15 * DEG), () => view._pan(0, 40)),
    arrow('Tilt down', 'Pan down', '↓', () => view._orbit(0, 15 * DEG), () => view._pan(0, -40)),
  ];
  const panMode = tool('Arrow buttons pan', '✥', () => {
    panning = !panning;
    panMode.setAttribute('aria-pressed', String(panning));
    panMode.style.background = panning ? '#111' : 'rgba(255,255,255,0.92)';
    panMode.style.color = panning ? '#fff' : '#111';
    const texts = panning ? ['←', '→', '↑', '↓'] : ['↶', '↷', '↑', '↓'];
    arrows.forEach((b, i) => { const label = panning ? b.dataset.pan : b.dataset.turn; b.setAttribute('aria-label', label); b.title = label; b.textContent = texts[i]; });
    view._announce(panning ? 'The arrow buttons now pan the view.' : 'The arrow buttons now turn and tilt the view.');
  }, { camera: false });   // (not a change of the view: nothing to say about the camera)
  panMode.setAttribute('aria-pressed', 'false');
  tools.append(
    ...arrows, panMode,
    tool('Zoom in', '+', () => view._zoom(1 / 1.25)), tool('Zoom out', '−', () => view._zoom(1.25)),
    tool('Frame everything', '⤢', () => view.fit()),
  );
  return tools;
}
