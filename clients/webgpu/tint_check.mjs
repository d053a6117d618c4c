// Validates WGSL modules with Tint, the WGSL compiler inside Chromium's WebGPU: headless
// Chromium on SwiftShader (no GPU needed), a page served from 127.0.0.1 (WebGPU needs a
// secure context), GPUDevice.createShaderModule and getCompilationInfo(). One JSON line per
// file on stdout, as naga_check.mjs:
//   {"file": PATH, "ok": true}
//   {"file": PATH, "ok": false, "errors": [{"line": L, "column": C, "message": TEXT}]}
//   {"file": PATH, "ok": false, "skipped": WHY}   Chromium or a WebGPU adapter missing
// Exit status 0 when every file is valid, 1 when one is not, 2 when Tint could not run.
// Usage: node tint_check.mjs [--chromium /usr/bin/chromium] FILE.wgsl...
import { access, constants, readFile } from "node:fs/promises";
import { createServer } from "node:http";

const argv = process.argv.slice(2);
let chromiumPath = "/usr/bin/chromium";
if (argv[0] === "--chromium") {
  chromiumPath = argv[1];
  argv.splice(0, 2);
}

function skipAll(why) {
  for (const file of argv) process.stdout.write(JSON.stringify({ file, ok: false, skipped: why }) + "\n");
  process.exit(2);
}

try {
  await access(chromiumPath, constants.X_OK);
} catch {
  skipAll(`no Chromium at ${chromiumPath} (Debian: apt-get install chromium)`);
}
let chromium;
try {
  ({ chromium } = await import("playwright-core"));
} catch (e) {
  skipAll(`cannot load playwright-core (run \`npm ci\` in clients/webgpu): ${e.message}`);
}

// An empty page: WebGPU is offered only to a secure context such as http://127.0.0.1.
const server = createServer((req, res) => {
  res.writeHead(200, { "content-type": "text/html" });
  res.end("<!doctype html><title>tint_check</title>");
});
await new Promise((resolve) => server.listen(0, "127.0.0.1", resolve));
let browser;
try {
  browser = await chromium.launch({
    executablePath: chromiumPath,
    args: ["--enable-unsafe-webgpu", "--enable-features=Vulkan,WebGPU", "--use-angle=swiftshader",
           "--enable-unsafe-swiftshader", "--use-webgpu-adapter=swiftshader", "--ignore-gpu-blocklist"],
  });
} catch (e) {
  server.close();
  skipAll(`cannot start Chromium at ${chromiumPath}: ${e.message.split("\n")[0]}`);
}

let status = 0;
try {
  const page = await browser.newPage();
  await page.goto(`http://127.0.0.1:${server.address().port}/`);
  const sources = [];
  for (const file of argv) sources.push(await readFile(file, "utf8"));
  const results = await page.evaluate(async (codes) => {
    if (!navigator.gpu) return { skipped: "this Chromium offers no navigator.gpu (WebGPU disabled)" };
    const adapter = await navigator.gpu.requestAdapter();
    if (!adapter) return { skipped: "Chromium's WebGPU gave no adapter (SwiftShader's Vulkan missing?)" };
    const device = await adapter.requestDevice();
    const out = [];
    for (const code of codes) {
      const module = device.createShaderModule({ code });
      const info = await module.getCompilationInfo();
      const errors = info.messages.filter((m) => m.type === "error")
        .map((m) => ({ line: m.lineNum, column: m.linePos, message: m.message }));
      out.push({ ok: errors.length === 0, errors });
    }
    return { results: out };
  }, sources);
  if (results.skipped) {
    for (const file of argv) process.stdout.write(JSON.stringify({ file, ok: false, skipped: results.skipped }) + "\n");
    status = 2;
  } else {
    results.results.forEach((r, i) => {
      const line = r.ok ? { file: argv[i], ok: true } : { file: argv[i], ok: false, errors: r.errors };
      process.stdout.write(JSON.stringify(line) + "\n");
      if (!r.ok) status = Math.max(status, 1);
    });
  }
} finally {
  await browser.close();
  server.close();
}
process.exit(status);
