// The header's language menu: a button that names the page's language ("Language: Slovenčina") and opens a list of
// the languages, each a button named in itself and marked with its `lang` (a screen reader says "Magyar" in a
// Hungarian voice). Pressing one remembers it (where storage works) and reloads the page in it; the view is kept
// (it is in the link's hash). Where storage is blocked the choice goes into the address as lang=, so the reload
// still shows it.
//
// Not a <select> that acts on `change`: a keyboard moving through a select's options with the arrow keys fires
// `change` at each one (Chromium, Firefox on Windows and Linux), and the page would reload at the first arrow
// (WCAG 3.2.2, On Input). Here nothing happens until a language is pressed.

import { h } from './dom.js';
import { LOCALES, locale, rememberLocale, storedLocale, t } from './i18n.js';

/** Reloads the page in language `c`, keeping the view, and remembers the choice. */
function switchTo(c) {
  rememberLocale(c);
  const u = new URL(location.href);
  if (storedLocale() === c) u.searchParams.delete('lang'); else u.searchParams.set('lang', c);
  // a lang= in the view's options (an "Open in SplineLab" link of an embed) would win over the choice: drop it
  const i = u.hash.indexOf('?');
  if (i >= 0) {
    const q = new URLSearchParams(u.hash.slice(i + 1));
    q.delete('lang');
    u.hash = u.hash.slice(0, i) + ([...q].length ? `?${q}` : '');
  }
  if (u.href === location.href) location.reload(); else location.replace(u.href);
}

/** Appends the menu to `header` (once) and returns it. @param {Element | null} header */
export function languageMenu(header) {
  if (!header) return null;
  header.querySelector('.lang-menu')?.remove();
  const here = locale();
  const list = h('ul', { class: 'lang-list', id: 'lang-list', hidden: true },
    Object.entries(LOCALES).map(([c, name]) => h('li', null, h('button', {
      type: 'button', class: 'lang-choice', lang: c, dataset: { lang: c }, 'aria-current': c === here ? 'true' : null,
      onclick: () => { if (c === here) close(); else switchTo(c); },
    }, name))));
  const toggle = h('button', { type: 'button', class: 'lang-toggle', 'aria-expanded': 'false', 'aria-controls': 'lang-list' },
    h('span', { class: 'lang-word' }, `${t('Language')}: `), h('span', { lang: here }, LOCALES[here]), h('span', { 'aria-hidden': 'true' }, ' ▾'));
  const box = h('div', { class: 'lang-menu' }, toggle, list);
  const open = () => { list.hidden = false; toggle.setAttribute('aria-expanded', 'true'); };
  const close = (focusToggle = false) => {
    list.hidden = true;
    toggle.setAttribute('aria-expanded', 'false');
    if (focusToggle) toggle.focus();
  };
  toggle.addEventListener('click', () => (list.hidden ? open() : close()));
  // Escape closes it (the focus back on its button); so does a press elsewhere, or Tab to something else (a focus
  // that moves to no element, as a click in Safari does, is left to the press: the list must stay for that click)
  box.addEventListener('keydown', (e) => { if (e.key === 'Escape' && !list.hidden) { e.preventDefault(); close(true); } });
  document.addEventListener('pointerdown', (e) => { if (!box.contains(/** @type {Node} */ (e.target))) close(); });
  box.addEventListener('focusout', (e) => { const to = /** @type {Node | null} */ (e.relatedTarget); if (to && !box.contains(to)) close(); });
  header.appendChild(box);
  return box;
}
