// "Download for LMS (SCORM)" (issue 27): a SCORM 1.2 package of one exercise, made in the browser.
//
// The zip (./zip.js) holds
//   imsmanifest.xml  SCORM 1.2 (IMS Content Packaging 1.1.2 + ADL SCORM 1.2 metadata): one organization, one item
//                    with its adlcp:masteryscore (the pass mark), one resource, adlcp:scormtype="sco"
//   index.html       the launch page: the one-file build of SplineLab (splinelab.html, every demo, script, style
//                    and the wasm inlined: the LMS serves the package from its own domain, sometimes with the wrong
//                    type for .wasm, so nothing is fetched from anywhere) with the exercise's config in its head
//                    (./scorm-launch.js reads it)
// The one-file build is fetched from beside the page (the published site carries it; a source checkout has it
// after scripts/build-offline.sh and scripts/build-site.mjs).
// relayPackage(): the same manifest with a small launch page that shows the exercises from this site instead
// (./scorm-relay.js; for a site the students can reach).

import { zip } from './zip.js';
import { relayPage } from './scorm-relay.js';

/** Text for XML content and attribute values. */
const xml = (s) => String(s).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');

/** The imsmanifest.xml of a one-SCO package. */
export function manifest({ id, title, passMark }) {
  const t = xml(title);
  return `<?xml version="1.0" encoding="UTF-8"?>
<manifest identifier="splinelab-${xml(id)}" version="1.0"
  xmlns="http://www.imsproject.org/xsd/imscp_rootv1p1p2"
  xmlns:adlcp="http://www.adlnet.org/xsd/adlcp_rootv1p2"
  xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
  xsi:schemaLocation="http://www.imsproject.org/xsd/imscp_rootv1p1p2 imscp_rootv1p1p2.xsd http://www.imsglobal.org/xsd/imsmd_rootv1p2p1 imsmd_rootv1p2p1.xsd http://www.adlnet.org/xsd/adlcp_rootv1p2 adlcp_rootv1p2.xsd">
  <metadata>
    <schema>ADL SCORM</schema>
    <schemaversion>1.2</schemaversion>
  </metadata>
  <organizations default="splinelab-org">
    <organization identifier="splinelab-org">
      <title>${t}</title>
      <item identifier="item-${xml(id)}" identifierref="sco-${xml(id)}" isvisible="true">
        <title>${t}</title>
        <adlcp:masteryscore>${passMark}</adlcp:masteryscore>
      </item>
    </organization>
  </organizations>
  <resources>
    <resource identifier="sco-${xml(id)}" type="webcontent" adlcp:scormtype="sco" href="index.html">
      <file href="index.html"/>
    </resource>
  </resources>
</manifest>
`;
}

