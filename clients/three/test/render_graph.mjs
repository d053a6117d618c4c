// Renders one compiled graph with the three.js client in headless Chromium and writes a
// screenshot of the canvas. Serves this client folder (module, page, node_modules/three)
// and the compiled graph's folder from a throw-away HTTP server on 127.0.0.1 (a free port);
// nothing is fetched from elsewhere. Used by tests/ecosystem/three_client_test.cpp.
//
//   node render_graph.mjs --dir OUT --manifest lake.manifest.json --size 320x180 \
//     --eye=14,7,-12 --target=-4,-1.5,4 --up=0,1,0 --fov 55 --near 0.1 --far 200 \
//     --time 3.5 --grid 128 --screenshot three.png [--chromium /usr/bin/chromium]
//
// Exit status: 0 written; 1 the page failed (message on stderr); 2 usage or environment
// (no Chromium, no playwright-core).
import { createServer } from 'node:http';
import { readFile, access } from 'node:fs/promises';
import { constants } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { parseArgs } from 'node:util';

const clientDir = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');

function fail(code, message) {
  process.stderr.write(`render_graph: ${message}\n`);
  process.exit(code);
}

let args;
try {
  ({ values: args } = parseArgs({
    options: Object.fromEntries(
      ['dir', 'manifest', 'size', 'eye', 'target', 'up', 'fov', 'near', 'far', 'time', 'grid', 'screenshot', 'chromium']
        .map((k) => [k, { type: 'string' }])),
  }));
} catch (e) {
  fail(2, e.message);
}
for (const k of ['dir', 'manifest', 'size', 'eye', 'target', 'up', 'fov', 'near', 'far', 'time', 'grid', 'screenshot'])
  if (args[k] === undefined) fail(2, `missing --${k}`);
const size = /^(\d+)x(\d+)$/.exec(args.size);
if (!size) fail(2, `--size must be WIDTHxHEIGHT (got '${args.size}')`);
const [width, height] = [Number(size[1]), Number(size[2])];
const chromiumPath = args.chromium ?? '/usr/bin/chromium';
try {
  await access(chromiumPath, constants.X_OK);
} catch {
  fail(2, `no Chromium at ${chromiumPath} (Debian: apt-get install chromium; scripts/setup.sh installs it)`);
}
let chromium;
try {
  ({ chromium } = await import('playwright-core'));
} catch (e) {
  fail(2, `cannot load playwright-core (run \`npm ci\` in ${clientDir}): ${e.message}`);
}

const TYPES = { '.html': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript', '.json': 'application/json',
  '.png': 'image/png' };
const roots = { '/client/': clientDir, '/out/': path.resolve(args.dir) };

// Static files under the two roots; anything else (or outside them) is a 404.
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
const origin = `http://127.0.0.1:${server.address().port}`;

const query = new URLSearchParams({
  manifest: `/out/${args.manifest}`, width, height, eye: args.eye, target: args.target, up: args.up,
  fov: args.fov, near: args.near, far: args.far, time: args.time, grid: args.grid,
});
// WebGL 2 without a GPU: ANGLE on SwiftShader (Chromium ships it).
const browser = await chromium.launch({
  executablePath: chromiumPath,
  args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist'],
  timeout: 30000,
}).catch((e) => fail(2, `cannot start Chromium at ${chromiumPath}: ${e.message}`));
let code = 0;
try {
  const page = await browser.newPage({ viewport: { width, height }, deviceScaleFactor: 1 });
  const problems = [];
  page.on('console', (m) => { if (m.type() === 'error') problems.push(m.text()); });
  page.on('pageerror', (e) => problems.push(e.message));
  page.on('requestfailed', (r) => problems.push(`request failed: ${r.url()}`));
  await page.goto(`${origin}/client/test/render.html?${query}`);
  await page.waitForFunction(() => window.wgResult !== undefined, null, { timeout: 30000 });
  const result = await page.evaluate(() => window.wgResult);
  if (!result.ok) problems.unshift(result.error);
  if (problems.length) {
    process.stderr.write(`render_graph: the page failed:\n  ${problems.join('\n  ')}\n`);
    code = 1;
  } else {
    await page.locator('canvas').screenshot({ path: args.screenshot });
    process.stdout.write(`render_graph: ${args.manifest} ${width}x${height} on ${result.renderer} -> ${args.screenshot}\n`);
  }
} catch (e) {
  process.stderr.write(`render_graph: ${e.message}\n`);
  code = 1;
} finally {
  await browser.close();
  server.close();
}
process.exit(code);
