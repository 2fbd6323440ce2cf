import { startHarness } from './harness.mjs';
const H = await startHarness();
const t = await H.open('#bspline-basics');
await t.page.click('.share-toggle');
await t.frames(3);
console.log(await t.screenshot('course-share', { fullPage: true }));
const t2 = await H.open('#knot-modification');
console.log(await t2.screenshot('course-knot', { fullPage: true }));
await H.close();
