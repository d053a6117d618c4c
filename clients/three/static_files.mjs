// Static files for the client's pages (the gallery's example/serve.mjs, the test pages'
// test/static_server.mjs): a request for a path under one of `roots` (URL prefix -> folder)
// is answered with that file, never cached; anything else, or a path that leaves its
// folder, is a 404.
import { readFile } from 'node:fs/promises';
import path from 'node:path';

const TYPES = { '.html': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript', '.json': 'application/json',
  '.png': 'image/png', '.css': 'text/css', '.wasm': 'application/wasm' };

export async function serveStaticFile(roots, req, res) {
  const url = new URL(req.url, 'http://127.0.0.1');
  const prefix = Object.keys(roots).find((p) => url.pathname.startsWith(p));
  const file = prefix && path.resolve(roots[prefix], '.' + decodeURIComponent(url.pathname.slice(prefix.length - 1)));
  if (!file || !(file + path.sep).startsWith(roots[prefix] + path.sep)) {
    res.writeHead(404).end();
    return;
  }
  try {
    const body = await readFile(file);
    res.writeHead(200, { 'content-type': TYPES[path.extname(file)] ?? 'text/plain', 'cache-control': 'no-store' });
    res.end(body);
  } catch {
    res.writeHead(404).end();
  }
}
