// `watergraph probe --target wgsl`'s helper: one headless Chromium (WebGPU on SwiftShader, a
// page served from 127.0.0.1, as tint_check.mjs starts it) kept open while the compiler sends
// probe jobs, one JSON line each on stdin (watergraph-webgpu-probe.js says what a job holds).
// On stdout, one JSON line first:
//   {"ready": true, "device": NAME}   the page has a WebGPU device
//   {"skipped": WHY}                  Chromium, playwright-core or an adapter is missing
// then one line per job: {"pixels": [float32 bit patterns, 4 per case]} or {"error": WHY}
// (Tint rejected the module, WebGPU validation failed). It ends at the end of its input.
// Usage: node probe_server.mjs [--chromium /usr/bin/chromium]
import { access, constants, readFile } from 'node:fs/promises';
import { createServer } from 'node:http';
import path from 'node:path';
import { createInterface } from 'node:readline';
import { fileURLToPath } from 'node:url';

const argv = process.argv.slice(2);
const chromiumPath = argv[0] === '--chromium' ? argv[1] : '/usr/bin/chromium';
const say = (line) => new Promise((resolve) => process.stdout.write(JSON.stringify(line) + '\n', resolve));

async function skip(why) {
  await say({ skipped: why });
  process.exit(2);
}

try {
  await access(chromiumPath, constants.X_OK);
} catch {
  await skip(`no Chromium at ${chromiumPath} (Debian: apt-get install chromium)`);
}
let chromium;
try {
  ({ chromium } = await import('playwright-core'));
} catch (e) {
  await skip(`cannot load playwright-core (run \`npm ci\` in clients/webgpu): ${e.message}`);
}

// The page and the runner module; WebGPU is offered only to a secure context such as 127.0.0.1.
const runner = await readFile(path.join(path.dirname(fileURLToPath(import.meta.url)), 'watergraph-webgpu-probe.js'), 'utf8');
const server = createServer((req, res) => {
  if (req.url === '/watergraph-webgpu-probe.js') {
    res.writeHead(200, { 'content-type': 'text/javascript' });
    res.end(runner);
    return;
  }
  res.writeHead(200, { 'content-type': 'text/html' });
  res.end('<!doctype html><title>watergraph probe</title>');
});
await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
let browser;
try {
  browser = await chromium.launch({
    executablePath: chromiumPath,
    args: ['--enable-unsafe-webgpu', '--enable-features=Vulkan,WebGPU', '--use-angle=swiftshader',
           '--enable-unsafe-swiftshader', '--use-webgpu-adapter=swiftshader', '--ignore-gpu-blocklist'],
  });
} catch (e) {
  server.close();
  await skip(`cannot start Chromium at ${chromiumPath}: ${e.message.split('\n')[0]}`);
}

async function finish(code) {
  await browser.close();
  server.close();
  process.exitCode = code;
}

const page = await browser.newPage();
await page.goto(`http://127.0.0.1:${server.address().port}/`);
const ready = await page.evaluate(async () => {
  if (!navigator.gpu) return { skipped: 'this Chromium offers no navigator.gpu (WebGPU disabled)' };
  const adapter = await navigator.gpu.requestAdapter();
  if (!adapter) return { skipped: 'Chromium\'s WebGPU gave no adapter (SwiftShader\'s Vulkan missing?)' };
  window.wgDevice = await adapter.requestDevice();
  window.wgProbe = (await import('/watergraph-webgpu-probe.js')).runProbeCases;
  const info = adapter.info ?? {};
  const name = [info.vendor, info.architecture, info.description].filter((x) => x).join(' ');
  return { ready: true, device: `WebGPU (Chromium${name ? `, ${name}` : ''})` };
});
await say(ready);
if (ready.skipped) {
  await finish(2);
} else {
  // One job at a time, in order: the compiler waits for each answer.
  for await (const line of createInterface({ input: process.stdin, crlfDelay: Infinity })) {
    if (!line.trim()) continue;
    let reply;
    try {
      const job = JSON.parse(line);
      reply = { pixels: await page.evaluate((j) => window.wgProbe(window.wgDevice, j), job) };
    } catch (e) {
      reply = { error: e.message.split('\n')[0] };
    }
    await say(reply);
  }
  await finish(0);
}
