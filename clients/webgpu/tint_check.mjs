// Validates WGSL modules with Tint, the WGSL compiler inside Chromium's WebGPU: headless
// Chromium on SwiftShader (chromium_webgpu.mjs), GPUDevice.createShaderModule and
// getCompilationInfo(). One JSON line per file on stdout, as naga_check.mjs:
//   {"file": PATH, "ok": true}
//   {"file": PATH, "ok": false, "errors": [{"line": L, "column": C, "message": TEXT}]}
//   {"file": PATH, "ok": false, "skipped": WHY}   Chromium or a WebGPU adapter missing
// Exit status 0 when every file is valid, 1 when one is not, 2 when Tint could not run.
// Usage: node tint_check.mjs [--chromium /usr/bin/chromium] FILE.wgsl...
import { readFile } from 'node:fs/promises';

import { openWebgpuPage, takeChromiumOption, WebgpuUnavailable } from './chromium_webgpu.mjs';

const argv = process.argv.slice(2);
const chromiumPath = takeChromiumOption(argv);

let session;
try {
  session = await openWebgpuPage(chromiumPath, { title: 'tint_check' });
} catch (e) {
  if (!(e instanceof WebgpuUnavailable)) throw e;
  for (const file of argv) process.stdout.write(JSON.stringify({ file, ok: false, skipped: e.message }) + '\n');
  process.exit(2);
}

let status = 0;
try {
  const sources = [];
  for (const file of argv) sources.push(await readFile(file, 'utf8'));
  const results = await session.page.evaluate(async (codes) => {
    const out = [];
    for (const code of codes) {
      const module = window.wgDevice.createShaderModule({ code });
      const info = await module.getCompilationInfo();
      const errors = info.messages.filter((m) => m.type === 'error')
        .map((m) => ({ line: m.lineNum, column: m.linePos, message: m.message }));
      out.push({ ok: errors.length === 0, errors });
    }
    return out;
  }, sources);
  results.forEach((r, i) => {
    const line = r.ok ? { file: argv[i], ok: true } : { file: argv[i], ok: false, errors: r.errors };
    process.stdout.write(JSON.stringify(line) + '\n');
    if (!r.ok) status = Math.max(status, 1);
  });
} finally {
  await session.close();
}
process.exit(status);
