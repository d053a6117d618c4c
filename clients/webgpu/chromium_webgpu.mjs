// Headless Chromium with WebGPU on SwiftShader (no GPU needed), one page served from 127.0.0.1
// (WebGPU is offered only to a secure context) holding a GPUDevice: what tint_check.mjs and
// executor_server.mjs start, in one place so that the flags and the page's set-up cannot drift
// apart. What cannot start (no Chromium, playwright-core not installed, Chromium failing to
// launch, no navigator.gpu, no adapter) is a WebgpuUnavailable whose message says why; a caller
// reports it as a check that did not run, never as one that passed.
import { access, constants } from 'node:fs/promises';
import { createServer } from 'node:http';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

import { serveStaticFile } from '../three/static_files.mjs';

export const DEFAULT_CHROMIUM = '/usr/bin/chromium';

// Chromium's WebGPU on SwiftShader's Vulkan, as the issue's checks found it runs headless.
export const CHROMIUM_WEBGPU_ARGS = ['--enable-unsafe-webgpu', '--enable-features=Vulkan,WebGPU', '--use-angle=swiftshader',
  '--enable-unsafe-swiftshader', '--use-webgpu-adapter=swiftshader', '--ignore-gpu-blocklist'];

export class WebgpuUnavailable extends Error {
  constructor(message) {
    super(message);
    this.name = 'WebgpuUnavailable';
  }
}

// `--chromium PATH` at the front of `argv` (removed), else DEFAULT_CHROMIUM.
export function takeChromiumOption(argv) {
  if (argv[0] !== '--chromium') return DEFAULT_CHROMIUM;
  const chosen = argv[1];
  argv.splice(0, 2);
  return chosen;
}

const clientDir = path.dirname(fileURLToPath(import.meta.url));

// Starts Chromium on a page of this client folder (its scripts and node_modules served under
// '/', and the three.js client's folder under '/three/' for the ocean plan both clients share;
// nothing else), asks the page for an adapter and a device with `features` where
// the adapter offers them, and leaves the device in window.wgDevice. Returns {page, device
// (the adapter's name), close()}. Throws WebgpuUnavailable.
export async function openWebgpuPage(chromiumPath, { title = 'watergraph WebGPU', features = [] } = {}) {
  try {
    await access(chromiumPath, constants.X_OK);
  } catch {
    throw new WebgpuUnavailable(`no Chromium at ${chromiumPath} (Debian: apt-get install chromium)`);
  }
  let chromium;
  try {
    ({ chromium } = await import('playwright-core'));
  } catch (e) {
    throw new WebgpuUnavailable(`cannot load playwright-core (run \`npm ci\` in clients/webgpu): ${e.message}`);
  }
  // '/three/' first: a request takes the first root its path starts with.
  const roots = { '/three/': path.resolve(clientDir, '../three'), '/': clientDir };
  const server = createServer((req, res) => {
    if (new URL(req.url, 'http://127.0.0.1').pathname === '/') {
      res.writeHead(200, { 'content-type': 'text/html' });
      res.end(`<!doctype html><meta charset="utf-8"><link rel="icon" href="data:,"><title>${title}</title>`);
      return;
    }
    serveStaticFile(roots, req, res);
  });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  let browser;
  try {
    browser = await chromium.launch({ executablePath: chromiumPath, args: CHROMIUM_WEBGPU_ARGS, timeout: 60000 });
  } catch (e) {
    server.close();
    throw new WebgpuUnavailable(`cannot start Chromium at ${chromiumPath}: ${e.message.split('\n')[0]}`);
  }
  const close = async () => {
    await browser.close();
    server.close();
  };
  const page = await browser.newPage();
  await page.goto(`http://127.0.0.1:${server.address().port}/`);
  const ready = await page.evaluate(async (wanted) => {
    if (!navigator.gpu) return { skipped: 'this Chromium offers no navigator.gpu (WebGPU disabled)' };
    const adapter = await navigator.gpu.requestAdapter();
    if (!adapter) return { skipped: 'Chromium\'s WebGPU gave no adapter (SwiftShader\'s Vulkan missing?)' };
    const requiredFeatures = wanted.filter((f) => adapter.features.has(f));
    // As many colour attachment bytes per sample as the adapter offers: a filtered ocean
    // cascade's pack writes three RGBA32F targets, 48 bytes, over WebGPU's default of 32
    // (watergraph-webgpu-ocean.js says so clearly where a device has less).
    const requiredLimits = { maxColorAttachmentBytesPerSample: adapter.limits.maxColorAttachmentBytesPerSample };
    window.wgDevice = await adapter.requestDevice({ requiredFeatures, requiredLimits });
    const info = adapter.info ?? {};
    const name = [info.vendor, info.architecture, info.description].filter((x) => x).join(' ');
    return { device: `WebGPU (Chromium${name ? `, ${name}` : ''})` };
  }, features);
  if (ready.skipped) {
    await close();
    throw new WebgpuUnavailable(ready.skipped);
  }
  return { page, device: ready.device, close };
}
