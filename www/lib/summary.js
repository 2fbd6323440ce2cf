// A demo's one-paragraph summary under its title that never loses text (WCAG 2.2 SC 1.4.4 Resize Text, 1.4.10
// Reflow). Short screens (a projector at 150 %, or a laptop at 200 % zoom: 683×450 CSS px) keep the header small by
// showing the summary's first lines only (style.css: two lines up to 820 px of height, one up to 560); where the text
// is cut, a "More" button beside it shows the whole paragraph (and "Less" folds it again). The button exists only
// while the text is cut (a ResizeObserver checks after every change of size), so a tall screen has no extra Tab stop.
// Screen readers read the whole paragraph either way (a clamped box keeps its text).
import { h } from './dom.js';
import { t } from './i18n.js';

/** The summary line of a demo page: the paragraph and its More/Less button. @param {string} text */
export function demoSummary(text) {
  const p = h('p', { class: 'demo-summary', id: 'demo-summary' }, text);
  const more = h('button', {
    type: 'button', class: 'summary-more', hidden: true, 'aria-expanded': 'false', 'aria-controls': 'demo-summary',
    'aria-label': t('More of the summary'), onclick: () => setOpen(!p.classList.contains('expanded')),
  }, t('More'));
  function setOpen(open) {
    p.classList.toggle('expanded', open);
    more.setAttribute('aria-expanded', String(open));
    more.textContent = open ? t('Less') : t('More');
    more.setAttribute('aria-label', open ? t('Less of the summary') : t('More of the summary'));
  }
  // cut: the clamped box is shorter than its text (1 px of rounding allowed). Checked in the next frame, not in the
  // observer's callback: showing the button narrows the paragraph, and a size changed inside the callback is a
  // "ResizeObserver loop" error (WebKit logs it to the console)
  const check = () => { if (!p.classList.contains('expanded')) more.hidden = p.scrollHeight <= p.clientHeight + 1; };
  new ResizeObserver(() => requestAnimationFrame(check)).observe(p);
  return h('div', { class: 'demo-summary-line' }, p, more);
}
