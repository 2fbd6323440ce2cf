// What a person reads or hears on a page, for the language checks (tests/e2e/i18n.test.mjs): every visible text
// node, and the aria-label, title, placeholder and alt of every element, each with where it is. Left out: formulas
// (<math>; notation stays as it is), code (<code>, <pre>, textareas of embed code: code is not translated), what
// the page marks translate="no" (the brand SplineLab),
// inputs' values (numbers a person typed), and text that has no two letters in a row (numbers, symbols, "u").

/** Runs in the page: the texts as [{ text, where }], where = 'text' | the attribute's name, with a CSS-ish path. */
export function pageTexts() {
  const out = [];
  const skip = (el) => el.closest('math, code, pre, script, style, noscript, textarea, [translate="no"]');
  const visible = (el) => {
    if (!(el instanceof Element)) return false;
    if (el.closest('[hidden], [aria-hidden="true"]')) return false;
    const r = el.getClientRects();
    if (!r.length) return false;
    const cs = getComputedStyle(el);
    return cs.visibility !== 'hidden' && cs.display !== 'none';
  };
  const path = (el) => {
    const parts = [];
    for (let e = el; e && e !== document.body && parts.length < 4; e = e.parentElement) {
      parts.unshift(e.tagName.toLowerCase() + (e.className && typeof e.className === 'string' ? `.${e.className.trim().split(/\s+/)[0]}` : ''));
    }
    return parts.join(' > ');
  };
  const words = (s) => /(?:(?!\p{Lm})\p{L}){2}/u.test(s);   // (Nᵢ,ₚ is notation, not words)
  const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
  for (let n = walker.nextNode(); n; n = walker.nextNode()) {
    const s = n.textContent.replace(/\s+/g, ' ').trim();
    const el = n.parentElement;
    if (!s || !words(s) || !el || skip(el) || !visible(el)) continue;
    // a visually hidden text (class visually-hidden) is read by a screen reader: it counts
    out.push({ text: s, where: path(el) });
  }
  for (const el of document.querySelectorAll('[aria-label], [title], [placeholder], img[alt], [aria-roledescription]')) {
    if (skip(el) || el.closest('[hidden]')) continue;
    for (const a of ['aria-label', 'title', 'placeholder', 'alt', 'aria-roledescription']) {
      const v = el.getAttribute(a);
      if (v && words(v)) out.push({ text: v.replace(/\s+/g, ' ').trim(), where: `${path(el)} [${a}]` });
    }
  }
  out.push({ text: document.title, where: 'title' });
  return out;
}
