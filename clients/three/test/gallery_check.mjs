// Loads the gallery (example/) in headless Chromium as a person would: prepares it with
// `watergraph` (example/serve.mjs), opens the page, waits for frames, switches to each
// graph named with --switch through the graph picker, then picks the tone mapper --tonemap
// and sets the exposure slider to --exposure (EV), and fails on any console error or
// failed request. --buoys-json FILE writes the last graph's floating buoys (the page's time
// and each buoy's position and normal from the graph's surface query). Used by
// tests/ecosystem/three_client_test.cpp.
//
//   node test/gallery_check.mjs --watergraph build/cli/watergraph [--switch deferred_underwater,pool]
//     [--tonemap agx] [--exposure 0.5] [--size 960x540] [--screenshot gallery.png] [--buoys-json FILE]
//     [--chromium /usr/bin/chromium]
//
// Exit status: 0 fine; 1 the page failed (message on stderr); 2 usage or environment.
import { access, mkdtemp, rm, writeFile } from 'node:fs/promises';
import { constants } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { parseArgs } from 'node:util';
import { prepareGallery, galleryServer } from '../example/serve.mjs';

function fail(code, message) {
  process.stderr.write(`gallery_check: ${message}\n`);
  process.exit(code);
}

let args;
try {
  ({ values: args } = parseArgs({
    options: Object.fromEntries(['watergraph', 'switch', 'size', 'screenshot', 'chromium', 'tonemap', 'exposure', 'buoys-json']
      .map((k) => [k, { type: 'string' }])),
  }));
} catch (e) {
  fail(2, e.message);
}
if (!args.watergraph) fail(2, 'missing --watergraph');
const size = /^(\d+)x(\d+)$/.exec(args.size ?? '960x540');
if (!size) fail(2, `--size must be WIDTHxHEIGHT (got '${args.size}')`);
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
  fail(2, `cannot load playwright-core (run \`npm ci\` in clients/three): ${e.message}`);
}

const outDir = await mkdtemp(path.join(tmpdir(), 'wg_gallery_check_'));
let code = 0;
try {
  let graphs;
  try {
    graphs = prepareGallery({ watergraph: args.watergraph, outDir });
  } catch (e) {
    fail(2, `cannot prepare the gallery: ${e.stderr?.toString() || e.message}`);
  }
  const server = galleryServer(outDir);
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  const browser = await chromium.launch({
    executablePath: chromiumPath,
    args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist'],
    timeout: 30000,
  }).catch((e) => fail(2, `cannot start Chromium at ${chromiumPath}: ${e.message}`));
  try {
    const page = await browser.newPage({ viewport: { width: Number(size[1]), height: Number(size[2]) }, deviceScaleFactor: 1 });
    const problems = [];
    page.on('console', (m) => { if (m.type() === 'error') problems.push(m.text()); });
    page.on('pageerror', (e) => problems.push(e.message));
    page.on('requestfailed', (r) => problems.push(`request failed: ${r.url()}`));
    await page.goto(`http://127.0.0.1:${server.address().port}/`);
    // A few frames of the first graph, then each graph asked for, picked in the <select>.
    // (or an error the page reports, which ends the check at once)
    const settle = (name) => page.waitForFunction(
      (n) => window.wgGallery?.errors?.length || (window.wgGallery?.ready && window.wgGallery.graph === n && window.wgGallery.frames >= 3),
      name, { timeout: 60000 });
    await settle(graphs[0].name);
    const switched = [];
    for (const name of (args.switch ?? '').split(',').filter(Boolean)) {
      if (!graphs.some((g) => g.name === name)) throw new Error(`no graph '${name}' in the gallery`);
      await page.selectOption('#graph', name);
      await settle(name);
      switched.push(name);
    }
    // The view controls: frames drawn through the tone mapper and exposure picked.
    if (args.tonemap) await page.selectOption('#tonemap', args.tonemap);
    if (args.exposure) await page.locator('#exposure').fill(args.exposure);
    const frames = await page.evaluate(() => window.wgGallery.frames);
    await page.waitForFunction((n) => window.wgGallery.errors.length || window.wgGallery.frames >= n + 3, frames, { timeout: 60000 });
    const view = await page.evaluate(() => ({ ...window.wgGallery.view, frameFormat: window.wgGallery.frameFormat }));
    const floating = await page.evaluate(() => ({ graph: window.wgGallery.graph, time: window.wgGallery.buoysTime,
      buoys: window.wgGallery.buoys }));
    if (args['buoys-json']) await writeFile(args['buoys-json'], JSON.stringify(floating));
    const errors = await page.evaluate(() => window.wgGallery.errors);
    problems.push(...errors);
    if (problems.length) {
      process.stderr.write(`gallery_check: the page failed:\n  ${problems.join('\n  ')}\n`);
      code = 1;
    } else {
      if (args.screenshot) await page.screenshot({ path: args.screenshot });
      process.stdout.write(`gallery_check: ${graphs.length} graphs, started with ${graphs[0].name}, ` +
        `switched to ${switched.join(', ') || 'none'}: no console errors\n` +
        `gallery_check: view ${view.toneMapping} at ${view.exposure} EV, frame ${view.frameFormat}\n` +
        `gallery_check: ${floating.buoys.length} buoys floating on ${floating.graph}\n`);
    }
  } catch (e) {
    process.stderr.write(`gallery_check: ${e.message}\n`);
    code = 1;
  } finally {
    await browser.close();
    server.close();
  }
} finally {
  await rm(outDir, { recursive: true, force: true });
}
process.exit(code);
