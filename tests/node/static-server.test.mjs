// scripts/static-server.mjs stays in its folder (issue 30, item 1): requests that decode to a path outside the
// served folder — a sibling folder whose name starts with the root's (`www` next to `www-secret`), encoded,
// doubly encoded and mixed escapes — never return a file of it; files inside, even with dots in their names, are
// served. Runs on loopback, a temporary folder, a bounded list of requests.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtemp, mkdir, writeFile, rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { request } from 'node:http';
import { serve, insideRoot } from '../../scripts/static-server.mjs';

const SECRET = 'the-key-of-the-sibling-folder';
let dir, server, port;
before(async () => {
  dir = await mkdtemp(join(tmpdir(), 'splinelab-static-'));
  await mkdir(join(dir, 'www', 'sub'), { recursive: true });
  await mkdir(join(dir, 'www-secret'), { recursive: true });
  await writeFile(join(dir, 'www', 'index.html'), '<p>home</p>');
  await writeFile(join(dir, 'www', 'sub', 'a.txt'), 'inside');
  await writeFile(join(dir, 'www', '..dots.txt'), 'dots inside');
  await writeFile(join(dir, 'www-secret', 'key.txt'), SECRET);
  await writeFile(join(dir, 'outside.txt'), SECRET);
  server = await serve(join(dir, 'www'), 0, '127.0.0.1');
  port = server.address().port;
});
after(async () => { server?.closeAllConnections?.(); await new Promise((ok) => server.close(ok)); await rm(dir, { recursive: true, force: true }); });

/** A raw GET (the path is sent as written: no client-side normalisation). */
function get(path) {
  return new Promise((ok, fail) => {
    const req = request({ host: '127.0.0.1', port, path, method: 'GET' }, (res) => {
      let body = '';
      res.on('data', (c) => { body += c; });
      res.on('end', () => ok({ status: res.statusCode, body }));
    });
    req.on('error', fail);
    req.end();
  });
}

test('escapes to a sibling or parent folder get no file', async () => {
  const escapes = [
    '/..%2fwww-secret/key.txt', '/..%2Fwww-secret%2Fkey.txt', '/%2e%2e%2fwww-secret%2fkey.txt', '/%2E%2E/www-secret/key.txt',
    '/sub/..%2f..%2fwww-secret/key.txt', '/..%2f..%2f' + 'outside.txt', '/%2e%2e%2foutside.txt', '/..%5cwww-secret%5ckey.txt',
    '/%252e%252e%252fwww-secret%252fkey.txt', '/..%2f%2e%2e%2fwww-secret/key.txt', '/sub/%2e%2e/%2e%2e/outside.txt',
    '/../www-secret/key.txt', '/sub/../../outside.txt',
  ];
  for (const p of escapes) {
    const r = await get(p);
    assert.ok(r.status === 403 || r.status === 404, `${p}: status ${r.status}`);
    assert.ok(!r.body.includes(SECRET), `${p}: served the file outside the folder`);
  }
});

test('files inside the folder are served, dotted names too', async () => {
  assert.deepEqual(await get('/sub/a.txt'), { status: 200, body: 'inside' });
  assert.deepEqual(await get('/..dots.txt'), { status: 200, body: 'dots inside' });
  assert.deepEqual(await get('/sub/%2e%2e/sub/a.txt'), { status: 200, body: 'inside' });
  assert.equal((await get('/')).body, '<p>home</p>');
});

test('insideRoot: by path, not by string prefix', () => {
  assert.equal(insideRoot('/srv/www', '/srv/www'), true);
  assert.equal(insideRoot('/srv/www', '/srv/www/a/b.js'), true);
  assert.equal(insideRoot('/srv/www', '/srv/www/..dots'), true);
  assert.equal(insideRoot('/srv/www', '/srv/www-secret/key.txt'), false);
  assert.equal(insideRoot('/srv/www', '/srv'), false);
  assert.equal(insideRoot('/srv/www', '/etc/passwd'), false);
});
