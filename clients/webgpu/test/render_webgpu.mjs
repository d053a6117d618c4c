// Renders a compiled graph (compile --target es300,wgsl --textures) with the WebGPU runner in
// headless Chromium on SwiftShader and writes the frame as a PNG.
// Usage: node render_webgpu.mjs --dir DIR --manifest GRAPH.manifest.json --description scene.json
//          --size WxH --camera above|grazing|underwater|topdown --time T --grid N --png OUT.png
//          [--scene builtin|none] [--chromium /usr/bin/chromium]
//        node render_webgpu.mjs --dir DIR --jobs JOBS.json --description scene.json --size WxH
//          --time T --grid N [--chromium ...]
// JOBS.json: [{"manifest": PATH under DIR, "camera": NAME, "png": OUT, "scene": "builtin"|"none"}, ...],
// all rendered by one page; a failed job is reported and the others still run (not after a
// job that timed out or crashed the page: the page is not trusted with the next).
// (scene.json from `watergraph scene`: its camera presets, sun, mesh and shaders are the runtime's;
// --scene none draws the water alone, as `render --scene none`.)
// Exit status: 0 written; 1 the page failed (message on stderr); 2 usage, or Chromium/WebGPU missing.
import { access, constants, readFile, writeFile } from 'node:fs/promises';
import { startStaticServer } from '../../three/test/static_server.mjs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { parseArgs } from 'node:util';

const fail = (code, message) => {
  process.stderr.write(`render_webgpu: ${message}\n`);
  process.exit(code);
};
const keys = ['dir', 'manifest', 'description', 'size', 'camera', 'time', 'grid', 'png', 'chromium', 'scene', 'jobs'];
const optional = new Set(['chromium', 'scene', 'jobs']);
let args;
try {
  ({ values: args } = parseArgs({ options: Object.fromEntries(keys.map((k) => [k, { type: 'string' }])) }));
} catch (e) {
  fail(2, e.message);
}
// One job from the command line, or the list of --jobs.
if (args.jobs !== undefined) for (const k of ['manifest', 'camera', 'png', 'scene']) optional.add(k);
for (const k of keys) if (!optional.has(k) && args[k] === undefined) fail(2, `missing --${k}`);
let jobs = [{ manifest: args.manifest, camera: args.camera, png: args.png, scene: args.scene ?? 'builtin' }];
if (args.jobs !== undefined) {
  try {
    jobs = JSON.parse(await readFile(args.jobs, 'utf8'));
  } catch (e) {
    fail(2, `cannot read the jobs ${args.jobs}: ${e.message}`);
  }
  if (!Array.isArray(jobs) || jobs.some((j) => !j || typeof j.manifest !== 'string' || typeof j.camera !== 'string' || typeof j.png !== 'string'))
    fail(2, `${args.jobs}: not a list of {manifest, camera, png, scene}`);
}
for (const j of jobs) {
  j.scene ??= 'builtin';
  if (!['builtin', 'none'].includes(j.scene)) fail(2, `${j.manifest}: scene must be builtin or none`);
}
const [width, height] = args.size.split('x').map(Number);
const chromiumPath = args.chromium ?? '/usr/bin/chromium';
try {
  await access(chromiumPath, constants.X_OK);
} catch {
  fail(2, `no Chromium at ${chromiumPath} (Debian: apt-get install chromium)`);
}
const here = path.dirname(fileURLToPath(import.meta.url));
let chromium;
try {
  ({ chromium } = await import('playwright-core'));
} catch (e) {
  fail(2, `cannot load playwright-core (run \`npm ci\` in clients/webgpu): ${e.message}`);
}
const roots = { '/webgpu/': path.resolve(here, '..'), '/three/': path.resolve(here, '../../three'),
  '/out/': path.resolve(args.dir), '/scene/': path.dirname(path.resolve(args.description)) };
const { server, origin } = await startStaticServer(roots);
const browser = await chromium.launch({
  executablePath: chromiumPath,
  args: ['--enable-unsafe-webgpu', '--enable-features=Vulkan,WebGPU', '--use-angle=swiftshader',
         '--enable-unsafe-swiftshader', '--use-webgpu-adapter=swiftshader', '--ignore-gpu-blocklist'],
  timeout: 30000,
}).catch((e) => { server.close(); fail(2, `cannot start Chromium at ${chromiumPath}: ${e.message.split('\n')[0]}`); });
let code = 0;
try {
  // One page renders every job (window.wgRender, test/render.js), so naga and the scene's
  // translated shaders are made once; a page error is reported with the job it came in.
  const page = await browser.newPage();
  const problems = [];
  page.on('pageerror', (e) => problems.push(e.message));
  await page.goto(`${origin}/webgpu/test/render.html`);
  await page.waitForFunction(() => window.wgReady === true, null, { timeout: 60000 });
  for (const job of jobs) {
    problems.length = 0;
    const params = { manifest: `/out/${job.manifest}`, description: `/scene/${path.basename(args.description)}`,
      width, height, camera: job.camera, time: args.time, grid: args.grid, scene: job.scene };
    // 120 s: a spectral ocean's still frame replays its foam (tens of transforms per cascade).
    let timer;
    const timeout = new Promise((resolve) => {
      timer = setTimeout(() => resolve({ ok: false, error: 'TimeoutError: the frame took over 120 s' }), 120000);
    });
    const result = await Promise.race([page.evaluate((p) => window.wgRender(p), params), timeout])
      .catch((e) => ({ ok: false, error: `${e.name}: ${e.message.split('\n')[0]}` }));
    clearTimeout(timer);
    if (!result.ok) {
      process.stderr.write(`render_webgpu: ${job.manifest}: ${[result.error, ...problems].join('\n  ')}\n`);
      // A missing WebGPU is the machine's (2); a job's failure is the graph's or the runner's (1).
      code = /WebGPU is not enabled|no WebGPU adapter/.test(result.error) ? 2 : Math.max(code, 1);
      if (code === 2 || /TimeoutError|Target closed|crashed/.test(result.error)) break;
    } else {
      await writeFile(job.png, Buffer.from(result.png, 'base64'));
      process.stdout.write(`render_webgpu: ${job.manifest} ${job.camera} scene ${job.scene} ${width}x${height} on WebGPU (${result.adapter}) -> ${job.png}\n`);
    }
  }
} finally {
  await browser.close();
  server.close();
}
process.exit(code);
