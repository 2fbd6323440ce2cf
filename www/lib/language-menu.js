// The header's language menu: a labelled <select> of the languages, each named in itself and marked with its
// `lang` (a screen reader says "Slovenčina" in a Slovak voice). Choosing one remembers it (where storage works)
// and reloads the page in it; the view is kept (it is in the link's hash). Where storage is blocked the choice
// goes into the address as lang=, so the reload still shows it.

import { h } from './dom.js';
import { LOCALES, locale, rememberLocale, t } from './i18n.js';

/** Appends the menu to `header` (once) and returns it. @param {Element | null} header */
export function languageMenu(header) {
  if (!header) return null;
  header.querySelector('.lang-menu')?.remove();
  const select = h('select', { class: 'lang-select', id: 'lang-select', 'aria-label': t('Language') },
    Object.entries(LOCALES).map(([c, name]) => h('option', { value: c, lang: c, selected: c === locale() }, name)));
  select.addEventListener('change', () => {
    const c = select.value;
    rememberLocale(c);
    let kept = null;
    try { kept = localStorage.getItem('splinelab:lang'); } catch { /* blocked */ }
    const u = new URL(location.href);
    if (kept === c) u.searchParams.delete('lang'); else u.searchParams.set('lang', c);
    // a lang= in the view's options (an "Open in SplineLab" link of an embed) would win over the choice: drop it
    const i = u.hash.indexOf('?');
    if (i >= 0) {
      const q = new URLSearchParams(u.hash.slice(i + 1));
      q.delete('lang');
      u.hash = u.hash.slice(0, i) + ([...q].length ? `?${q}` : '');
    }
    if (u.href === location.href) location.reload(); else location.replace(u.href);
  });
  const label = h('label', { class: 'lang-label', for: 'lang-select' }, h('span', { class: 'lang-word' }, t('Language')));
  const box = h('div', { class: 'lang-menu' }, label, select);
  // the select's name comes from its label; the aria-label above is for a label hidden on a phone
  select.removeAttribute('aria-label');
  header.appendChild(box);
  return box;
}
