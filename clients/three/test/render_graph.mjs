// Renders compiled graphs with the three.js client in headless Chromium and writes a
// screenshot of the canvas for each. Serves this client folder (modules, page,
// node_modules/three), each compiled graph's folder and the scene description from a
// throw-away HTTP server on 127.0.0.1 (a free port); nothing is fetched from elsewhere.
// One browser renders every job. Used by tests/ecosystem/three_client_test.cpp.
//
//   node render_graph.mjs --dir OUT --manifest lake.manifest.json --size 320x180 \
//     --eye=14,7,-12 --target=-4,-1.5,4 --up=0,1,0 --fov 55 --near 0.1 --far 200 \
//     --time 3.5 --grid 128 --screenshot three.png [--description scene.json [--builtin]] \
//     [--box x,y,z,size] [--tonemap NAME] [--exposure EV] [--nofloat] [--host-tone-mapping]
//     [--chromium /usr/bin/chromium]
//   node render_graph.mjs --batch jobs.json [--description scene.json] [--chromium ...]
//
// --description: a `watergraph scene` file; the client then runs every pass the manifest
// lists, and --builtin draws the built-in scene around the water. --box adds a user's own
// object to the scene: a red cube (unlit) of that centre and edge length. --tonemap and
// --exposure: the client's render options (default: the manifest's view). --nofloat: the
// page hides the extensions that make half floats renderable (the client's RGBA8 fallback).
// --host-tone-mapping: the page sets three.js's own tone mapping (ACES) and sRGB output on
// the renderer, as a host might; the client's output transform must set them aside.
// Each written screenshot is reported on stdout with the frame's format and the warnings
// the page gave. --batch: a JSON array of
// jobs, each an object with the single-job options as keys ("dir", "manifest", ...,
// "builtin": true). Exit status: 0 all written; 1 a page failed (message on stderr; the
// other jobs still run); 2 usage or environment (no Chromium, no playwright-core).
import { readFile, access } from 'node:fs/promises';
import { startStaticServer } from './static_server.mjs';
import { constants } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { parseArgs } from 'node:util';

const clientDir = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');

function fail(code, message) {
  process.stderr.write(`render_graph: ${message}\n`);
  process.exit(code);
}

const JOB_KEYS = ['dir', 'manifest', 'size', 'eye', 'target', 'up', 'fov', 'near', 'far', 'time', 'grid', 'screenshot'];
let args;
try {
  ({ values: args } = parseArgs({
    options: {
      ...Object.fromEntries([...JOB_KEYS, 'chromium', 'batch', 'description', 'box', 'tonemap', 'exposure']
        .map((k) => [k, { type: 'string' }])),
      builtin: { type: 'boolean' },
      nofloat: { type: 'boolean' },
      'host-tone-mapping': { type: 'boolean' },
    },
  }));
} catch (e) {
  fail(2, e.message);
}
let jobs;
if (args.batch) {
  try {
    jobs = JSON.parse(await readFile(args.batch, 'utf8'));
  } catch (e) {
    fail(2, `cannot read --batch ${args.batch}: ${e.message}`);
  }
  if (!Array.isArray(jobs) || jobs.length === 0) fail(2, `--batch ${args.batch} must hold a non-empty JSON array of jobs`);
} else {
  jobs = [{ ...args }];
}
jobs.forEach((job, i) => {
  for (const k of JOB_KEYS) if (job[k] === undefined) fail(2, `missing --${k}${args.batch ? ` in job ${i}` : ''}`);
  const size = /^(\d+)x(\d+)$/.exec(job.size);
  if (!size) fail(2, `--size must be WIDTHxHEIGHT (got '${job.size}')`);
  [job.width, job.height] = [Number(size[1]), Number(size[2])];
  if (job.builtin && !args.description) fail(2, '--builtin needs --description (a `watergraph scene` file)');
});
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


// /client/: this folder; /out<i>/: job i's compiled graph; /scene/: the description's folder.
const roots = { '/client/': clientDir };
jobs.forEach((job, i) => { roots[`/out${i}/`] = path.resolve(job.dir); });
if (args.description) roots['/scene/'] = path.dirname(path.resolve(args.description));

// Static files under the roots; anything else (or outside them) is a 404.
const { server, origin } = await startStaticServer(roots);

// WebGL 2 without a GPU: ANGLE on SwiftShader (Chromium ships it).
const browser = await chromium.launch({
  executablePath: chromiumPath,
  args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist'],
  timeout: 30000,
}).catch((e) => fail(2, `cannot start Chromium at ${chromiumPath}: ${e.message}`));
let code = 0;
try {
  for (const [i, job] of jobs.entries()) {
    const query = new URLSearchParams({
      manifest: `/out${i}/${job.manifest}`, width: job.width, height: job.height, eye: job.eye, target: job.target,
      up: job.up, fov: job.fov, near: job.near, far: job.far, time: job.time, grid: job.grid,
    });
    if (args.description) query.set('description', `/scene/${path.basename(args.description)}`);
    if (job.builtin) query.set('builtin', '1');
    if (job.box) query.set('box', job.box);
    if (job.tonemap !== undefined) query.set('tonemap', job.tonemap);
    if (job.exposure !== undefined) query.set('exposure', job.exposure);
    if (job.nofloat) query.set('nofloat', '1');
    if (job['host-tone-mapping']) query.set('hosttonemapping', '1');
    const page = await browser.newPage({ viewport: { width: job.width, height: job.height }, deviceScaleFactor: 1 });
    const problems = [];
    page.on('console', (m) => { if (m.type() === 'error') problems.push(m.text()); });
    page.on('pageerror', (e) => problems.push(e.message));
    page.on('requestfailed', (r) => problems.push(`request failed: ${r.url()}`));
    try {
      await page.goto(`${origin}/client/test/render.html?${query}`);
      // 120 s: a spectral ocean's still frame replays its foam (tens of inverse FFTs per
      // cascade) on SwiftShader, about 20 s on an idle machine.
      await page.waitForFunction(() => window.wgResult !== undefined, null, { timeout: 120000 });
      const result = await page.evaluate(() => window.wgResult);
      if (!result.ok) problems.unshift(result.error);
      if (problems.length) {
        process.stderr.write(`render_graph: ${job.manifest}: the page failed:\n  ${problems.join('\n  ')}\n`);
        code = 1;
      } else {
        await page.locator('canvas').screenshot({ path: job.screenshot });
        process.stdout.write(`render_graph: ${job.manifest} ${job.width}x${job.height} on ${result.renderer}, ` +
          `frame ${result.frameFormat ?? 'none (no description)'} -> ${job.screenshot}\n`);
        for (const w of result.warnings) process.stdout.write(`render_graph: ${job.manifest}: warning: ${w}\n`);
      }
    } catch (e) {
      process.stderr.write(`render_graph: ${job.manifest}: ${e.message}\n`);
      code = 1;
    } finally {
      await page.close();
    }
  }
} finally {
  await browser.close();
  server.close();
}
process.exit(code);
