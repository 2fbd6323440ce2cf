// The exercise catalogue page: one card per ready-made exercise (www/lib/exercise-catalogue.js), grouped by
// paper, each with its task and links that open it in the full page and in the embeddable page, and its SCORM
// package for an LMS (issue 27); several exercises, ticked here or pasted as links, go into one package with one
// total score.

import { h, append, clear } from './lib/dom.js';
import { PAPERS } from './lib/papers-ref.js';
import { CATALOGUE, catalogueExercise } from './lib/exercise-catalogue.js';
import { exerciseHash, readExercise, gradingFields, savePackage, exerciseField as field } from './lib/exercise.js';
import { decodeState, parseHash } from './lib/state.js';
import { importDemo } from './demos/index.js';
import { t, tn, translateIfKnown, startLocale, linkLocale, translateStatic, locale, missingKeys, askedKeys } from './lib/i18n.js'; // issue 28
import { languageMenu } from './lib/language-menu.js';

// the page's language, for checks and tools (as window.splinelab.i18n of the demo pages)
/** @type {any} */ (window).splinelabExercises = { i18n: { locale, missingKeys, askedKeys } };

/** The groups of cards: a paper (its authors and title as printed: a citation, not translated), then the background. */
const groups = () => [
  // the one paper whose authors are not known says so in words: those are translated
  ...PAPERS.map((p) => ({ key: p.key, title: `${translateIfKnown(p.authors)}: ${p.title}` })),
  { key: 'bg', title: t('Background: B-splines and their knots') },
];

/**
 * A translated sentence with elements in it: each `{name}` of `text` (already through t()) becomes `parts[name]`.
 * @param {string} text @param {Record<string, Node>} parts
 */
const sentence = (text, parts) => text.split(/(\{\w+\})/).map((x) => {
  const m = /^\{(\w+)\}$/.exec(x);
  return m && parts[m[1]] ? parts[m[1]] : x;
});

/**
 * "Download for LMS (SCORM)": the exercise as a SCORM 1.2 package, pass mark 100 (a correct answer); Make
 * exercise in a demo lets the teacher choose another, the set below too.
 */
function scormButton({ id, title, hash }) {
  const status = h('span', { class: 'exercise-scorm-status', role: 'status' });
  const button = h('button', { type: 'button', class: 'btn btn-small exercise-scorm', onclick: async () => {
    button.disabled = true;
    await savePackage({ id, title, passMark: 100, items: [{ id, title, hash }] }, `${id}-scorm.zip`, status);
    button.disabled = false;
  } }, t('Download for LMS (SCORM)'));
  return h('div', { class: 'exercise-scorm-row' }, button, h('p', null, status));
}

/** An exercise link pasted by a teacher → { id, title, hash } (its exercise read from the link), or an Error. */
async function fromLink(line, mods) {
  let hash = line.trim();
  const at = hash.indexOf('#');
  if (at < 0) throw new Error(t('“{link}” is not a SplineLab link (no #)', { link: line.trim().slice(0, 60) }));
  hash = hash.slice(at);
  const { id: demo, payload } = parseHash(hash);
  if (!demo || !payload) throw new Error(t('“{link}” names no demo state', { link: line.trim().slice(0, 60) }));
  if (!mods.has(demo)) mods.set(demo, await importDemo(demo));
  const raw = await decodeState(payload);
  const ex = readExercise(raw, demo);
  const demoTitle = t(mods.get(demo).meta.title);
  if (!ex) throw new Error(t('the link to “{demo}” holds no exercise (make one with Make exercise)', { demo: demoTitle }));
  return { id: ex.id, title: ex.title || `${demoTitle}: ${ex.check}`, hash: `#${demo}/${payload}` };
}