/** Throws an Error naming what is wrong with a package's settings. */
function check({ id, passMark, attempts, hintCost, items }) {
  const ID = /^[a-z0-9][a-z0-9-]{0,63}$/;
  if (!ID.test(id)) throw new Error(`the package id "${id}" may only hold a–z, 0–9 and -`);
  if (!Array.isArray(items) || items.length < 1 || items.length > 50) throw new Error('a package holds 1 to 50 exercises');
  for (const x of items) {
    if (!ID.test(x.id)) throw new Error(`the exercise id "${x.id}" may only hold a–z, 0–9 and -`);
    if (!/^#[a-z0-9-]+\//.test(x.hash)) throw new Error(`"${x.title || x.id}" is not an exercise link (#<demo>/<state>)`);
  }
  if (new Set(items.map((x) => x.id)).size !== items.length) throw new Error('two exercises of the set have the same id: each is scored on its own, so each must be there once');
  if (!(Number.isInteger(passMark) && passMark >= 0 && passMark <= 100)) throw new Error('the pass mark is not a whole number from 0 to 100');
  if (!(Number.isInteger(attempts) && attempts >= 0 && attempts <= 1000)) throw new Error('the Checks allowed are not a whole number from 0 (no limit) to 1000');
  if (!(Number.isInteger(hintCost) && hintCost >= 0 && hintCost <= 100)) throw new Error('the points a hint costs are not a whole number from 0 to 100');
}

/** The launch page: `oneFile` (the text of splinelab.html) with the config script right after <head>. */
export function launchPage(oneFile, config) {
  // JSON inside <script>: "<" is escaped so no "</script>" in a task or title can end the element
  const json = JSON.stringify({ v: 1, ...config }).replace(/</g, '\\u003c');
  const tag = `<script id="splinelab-scorm" type="application/json">${json}</script>`;
  const at = oneFile.search(/<head[^>]*>/i);
  if (at < 0) throw new Error('the one-file build has no <head>');
  const end = oneFile.indexOf('>', at) + 1;
  return `${oneFile.slice(0, end)}\n${tag}${oneFile.slice(end)}`;
}

/**
 * The package of one exercise or of a set: `{ id, title, passMark, items: [{ id, title, hash }] }` (hash: an
 * exercise link's '#<demo>/<state>'; a set is one SCO whose score is the mean of its exercises' best scores, see
 * ./scorm.js). `oneFile`: the text of splinelab.html (fetched from beside the page when not given). Resolves to
 * a Blob.
 * `attempts`: Checks per exercise (0: no limit); `hintCost`: points a shown hint costs (see ./scorm.js).
 * @param {{ id: string, title: string, passMark?: number, attempts?: number, hintCost?: number, items: { id: string, title: string, hash: string }[] }} pkg
 * @param {{ oneFile?: string, base?: URL }} [opts]
 */
export async function scormPackage({ id, title, passMark = 100, attempts = 0, hintCost = 0, items }, { oneFile = undefined, base = new URL('./', location.href) } = {}) {
  check({ id, passMark, attempts, hintCost, items });
  const page = oneFile ?? await textBeside(base, 'splinelab.html', 'the one-file build (splinelab.html) is not beside this page: it is part of the published site; in a source checkout, build it with scripts/build-offline.sh, then node scripts/build-site.mjs, and use dist/site');
  return packageBlob({ id, title, passMark }, launchPage(page, { title, passMark, attempts, hintCost, items: items.map(({ id: i, title: t, hash }) => ({ id: i, title: t, hash })) }));
}

/** The text of the file `name` of the site's folder `base`; an Error saying `missing` when it is not there. */
async function textBeside(base, name, missing) {
  let r = null;
  try { r = await fetch(new URL(name, base)); } catch { r = null; }
  if (!r || !r.ok) throw new Error(missing);
  return r.text();
}

/** The zip of a one-SCO package: its manifest and its launch page. */
async function packageBlob({ id, title, passMark }, page) {
  const bytes = await zip([
    { name: 'imsmanifest.xml', data: manifest({ id, title, passMark }) },
    { name: 'index.html', data: page },
  ]);
  return new Blob([/** @type {Uint8Array<ArrayBuffer>} */ (bytes)], { type: 'application/zip' });
}

/**
 * The relay package of the same exercises (./scorm-relay.js): a few KB; its page shows each exercise from this
 * site (`base`: the site's folder, which must stay online for the students) and relays the results.
 * @param {{ id: string, title: string, passMark?: number, attempts?: number, hintCost?: number, items: { id: string, title: string, hash: string }[] }} pkg
 * @param {{ base?: URL, scormSource?: string }} [opts]
 */
export async function relayPackage({ id, title, passMark = 100, attempts = 0, hintCost = 0, items }, { base = new URL('./', location.href), scormSource = undefined } = {}) {
  check({ id, passMark, attempts, hintCost, items });
  const src = scormSource ?? await textBeside(base, 'lib/scorm.js', 'lib/scorm.js is not beside this page (the site\'s build copies it: node scripts/build-site.mjs)');
  const host = new URL(base).origin;
  const page = relayPage({ title, passMark, attempts, hintCost, host, items: items.map((x) => ({ id: x.id, title: x.title, url: new URL(`embed.html${x.hash}`, base).href })) }, src);
  return packageBlob({ id, title, passMark }, page);
}

/** Saves `blob` as `name` (a download link clicked once). */
export function download(blob, name) {
  const url = URL.createObjectURL(blob);
  const a = document.createElement('a');
  a.href = url; a.download = name; a.hidden = true;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 60000);
}
