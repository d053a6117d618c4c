// Serves the live gallery (index.html beside this file) on 127.0.0.1: compiles every
// example graph (graphs/*.json) for es300 with its textures, once per preset of the graph,
// writes the built-in scene's description (`watergraph scene`) and the list of graphs,
// then serves them with this client and its node_modules/three.
//
//   node clients/three/example/serve.mjs [--watergraph PATH] [--port 8080]
//
// --watergraph: the watergraph binary (default: build/bin/watergraph in this repository,
// else `watergraph` on PATH).
//
// Nothing is fetched from elsewhere; the compiled files go to a temporary folder removed
// on exit. Exit status 2 for usage or a failed compile (its message on stderr).
import { createServer } from 'node:http';
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, readdirSync, rmSync, writeFileSync, mkdirSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { parseArgs } from 'node:util';

import { serveStaticFile } from '../static_files.mjs';

const clientDir = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const repoDir = path.resolve(clientDir, '..', '..');


// Compiles the gallery's files into `outDir`: scene.json, gallery.json (graphs with their
// descriptions, presets and whether they have a surface query) and <graph>/<preset or
// "default">/ with the compiled graph (and its <graph>.query.js).
export function prepareGallery({ watergraph, graphsDir = path.join(repoDir, 'graphs'), outDir }) {
  const run = (args) => execFileSync(watergraph, args, { stdio: ['ignore', 'ignore', 'pipe'] });
  run(['scene', '-o', path.join(outDir, 'scene.json')]);
  const graphs = [];
  for (const file of readdirSync(graphsDir).filter((f) => f.endsWith('.json')).sort()) {
    const name = file.replace(/\.json$/, '');
    const graph = JSON.parse(readFileSync(path.join(graphsDir, file), 'utf8'));
    const presets = Object.keys(graph.presets ?? {});
    // With the surface query the buoys float by (docs/queries.md); a graph whose
    // displacement has no query form floats none.
    let query = true;
    for (const preset of ['default', ...presets]) {
      const dir = path.join(outDir, name, preset);
      mkdirSync(dir, { recursive: true });
      const flags = preset === 'default' ? [] : ['--preset', preset];
      run(['compile', path.join(graphsDir, file), '-o', dir, '--target', 'es300', '--textures', '--quiet', ...flags]);
      if (!query) continue;
      try {
        run(['compile', path.join(graphsDir, file), '-o', dir, '--target', 'query-js', '--quiet', ...flags]);
      } catch {
        query = false;
      }
    }
    graphs.push({ name, description: graph.description ?? '', presets, query });
  }
  writeFileSync(path.join(outDir, 'gallery.json'), JSON.stringify({ graphs }, null, 1));
  return graphs;
}

// An HTTP server for /client/ (this client) and /out/ (the prepared files); / goes to the page.
export function galleryServer(outDir) {
  const roots = { '/client/': clientDir, '/out/': outDir };
  return createServer((req, res) => {
    const url = new URL(req.url, 'http://127.0.0.1');
    if (url.pathname === '/') {
      res.writeHead(302, { location: '/client/example/index.html' }).end();
      return;
    }
    serveStaticFile(roots, req, res);
  });
}

if (process.argv[1] && path.resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  let args;
  try {
    ({ values: args } = parseArgs({ options: { watergraph: { type: 'string' }, port: { type: 'string' } } }));
  } catch (e) {
    process.stderr.write(`serve: ${e.message}\n`);
    process.exit(2);
  }
  const built = path.join(repoDir, 'build', 'bin', 'watergraph');
  const watergraph = args.watergraph ?? (existsSync(built) ? built : 'watergraph');
  const port = Number(args.port ?? 8080);
  const outDir = mkdtempSync(path.join(tmpdir(), 'wg_gallery_'));
  const cleanUp = () => rmSync(outDir, { recursive: true, force: true });
  try {
    const graphs = prepareGallery({ watergraph, outDir });
    process.stdout.write(`serve: compiled ${graphs.length} graphs and their presets\n`);
  } catch (e) {
    cleanUp();
    process.stderr.write(`serve: cannot prepare the gallery with ${watergraph}: ${e.stderr?.toString() || e.message}\n` +
      '(build watergraph first, or name it with --watergraph)\n');
    process.exit(2);
  }
  const server = galleryServer(outDir);
  server.on('error', (e) => {
    cleanUp();
    process.stderr.write(`serve: cannot listen on 127.0.0.1:${port}: ${e.message}\n`);
    process.exit(2);
  });
  server.listen(port, '127.0.0.1', () => process.stdout.write(`serve: open http://127.0.0.1:${port}/ (Ctrl-C stops)\n`));
  for (const signal of ['SIGINT', 'SIGTERM']) process.on(signal, () => { cleanUp(); process.exit(0); });
}
