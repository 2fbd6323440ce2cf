// Iframes that size themselves: when embed.html runs inside an iframe, it tells the parent page its height.
//
// Two protocols, both one-way from the figure's point of view (the parent decides):
//  1. The H5P resizer protocol that Moodle, WordPress and other LMS pages already load for H5P content
//     (h5p-resizer.js). Messages are objects with `context: 'h5p'`:
//       child → parent  { context: 'h5p', action: 'hello' }                        at start (and on parent 'ready')
//       parent → child  { context: 'h5p', action: 'hello' }                        the parent speaks the protocol
//       child → parent  { context: 'h5p', action: 'prepareResize', scrollHeight, clientHeight }
//       child → parent  { context: 'h5p', action: 'resize', scrollHeight }         after prepareResize, and after
//       parent → child  { context: 'h5p', action: 'resizePrepared' }              … the parent's reply
//       parent → child  { context: 'h5p', action: 'resize' }                       the parent window resized:
//                                                                                   measure again
//     After the parent's hello, every change of the page height sends prepareResize + resize.
//  2. SplineLab's own message for pages without H5P, posted on every height change (from the start):
//       child → parent  { type: 'splinelab:resize', height, demo }
//     The guide (www/guide.html, "Iframes that size themselves") gives the few lines a parent page needs.
// Heights are CSS pixels of document.body.scrollHeight, rounded up. Nothing here reads the parent page; messages
// carry only the height and the demo id, so they are posted with targetOrigin '*'.
//
// Imported for its effect by app.js (`import './lib/resize.js';`); does nothing outside an iframe.

/** The height the parent should give the iframe. */
export function contentHeight() {
  return Math.ceil(Math.max(document.body.scrollHeight, document.body.getBoundingClientRect().height));
}

export function startResizer(win = window) {
  if (win.parent === win) return null; // not in an iframe
  const parent = win.parent;
  let h5p = false;          // the parent answered hello
  let last = -1;            // last height posted
  let frame = 0;
  const post = (msg) => { try { parent.postMessage(msg, '*'); } catch { /* parent gone */ } };
  const h5pResize = () => {
    post({ context: 'h5p', action: 'prepareResize', scrollHeight: contentHeight(), clientHeight: document.body.clientHeight });
    post({ context: 'h5p', action: 'resize', scrollHeight: contentHeight() });
  };
  const measure = (force = false) => {
    frame = 0;
    const height = contentHeight();
    if (!force && Math.abs(height - last) < 1) return;
    last = height;
    post({ type: 'splinelab:resize', height, demo: document.body.dataset.demo || '' });
    if (h5p) h5pResize();
  };
  const soon = () => { if (!frame) frame = requestAnimationFrame(() => measure()); };

  win.addEventListener('message', (e) => {
    if (e.source !== parent) return;
    const d = e.data;
    if (!d || typeof d !== 'object' || d.context !== 'h5p') return;
    if (d.action === 'hello') {
      h5p = true;
      h5pResize();
    } else if (d.action === 'ready') {
      post({ context: 'h5p', action: 'hello' });
    } else if (d.action === 'resizePrepared') {
      post({ context: 'h5p', action: 'resize', scrollHeight: contentHeight() });
    } else if (d.action === 'resize') {
      measure(true);
    }
  });

  if (typeof ResizeObserver === 'function') {
    const ro = new ResizeObserver(soon);
    ro.observe(document.body);
    ro.observe(document.documentElement);
  }
  win.addEventListener('load', soon);
  win.addEventListener('resize', soon);
  // content that changes height without resizing body's box (rare: fonts, images)
  new MutationObserver(soon).observe(document.body, { childList: true, subtree: true, attributes: true, attributeFilter: ['hidden', 'class', 'open'] });

  post({ context: 'h5p', action: 'hello' });
  soon();
  return { measure: () => measure(true) };
}

if (document.body.dataset.mode === 'embed') startResizer();
