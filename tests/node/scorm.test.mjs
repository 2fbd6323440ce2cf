// www/lib/scorm.js (the content side of SCORM 1.2) against the test LMS of tests/fixtures/scorm12-lms.js, written
// from the RTE specification: what a launch, a Check, a relaunch and leaving write into the learner's record.
// The package itself (manifest, launch page) is tested here too; the real pages in tests/e2e/scorm.test.mjs.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import '../fixtures/scorm12-lms.js';
import { findAPI, scormSession, timespan, readSuspend, SUSPEND_LIMIT } from '../../www/lib/scorm.js';
import { manifest, launchPage } from '../../www/lib/scorm-package.js';

const { createScorm12LMS } = /** @type {any} */ (globalThis);

test('findAPI: up the parent chain (at most 7 frames), then the opener; frames of another origin are skipped', () => {
  const api = { LMSInitialize() {} };
  const frame = (parent, API) => { const w = { API, parent: null }; w.parent = parent || w; return w; };
  const top = frame(null, api);
  let w = top;
  for (let i = 0; i < 3; i++) w = frame(w);
  assert.equal(findAPI(w), api, '3 levels down');
  let deep = top;
  for (let i = 0; i < 9; i++) deep = frame(deep);
  assert.equal(findAPI(deep), null, '9 levels down is beyond ADL\'s 7');
  const foreign = { get API() { throw new DOMException('cross-origin', 'SecurityError'); }, parent: null };
  foreign.parent = top;
  assert.equal(findAPI(frame(foreign)), api, 'a foreign frame in between is passed');
  const popup = frame(null); popup.opener = frame(null, api);
  assert.equal(findAPI(popup), api, 'from the opener');
  assert.equal(findAPI(frame(null)), null);
});

test('timespan: CMITimespan HHHH:MM:SS.SS', () => {
  assert.equal(timespan(0), '0000:00:00.00');
  assert.equal(timespan(3725.456), '0001:02:05.46');
});

test('a first launch, a failed Check, a passed Check, leaving: the record the LMS keeps', () => {
  const record = {};
  const lms = createScorm12LMS(record);
  const said = [];
  let t = 1000;
  const s = scormSession({ api: lms, passMark: 100, say: (m, k) => said.push([k, m]), now: () => t });
  assert.equal(s.connected, true);
  assert.equal(s.entry, 'ab-initio');
  assert.equal(record.lesson_status, 'incomplete', 'a launch marks it begun');
  s.setView(0, '#interp-approx/v1.aaa');
  assert.equal(s.report(0, { passed: false, score: 0.5 }).status, 'failed');
  assert.deepEqual([record.score_raw, record.score_min, record.score_max, record.lesson_status, record.exit], ['50', '0', '100', 'failed', 'suspend']);
  assert.deepEqual(JSON.parse(record.suspend_data), { v: 1, i: 0, b: [50], a: [1], h: [0], l: ['#interp-approx/v1.aaa'] });
  s.setView(0, '#interp-approx/v1.bbb');
  assert.equal(s.report(0, { passed: true, score: 1 }).status, 'passed');
  assert.deepEqual([record.score_raw, record.lesson_status, record.exit], ['100', 'passed', '']);
  assert.deepEqual(JSON.parse(record.suspend_data).l, ['#interp-approx/v1.bbb']);
  s.report(0, { passed: false, score: 0.25 });
  assert.deepEqual([record.score_raw, record.lesson_status], ['100', 'passed'], 'the best of the attempt stays');
  t += 65500;
  s.setView(0, '#interp-approx/v1.ddd');
  s.finish();
  assert.equal(lms.finished(), true);
  assert.deepEqual(record.session_times, ['0000:01:05.50']);
  assert.deepEqual(JSON.parse(record.suspend_data).l, ['#interp-approx/v1.ddd']);
  assert.deepEqual(said, [], 'nothing to complain about');
  const names = lms.calls.map((c) => c[0]);
  assert.equal(names[0], 'LMSInitialize');
  assert.equal(names.at(-1), 'LMSFinish');
  assert.ok(lms.calls.every((c) => c.at(-1) !== 'false'), 'every call succeeded');
  s.finish(); // a second pagehide (bfcache) calls nothing more
  assert.equal(lms.calls.at(-1)[0], 'LMSFinish');
});

