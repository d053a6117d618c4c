// The helper of `watergraph probe --target wgsl` and `check --target wgsl`: one headless
// Chromium (WebGPU on SwiftShader, chromium_webgpu.mjs) kept open while the compiler sends jobs,
// one JSON line each on stdin. On stdout, one JSON line first:
//   {"ready": true, "device": NAME}   the page has a WebGPU device
//   {"skipped": WHY}                  Chromium, playwright-core or an adapter is missing
// then one line per job, in order:
//   a probe job (no "kind"; watergraph-webgpu-probe.js says what it holds):
//     {"pixels": [float32 bit patterns, 4 per case]}
//   check's jobs ("kind": "scene", "water", "frame", "drop"; watergraph-webgpu-check.js):
//     {"ok": true}, or for a frame {"frame": base64 of its float32 RGBA, row 0 at the bottom}
//   or {"error": WHY} (Tint rejected a module, WebGPU validation failed).
// It ends at the end of its input.
// Usage: node executor_server.mjs [--chromium /usr/bin/chromium]
import { createInterface } from 'node:readline';

import { openWebgpuPage, takeChromiumOption, WebgpuUnavailable } from './chromium_webgpu.mjs';

const chromiumPath = takeChromiumOption(process.argv.slice(2));
const say = (line) => new Promise((resolve) => process.stdout.write(JSON.stringify(line) + '\n', resolve));

let session;
try {
  // check's frames are RGBA32F and the water blends into them as the runtime's GL_RGBA32F frame.
  session = await openWebgpuPage(chromiumPath, { title: 'watergraph executor', features: ['float32-blendable'] });
} catch (e) {
  if (!(e instanceof WebgpuUnavailable)) throw e;
  await say({ skipped: e.message });
  process.exit(2);
}
const { page } = session;
await page.evaluate(async () => {
  window.wgProbe = (await import('/watergraph-webgpu-probe.js')).runProbeCases;
  window.wgCheck = (await import('/watergraph-webgpu-check.js')).runCheckJob;
});
await say({ ready: true, device: session.device });
// One job at a time, in order: the compiler waits for each answer.
for await (const line of createInterface({ input: process.stdin, crlfDelay: Infinity })) {
  if (!line.trim()) continue;
  let reply;
  try {
    const job = JSON.parse(line);
    reply = job.kind === undefined
      ? { pixels: await page.evaluate((j) => window.wgProbe(window.wgDevice, j), job) }
      : await page.evaluate((j) => window.wgCheck(window.wgDevice, j), job);
  } catch (e) {
    reply = { error: e.message.split('\n')[0] };
  }
  await say(reply);
}
await session.close();