/** The set maker: the ticked catalogue exercises, in the order ticked, then the pasted links; one package. */
function setMaker(picked, mods) {
  const list = h('ol', { class: 'scorm-set-picked' });
  const titleIn = h('input', { type: 'text', class: 'scorm-set-title', value: t('SplineLab exercises'), maxlength: '200' });
  const grading = gradingFields({ passMark: 60 });
  const linksIn = h('textarea', { class: 'scorm-set-links', rows: 3, placeholder: 'https://…/index.html#interp-approx/v1.…' });
  const status = h('p', { class: 'scorm-set-status', role: 'status' });
  const refresh = () => {
    clear(list);
    append(list, picked.length ? picked.map((x) => h('li', null, x.title)) : h('li', { class: 'scorm-set-none' }, t('None ticked yet.')));
  };
  const go = h('button', { type: 'button', class: 'btn btn-primary scorm-set-go', onclick: async () => {
    const rules = grading.read();
    if (rules.error) { status.textContent = rules.error; return; }
    go.disabled = true;
    try {
      const own = [];
      for (const line of linksIn.value.split('\n').filter((l) => l.trim())) {
        try { own.push(await fromLink(line, mods)); } catch (e) { status.textContent = t('A pasted link cannot be used: {error}.', { error: e.message }); linksIn.focus(); return; }
      }
      const items = [...picked, ...own];
      if (items.length < 2) { status.textContent = tn(items.length, 'A set needs two exercises or more ({n} chosen): tick them below or paste links; one exercise has its own button.', 'A set needs two exercises or more ({n} chosen): tick them below or paste links; one exercise has its own button.'); return; }
      const title = titleIn.value.trim() || t('SplineLab exercises');
      await savePackage({ id: 'splinelab-set', title, ...rules, items }, `splinelab-set-${items.length}-scorm.zip`, status);
    } finally { go.disabled = false; }
  } }, t('Download the set for LMS (SCORM)'));
  refresh();
  const el = h('section', { class: 'scorm-set-maker', 'aria-labelledby': 'scorm-set-h' },
    h('h2', { id: 'scorm-set-h' }, t('A set of exercises for your LMS')),
    h('p', null, t('Tick “In the set” on the exercises below, in the order your students should do them, and/or paste links to your own exercises (from Make exercise). The set becomes one SCORM package with one score: the mean of the exercises’ best scores.')),
    list, field(t('Your own exercise links, one per line (optional)'), linksIn),
    field(t('Title in the LMS'), titleIn), ...grading.fields, go, status);
  return { el, refresh };
}

/** The page's introduction: one translated text with the Check and Make exercise words and the guide's link in it. */
function intro() {
  const p = document.getElementById('exercises-intro');
  if (!p) return;
  p.replaceChildren(...sentence(t('Each exercise opens a live figure with a task. Change the figure (drag points, move sliders, pick an option; an exact value is typed into the box beside its slider, and fractions such as 1/6 or 3/4 are read), then press {check}: SplineLab measures the construction exactly and says how far off you are, with a hint. Every exercise is a link, so it can be put on a course page as it is or embedded (see {guide}, which also explains how a course page collects the results). Teachers make their own from any view with {make}.'), {
    check: h('strong', null, t('Check')),
    guide: h('a', { href: 'guide.html#exercises' }, t('the guide')),
    make: h('strong', null, t('Make exercise')),
  }));
}

async function start() {
  await startLocale({ param: linkLocale() });
  translateStatic();
  intro();
  languageMenu(document.querySelector('.site-header'));
  // a lang= of this page's link goes on to the exercises' links (a reader's own choice is remembered anyway)
  const given = linkLocale() !== null && locale() !== 'en';
  const box = document.getElementById('catalogue');
  const mods = new Map();
  for (const id of new Set(CATALOGUE.map((e) => e.demo))) mods.set(id, await importDemo(id));
  const picked = [];
  const maker = setMaker(picked, mods);
  const sections = [];
  for (const g of groups()) {
    const items = CATALOGUE.filter((e) => e.paper === g.key);
    if (!items.length) continue;
    const cards = [];
    for (const e of items) {
      const mod = mods.get(e.demo);
      const state = { ...mod.defaults(), ...structuredClone(e.start) };
      const hash = await exerciseHash(e.demo, state, catalogueExercise(e));
      // the link keeps the English text (a reader in another language sees it translated: translateIfKnown); the
      // package's title is what this page shows
      const title = t(e.title);
      const item = { id: e.id, title, hash };
      const link = given ? `?lang=${locale()}` : '';
      const pick = h('input', { type: 'checkbox', class: 'exercise-pick-box', onchange: () => {
        const at = picked.indexOf(item);
        if (pick.checked && at < 0) picked.push(item);
        if (!pick.checked && at >= 0) picked.splice(at, 1);
        maker.refresh();
      } });
      cards.push(h('li', null, h('article', { class: 'exercise-card', dataset: { exercise: e.id, demo: e.demo } },
        h('h3', null, title),
        h('p', null, t(e.exercise.task)),
        h('p', { class: 'exercise-meta' }, t('In “{demo}”', { demo: t(mod.meta.title) })),
        h('p', null, h('a', { class: 'exercise-open', href: `index.html${link}${hash}` }, t('Open “{title}”', { title })), ' · ',
          h('a', { class: 'exercise-embed', href: `embed.html${link}${hash}` }, t('embeddable version'))),
        scormButton(item),
        h('label', { class: 'exercise-pick' }, pick, ` ${t('In the set')}`))));
    }
    sections.push(h('section', { class: 'exercise-group', dataset: { paper: g.key } }, h('h2', null, g.title), h('ul', { class: 'exercise-list' }, cards)));
  }
  clear(box);
  append(box, maker.el, sections);
  document.documentElement.dataset.ready = 'true';
}

start().catch((e) => {
  const box = document.getElementById('catalogue');
  append(box, h('p', { class: 'fatal', role: 'alert' }, t('The exercises could not be listed: {error}', { error: e.message })));
  document.documentElement.dataset.ready = 'error';
});