test('a relaunch after leaving unfinished: entry "resume", the saved views and best scores are read back', () => {
  const record = {};
  const a = scormSession({ api: createScorm12LMS(record), passMark: 80 });
  a.setView(0, '#noisy-data/v1.saved');
  a.report(0, { passed: false, score: 0.75 });
  a.setView(0, '#noisy-data/v1.saved2');
  a.finish();
  const b = scormSession({ api: createScorm12LMS(record), passMark: 80 });
  assert.equal(b.entry, 'resume');
  assert.deepEqual(b.resumed, { i: 0, b: [75], a: [1], h: [0], l: ['#noisy-data/v1.saved2'] });
  assert.equal(record.lesson_status, 'failed', 'a relaunch leaves the status as it was');
  b.report(0, { passed: false, score: 0.5 });
  assert.deepEqual([record.lesson_status, record.score_raw], ['failed', '75'], '75 (kept from the first launch) < the pass mark 80');
  b.report(0, { passed: true, score: 0.8 });
  assert.equal(record.lesson_status, 'passed', '80 reaches it');
});

test('a set of three: the score is the mean of the best scores, an unchecked exercise counting 0', () => {
  const record = {};
  const s = scormSession({ api: createScorm12LMS(record), count: 3, passMark: 60 });
  s.report(0, { score: 1 });
  assert.deepEqual([record.score_raw, record.lesson_status], ['33', 'failed'], '(100 + 0 + 0) / 3');
  s.report(1, { score: 0.5 });
  s.report(1, { score: 0.25 });
  assert.deepEqual([record.score_raw, record.lesson_status], ['50', 'failed'], '(100 + 50 + 0) / 3');
  s.setView(2, '#knot-modification/v1.k');
  s.report(2, { score: 0.75 });
  assert.deepEqual([record.score_raw, record.lesson_status], ['75', 'passed'], '(100 + 50 + 75) / 3 = 75 ≥ 60');
  assert.deepEqual(JSON.parse(record.suspend_data), { v: 1, i: 2, b: [100, 50, 75], a: [1, 2, 1], h: [0, 0, 0], l: ['', '', '#knot-modification/v1.k'] });
  assert.equal(readSuspend(record.suspend_data, 2), null, 'a record for another count is not read');
  assert.equal(readSuspend('#old-format', 3), null);
});

test('the teacher\'s rules: Checks allowed per exercise, and the points a shown hint costs', () => {
  const record = {};
  const s = scormSession({ api: createScorm12LMS(record), count: 2, passMark: 60, attempts: 2, hintCost: 30 });
  assert.equal(s.left(0), 2);
  assert.equal(s.report(0, { score: 0.5, hinted: true }).best, 50, 'the Check that shows the hint is not capped');
  const r = s.report(0, { score: 1, hinted: false });
  assert.deepEqual([r.best, r.left, r.raw], [70, 0, 35], 'after the hint: at most 100 − 30; (70 + 0) / 2');
  assert.equal(s.report(0, { score: 1 }), null, 'no Check left: not recorded');
  assert.equal(record.score_raw, '35');
  assert.equal(s.report(1, { score: 1, hinted: false }).best, 100, 'the other exercise has its own Checks and no hint shown');
  assert.deepEqual([record.score_raw, record.lesson_status], ['85', 'passed']);
  s.finish();
  const again = scormSession({ api: createScorm12LMS(record), count: 2, passMark: 60, attempts: 2, hintCost: 30 });
  assert.deepEqual([again.left(0), again.left(1)], [0, 1], 'the Checks used come back on a relaunch');
  assert.deepEqual(again.resumed.h, [1, 0]);
});

