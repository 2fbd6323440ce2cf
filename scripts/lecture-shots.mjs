// Screenshots of the lecture-room layout for the README and the guide (issue 19):
//   node scripts/lecture-shots.mjs   →  docs/static/lecture-{projector,present,phone}.png
// Projector: 1280×720 device pixels at 150 % zoom (853×480 CSS px, deviceScaleFactor 1.5); phone: 390×844.
// Served from www/ by scripts/static-server.mjs, headless Chromium (tests/e2e/harness.mjs). Keep each < 200 KB.
import { stat } from 'node:fs/promises';
import { join } from 'node:path';
import { startHarness, ROOT } from '../tests/e2e/harness.mjs';

const OUT = join(ROOT, 'docs/static');
const H = await startHarness();
const shots = [
  { name: 'lecture-projector', route: '#knot-modification', viewport: { width: 853, height: 480 }, dpr: 1.5 },
  { name: 'lecture-present', route: '#interp-approx', viewport: { width: 853, height: 480 }, dpr: 1.5, present: true },
  { name: 'lecture-phone', route: '#bspline-basics', viewport: { width: 390, height: 844 }, dpr: 1 },
];
try {
  for (const s of shots) {
    const t = await H.open(s.route, { viewport: s.viewport, deviceScaleFactor: s.dpr, reducedMotion: 'reduce' });
    if (s.present) {
      await t.page.getByRole('button', { name: 'Present', exact: true }).click();
      await t.page.getByRole('button', { name: 'Show controls' }).click();
    }
    await t.page.evaluate(() => document.activeElement?.blur());
    await t.frames(4);
    const path = join(OUT, `${s.name}.png`);
    await t.page.screenshot({ path });
    console.log(`${path}: ${Math.round((await stat(path)).size / 1024)} KB`);
    t.assertClean();
    await t.close();
  }
} finally {
  await H.close();
}
