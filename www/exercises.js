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

const GROUPS = [
  ...PAPERS.map((p) => ({ key: p.key, title: `${p.authors}: ${p.title}` })),
  { key: 'bg', title: 'Background: B-splines and their knots' },
];

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
  } }, 'Download for LMS (SCORM)');
  return h('div', { class: 'exercise-scorm-row' }, button, h('p', null, status));
}

/** An exercise link pasted by a teacher → { id, title, hash } (its exercise read from the link), or an Error. */
async function fromLink(line, mods) {
  let hash = line.trim();
  const at = hash.indexOf('#');
  if (at < 0) throw new Error(`“${line.trim().slice(0, 60)}” is not a SplineLab link (no #)`);
  hash = hash.slice(at);
  const { id: demo, payload } = parseHash(hash);
  if (!demo || !payload) throw new Error(`“${line.trim().slice(0, 60)}” names no demo state`);
  if (!mods.has(demo)) mods.set(demo, await importDemo(demo));
  const raw = await decodeState(payload);
  const ex = readExercise(raw, demo);
  if (!ex) throw new Error(`the link to “${mods.get(demo).meta.title}” holds no exercise (make one with Make exercise)`);
  return { id: ex.id, title: ex.title || `${mods.get(demo).meta.title}: ${ex.check}`, hash: `#${demo}/${payload}` };
}

/** The set maker: the ticked catalogue exercises, in the order ticked, then the pasted links; one package. */
function setMaker(picked, mods) {
  const list = h('ol', { class: 'scorm-set-picked' });
  const titleIn = h('input', { type: 'text', class: 'scorm-set-title', value: 'SplineLab exercises', maxlength: '200' });
  const grading = gradingFields({ passMark: 60 });
  const linksIn = h('textarea', { class: 'scorm-set-links', rows: 3, placeholder: 'https://…/index.html#interp-approx/v1.…' });
  const status = h('p', { class: 'scorm-set-status', role: 'status' });
  const refresh = () => {
    clear(list);
    append(list, picked.length ? picked.map((x) => h('li', null, x.title)) : h('li', { class: 'scorm-set-none' }, 'None ticked yet.'));
  };
  const go = h('button', { type: 'button', class: 'btn btn-primary scorm-set-go', onclick: async () => {
    const rules = grading.read();
    if (rules.error) { status.textContent = rules.error; return; }
    go.disabled = true;
    try {
      const own = [];
      for (const line of linksIn.value.split('\n').filter((l) => l.trim())) {
        try { own.push(await fromLink(line, mods)); } catch (e) { status.textContent = `A pasted link cannot be used: ${e.message}.`; linksIn.focus(); return; }
      }
      const items = [...picked, ...own];
      if (items.length < 2) { status.textContent = `A set needs two exercises or more (${items.length} chosen): tick them below or paste links; one exercise has its own button.`; return; }
      const title = titleIn.value.trim() || 'SplineLab exercises';
      await savePackage({ id: 'splinelab-set', title, ...rules, items }, `splinelab-set-${items.length}-scorm.zip`, status);
    } finally { go.disabled = false; }
  } }, 'Download the set for LMS (SCORM)');
  refresh();
  const el = h('section', { class: 'scorm-set-maker', 'aria-labelledby': 'scorm-set-h' },
    h('h2', { id: 'scorm-set-h' }, 'A set of exercises for your LMS'),
    h('p', null, 'Tick “In the set” on the exercises below, in the order your students should do them, and/or paste links to your own exercises (from Make exercise). The set becomes one SCORM package with one score: the mean of the exercises’ best scores.'),
    list, field('Your own exercise links, one per line (optional)', linksIn),
    field('Title in the LMS', titleIn), ...grading.fields, go, status);
  return { el, refresh };
}

async function start() {
  const box = document.getElementById('catalogue');
  const mods = new Map();
  for (const id of new Set(CATALOGUE.map((e) => e.demo))) mods.set(id, await importDemo(id));
  const picked = [];
  const maker = setMaker(picked, mods);
  const sections = [];
  for (const g of GROUPS) {
    const items = CATALOGUE.filter((e) => e.paper === g.key);
    if (!items.length) continue;
    const cards = [];
    for (const e of items) {
      const mod = mods.get(e.demo);
      const state = { ...mod.defaults(), ...structuredClone(e.start) };
      const hash = await exerciseHash(e.demo, state, catalogueExercise(e));
      const item = { id: e.id, title: e.title, hash };
      const pick = h('input', { type: 'checkbox', class: 'exercise-pick-box', onchange: () => {
        const at = picked.indexOf(item);
        if (pick.checked && at < 0) picked.push(item);
        if (!pick.checked && at >= 0) picked.splice(at, 1);
        maker.refresh();
      } });
      cards.push(h('li', null, h('article', { class: 'exercise-card', dataset: { exercise: e.id, demo: e.demo } },
        h('h3', null, e.title),
        h('p', null, e.exercise.task),
        h('p', { class: 'exercise-meta' }, `In “${mod.meta.title}”`),
        h('p', null, h('a', { class: 'exercise-open', href: `index.html${hash}` }, `Open “${e.title}”`), ' · ',
          h('a', { class: 'exercise-embed', href: `embed.html${hash}` }, 'embeddable version')),
        scormButton(item),
        h('label', { class: 'exercise-pick' }, pick, ' In the set'))));
    }
    sections.push(h('section', { class: 'exercise-group', dataset: { paper: g.key } }, h('h2', null, g.title), h('ul', { class: 'exercise-list' }, cards)));
  }
  clear(box);
  append(box, maker.el, sections);
  document.documentElement.dataset.ready = 'true';
}

start().catch((e) => {
  const box = document.getElementById('catalogue');
  append(box, h('p', { class: 'fatal', role: 'alert' }, `The exercises could not be listed: ${e.message}`));
  document.documentElement.dataset.ready = 'error';
});