test('views too long for cmi.suspend_data: the one shown is kept, then none; said once; the scores always', () => {
  const record = {};
  const said = [];
  const s = scormSession({ api: createScorm12LMS(record), count: 2, say: (m, k) => said.push([k, m]) });
  const long = (n) => `#curve-networks/v1.${'x'.repeat(n)}`;
  s.setView(0, long(3000));
  s.setView(1, long(2000));
  assert.deepEqual(JSON.parse(record.suspend_data).l, ['', long(2000)], 'the view shown (exercise 2) is kept');
  s.setView(1, long(SUSPEND_LIMIT));
  s.report(1, { score: 1 });
  assert.deepEqual(JSON.parse(record.suspend_data), { v: 1, i: 1, b: [-1, 100], a: [0, 1], h: [0, 0], l: [] });
  assert.equal(record.score_raw, '50');
  assert.equal(said.length, 1);
  assert.match(said[0][1], /too long for the 4096 characters/);
});

test('an LMS that refuses: its error code and text are shown, nothing is thrown', () => {
  const record = {};
  const lms = createScorm12LMS(record);
  lms.LMSInitialize(''); // already initialised by someone else: the SCO's LMSInitialize fails with 101
  const said = [];
  const s = scormSession({ api: lms, say: (m, k) => said.push([k, m]) });
  assert.equal(s.connected, false);
  assert.equal(said[0][0], 'error');
  assert.match(said[0][1], /LMSInitialize: error 101 — General exception/);
  assert.equal(s.report(0, { passed: true, score: 1 }), null);
  const throwing = { LMSInitialize() { throw new Error('boom'); }, LMSGetLastError() { return '101'; }, LMSGetErrorString() { return 'General exception'; } };
  const said2 = [];
  assert.doesNotThrow(() => scormSession({ api: throwing, say: (m, k) => said2.push([k, m]) }));
  assert.match(said2[0][1], /boom/);
});

test('no LMS: the page says the result is not recorded', () => {
  const said = [];
  const s = scormSession({ api: null, say: (m, k) => said.push([k, m]) });
  assert.equal(s.connected, false);
  assert.match(said[0][1], /not recorded/);
  assert.equal(s.report(0, { passed: true, score: 1 }), null);
});

test('the manifest: SCORM 1.2 metadata, one SCO, the pass mark as masteryscore, names escaped', () => {
  const m = manifest({ id: 'b2-through-data', title: 'Through <the> "data" & more', passMark: 80 });
  assert.match(m, /<schema>ADL SCORM<\/schema>\s*<schemaversion>1\.2<\/schemaversion>/);
  assert.match(m, /adlcp:scormtype="sco" href="index\.html"/);
  assert.match(m, /<adlcp:masteryscore>80<\/adlcp:masteryscore>/);
  assert.match(m, /Through &lt;the&gt; &quot;data&quot; &amp; more/);
  assert.equal((m.match(/<item /g) || []).length, 1);
});

test('the launch page: the config right after <head>, and a "</script>" in a task cannot end it', () => {
  const cfg = { title: 'x</script><script>alert(1)</script>', passMark: 100, items: [{ id: 'a', title: 'A', hash: '#a/v1.x' }] };
  const page = launchPage('<!doctype html><html><head><meta charset="utf-8"></head><body></body></html>', cfg);
  const m = page.match(/<head><\n?<script id="splinelab-scorm" type="application\/json">(.*?)<\/script>/s) || page.match(/<head>\n<script id="splinelab-scorm" type="application\/json">(.*?)<\/script>/s);
  assert.ok(m, page);
  assert.deepEqual(JSON.parse(m[1]), { v: 1, ...cfg });
  assert.equal((page.match(/<\/script>/g) || []).length, 1);
});
