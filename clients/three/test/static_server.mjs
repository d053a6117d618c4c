// The test pages' static file server (render_graph.mjs here, clients/webgpu's
// render_webgpu.mjs): files under `roots` (URL prefix -> folder), a 404 for anything else
// or outside them, never cached. Listens on a free port of 127.0.0.1.
import { readFile } from 'node:fs/promises';
import { createServer } from 'node:http';
import path from 'node:path';

const TYPES = { '.html': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript', '.json': 'application/json',
  '.png': 'image/png', '.wasm': 'application/wasm' };

// Returns {server, origin} once listening.
export async function startStaticServer(roots) {
  const server = createServer(async (req, res) => {
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
  });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  return { server, origin: `http://127.0.0.1:${server.address().port}` };
}
