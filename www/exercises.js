// The exercise catalogue page: one card per ready-made exercise (www/lib/exercise-catalogue.js), grouped by
// paper, each with its task and links that open it in the full page and in the embeddable page.

import { h, append, clear } from './lib/dom.js';
import { PAPERS } from './lib/papers-ref.js';
import { CATALOGUE, catalogueExercise } from './lib/exercise-catalogue.js';
import { exerciseHash } from './lib/exercise.js';
import { importDemo } from './demos/index.js';

const GROUPS = [
  ...PAPERS.map((p) => ({ key: p.key, title: `${p.authors}: ${p.title}` })),
  { key: 'bg', title: 'Background: B-splines and their knots' },
];

async function start() {
  const box = document.getElementById('catalogue');
  const mods = new Map();
  for (const id of new Set(CATALOGUE.map((e) => e.demo))) mods.set(id, await importDemo(id));
  const sections = [];
  for (const g of GROUPS) {
    const items = CATALOGUE.filter((e) => e.paper === g.key);
    if (!items.length) continue;
    const cards = [];
    for (const e of items) {
      const mod = mods.get(e.demo);
      const state = { ...mod.defaults(), ...structuredClone(e.start) };
      const hash = await exerciseHash(e.demo, state, catalogueExercise(e));
      cards.push(h('li', null, h('article', { class: 'exercise-card', dataset: { exercise: e.id, demo: e.demo } },
        h('h3', null, e.title),
        h('p', null, e.exercise.task),
        h('p', { class: 'exercise-meta' }, `In “${mod.meta.title}”`),
        h('p', null, h('a', { class: 'exercise-open', href: `index.html${hash}` }, `Open “${e.title}”`), ' · ',
          h('a', { class: 'exercise-embed', href: `embed.html${hash}` }, 'embeddable version')))));
    }
    sections.push(h('section', { class: 'exercise-group', dataset: { paper: g.key } }, h('h2', null, g.title), h('ul', { class: 'exercise-list' }, cards)));
  }
  clear(box);
  append(box, sections);
  document.documentElement.dataset.ready = 'true';
}

start().catch((e) => {
  const box = document.getElementById('catalogue');
  append(box, h('p', { class: 'fatal', role: 'alert' }, `The exercises could not be listed: ${e.message}`));
  document.documentElement.dataset.ready = 'error';
});
