// The test pages' static file server (render_graph.mjs here, clients/webgpu's
// render_webgpu.mjs): files under `roots` (URL prefix -> folder), a 404 for anything else
// or outside them, never cached. Listens on a free port of 127.0.0.1.
import { createServer } from 'node:http';

import { serveStaticFile } from '../static_files.mjs';

// Returns {server, origin} once listening.
export async function startStaticServer(roots) {
  const server = createServer((req, res) => serveStaticFile(roots, req, res));
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  return { server, origin: `http://127.0.0.1:${server.address().port}` };
}
