// Writes www/api.html, the JavaScript API reference on the site, from docs/API.md (the one text of the API
// reference; the sandbox's "API" link and the guide point at the page). Markdown by `marked` (a dev dependency:
// the page is static HTML, no script). Usage: node scripts/build-api-page.mjs [--check]
//   --check: exits 1 if www/api.html is not what docs/API.md gives now (tests/e2e/api-page.test.mjs runs it).
//
// What changes on the way from the repository's Markdown to a reader's page:
//   - index notation in prose is typeset: W_{−1} → W<sub>−1</sub>, L^a → L<sup>a</sup>, N_{j,3} → N<sub>j,3</sub>
//     (code spans and blocks stay as written: there `u_p` is the code's own text);
//   - the papers are named as readers know them (our internal "seed NNN" numbers become the authors);
//   - links to files outside the site (the specifications, the test scripts) become plain text, since the
//     site has no such files; links within the page stay.
import { readFile, writeFile } from 'node:fs/promises';
import { join, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';
import { Marked } from 'marked';
import { PAPERS } from '../www/lib/papers-ref.js';

const ROOT = join(dirname(fileURLToPath(import.meta.url)), '..');
const SOURCE = join(ROOT, 'docs/API.md');
const TARGET = join(ROOT, 'www/api.html');

const esc = (s) => String(s).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');

/** "(seed 003)" → "(Nistor, …)": the paper by the names of its authors. */
function namePapers(text) {
  return text.replace(/\(seeds? (\d{3})\)/g, (m, key) => {
    const p = PAPERS.find((q) => q.key === key);
    return p ? `(${p.short})` : m;
  }).replace(/\bseeds? (\d{3})\b/gi, (m, key) => {
    const p = PAPERS.find((q) => q.key === key);
    return p ? p.short : m;
  });
}

/**
 * Index notation of the prose (already HTML-escaped text, outside code) as sub- and superscripts:
 * `X_{…}` / `X^{…}` with braces (nested once), `X_i` / `X^a` for one letter, digit, or a word of them after a
 * letter or a closing bracket.
 */
export function typesetIndices(html) {
  const braced = /([\p{L}\p{N})\]′*>])([_^])\{((?:[^{}]|\{[^{}]*\})*)\}/gu;
  const bare = /([\p{L})\]′⁺⁻>])([_^])([±+−-]?[\p{L}\p{N}][\p{L}\p{N}′]*)/gu;
  let out = html;
  for (let k = 0; k < 3; k++) out = out.replace(braced, (m, base, op, body) => `${base}<${op === '_' ? 'sub' : 'sup'}>${body.replace(/[{}]/g, '')}</${op === '_' ? 'sub' : 'sup'}>`);
  out = out.replace(/([\p{L}\p{N})\]′>])\^(\([^()]{1,12}\))/gu, (m, base, body) => `${base}<sup>${body}</sup>`); // c^(j)
  // twice: the second pass takes a superscript right after a subscript (d_j^r)
  for (let k = 0; k < 2; k++) out = out.replace(bare, (m, base, op, body) => `${base}<${op === '_' ? 'sub' : 'sup'}>${body}</${op === '_' ? 'sub' : 'sup'}>`);
  return out;
}

/** typesetIndices on the Markdown's prose: not in fenced blocks, not in `code spans` (before Markdown reads the
 * text, so the underscores of W_{i−1} … W_{i+1} are never taken for emphasis). */
function typesetProse(md) {
  let fenced = false;
  return md.split('\n').map((line) => {
    if (/^\s*```/.test(line)) { fenced = !fenced; return line; }
    if (fenced) return line;
    return line.split(/(`[^`]*`)/).map((part, i) => (i % 2 ? part : typesetIndices(part))).join('');
  }).join('\n');
}

const slug = (text) => text.toLowerCase().replace(/<[^>]+>/g, '').replace(/[`*]/g, '').replace(/[^\p{L}\p{N}\s-]/gu, '').trim().replace(/\s+/g, '-');

export async function buildApiPage() {
  const md = typesetProse(await readFile(SOURCE, 'utf8'));
  const marked = new Marked({ gfm: true });
  const exportsSeen = [];
  marked.use({
    renderer: {
      heading({ tokens, depth, text }) {
        const inner = this.parser.parseInline(tokens);
        // `### \`name\`` sections get the export's name as their id (sandbox links: api.html#b2Curve)
        const m = /^`([A-Za-z0-9]+)`$/.exec(text.trim());
        const id = m ? m[1] : slug(namePapers(text));
        if (m) exportsSeen.push(m[1]);
        return `<h${depth} id="${esc(id)}">${inner}</h${depth}>\n`;
      },
      text(token) {
        if (token.tokens) return this.parser.parseInline(token.tokens);
        return namePapers(token.escaped ? token.text : esc(token.text));
      },
      link({ href, tokens }) {
        const inner = this.parser.parseInline(tokens);
        if (href.startsWith('#')) return `<a href="${esc(slugHref(href))}">${inner}</a>`;
        if (/^https?:/.test(href)) return `<a href="${esc(href)}">${inner}</a>`;
        return inner; // a file of the repository, not of the site
      },
      code({ text, lang }) {
        const kind = (lang || '').split(/\s+/)[0];
        return `<pre class="api-code" tabindex="0"><code${kind ? ` class="language-${esc(kind)}"` : ''}>${esc(text)}</code></pre>\n`;
      },
    },
  });
  // in-page links written against GitHub's heading ids: the contents list uses them; map them to ours
  const slugHref = (href) => `#${slug(namePapers(decodeURIComponent(href.slice(1)).replace(/-/g, ' '))).replace(/-+/g, '-')}`;
  const body = marked.parse(md);
  const page = `<!doctype html>
<html lang="en">
<head>
  <meta charset="utf-8">
  <meta http-equiv="Content-Security-Policy" content="default-src 'self'; script-src 'self'; style-src 'self'; img-src 'self' data:; object-src 'none'; base-uri 'none'">
  <meta name="viewport" content="width=device-width, initial-scale=1">
  <meta name="description" content="The SplineLab JavaScript API: every function of the WebAssembly module, its options, results and errors.">
  <title>SplineLab JavaScript API</title>
  <link rel="icon" href="data:,">
  <link rel="stylesheet" href="style.css">
</head>
<body data-mode="api" class="api-page">
  <header class="site-header">
    <a class="brand" href="index.html" translate="no">Spline<span>Lab</span></a>
    <span class="tagline">JavaScript API reference</span>
    <a class="sb-back" href="sandbox.html">Sandbox</a>
  </header>
  <main id="main" class="main">
    <article class="demo-explain api-doc">
<!-- generated by scripts/build-api-page.mjs from docs/API.md: edit that file, then run the script -->
${body}    </article>
  </main>
</body>
</html>
`;
  return { page, exports: exportsSeen };
}

if (import.meta.url === `file://${process.argv[1]}`) {
  const { page, exports } = await buildApiPage();
  if (process.argv.includes('--check')) {
    const now = await readFile(TARGET, 'utf8').catch(() => '');
    if (now !== page) { console.error('www/api.html is out of date: run node scripts/build-api-page.mjs'); process.exit(1); }
    console.log(`www/api.html is up to date (${exports.length} functions)`);
  } else {
    await writeFile(TARGET, page);
    console.log(`wrote www/api.html (${exports.length} functions, ${page.length} bytes)`);
  }
}
