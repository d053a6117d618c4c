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

// naga's report: "error: SUMMARY", the source with carets under the spans ("3 │ ... ^^^ naga::ir::Expression"),
// then notes ("= WHY"). The position is the first caret under something smaller than a whole
// function (else the first "wgsl:LINE:COL"); the message is the summary and its first note.
function errorsOf(error) {
  const text = (error.formatted || error.message || String(error)).replace(/\u001b\[[0-9;]*m/g, "");
  const lines = text.split("\n");
  let line = 0, column = 0, lastNumbered = 0;
  for (const l of lines) {
    const numbered = /^\s*(\d+) │/.exec(l);
    if (numbered) { lastNumbered = Number(numbered[1]); continue; }
    const caret = l.indexOf("^");
    if (!line && caret >= 0 && lastNumbered && !l.includes("naga::ir::Function")) {
      line = lastNumbered;
      const bar = l.indexOf("│");
      column = Math.max(1, caret - bar - 1);
    }
  }
  if (!line) {
    const at = /wgsl:(\d+):(\d+)/.exec(text);
    if (at) [line, column] = [Number(at[1]), Number(at[2])];
  }
  const summary = (lines[0] || "").replace(/^error: /, "");
  const note = lines.find((l) => /^\s*= /.test(l));
  const message = note ? `${summary}: ${note.replace(/^\s*= /, "")}` : summary;
  return [{ line, column, message, detail: text.trim() }];
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
