// Validates WGSL modules with naga (the npm package naga-wasm, pinned in package-lock.json):
// parse, then validate (types, uniformity, bindings). One JSON line per file on stdout:
//   {"file": PATH, "ok": true}
//   {"file": PATH, "ok": false, "errors": [{"line": L, "column": C, "message": TEXT}]}
// line and column are 1-based (0 when naga gave no span). Exit status 0 when every file is
// valid, 1 when one is not, 2 when naga-wasm cannot be loaded (run `npm ci` here).
// Usage: node naga_check.mjs FILE.wgsl...
import { readFileSync } from "node:fs";

let naga;
try {
  naga = await import("naga-wasm");
} catch (e) {
  process.stderr.write(`naga_check: cannot load naga-wasm (run \`npm ci\` in clients/webgpu): ${e.message}\n`);
  process.exit(2);
}

// naga's report names spans as "wgsl:LINE:COL"; the first one is where the error is.
function errorsOf(error) {
  const text = error.formatted || error.message || String(error);
  const at = /wgsl:(\d+):(\d+)/.exec(text);
  const message = (error.message || text).split("\n")[0];
  // The report without its colour codes, for a human reading the diagnostic.
  const detail = text.replace(/\u001b\[[0-9;]*m/g, "").trim();
  return [{ line: at ? Number(at[1]) : 0, column: at ? Number(at[2]) : 0, message, detail }];
}

let failed = false;
for (const file of process.argv.slice(2)) {
  const source = readFileSync(file, "utf8");
  let module, info;
  try {
    module = naga.parseWgsl(source);
    info = naga.validate(module);
    process.stdout.write(JSON.stringify({ file, ok: true }) + "\n");
  } catch (e) {
    failed = true;
    process.stdout.write(JSON.stringify({ file, ok: false, errors: errorsOf(e) }) + "\n");
  } finally {
    info?.free?.();
    module?.free?.();
  }
}
process.exit(failed ? 1 : 0);
