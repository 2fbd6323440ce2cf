import { startHarness } from '/work/wt/exercises/tests/e2e/harness.mjs';
const H = await startHarness();
const t = await H.open('exercises.html');
const links = await t.page.$$eval('.exercise-card', (cs) => cs.map((c) => ({ id: c.dataset.exercise, href: c.querySelector('.exercise-open').getAttribute('href') })));
for (const l of links.slice(5)) {
  const p = await H.open(l.href);
  const has = await p.page.$('.exercise-check');
  if (!has) { console.log(l.id, 'NO PANEL', await p.page.textContent('#notices'), p.errors()); continue; }
  await p.page.click('.exercise-check');
  const fb = await p.page.textContent('.exercise-feedback');
  console.log(l.id, '|', fb, '|', p.errors().join(';'));
}
await H.close();
