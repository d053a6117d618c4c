// watergraph's front end against three.js TSL, side by side in one run, on the synthetic
// graphs of bench/synthetic_graph.cpp and their TSL port (synthetic_tsl.js).
//
//   node bench/tsl/tsl_vs_watergraph.mjs --wg build/bin/wg_bench_compile [--rounds 5]
//     [--trials 5] [--warmup 3] [--repetitions 3] [--nodes 100,1000,10000] [--chromium /usr/bin/chromium]
//
// Each round runs both, the order alternating: watergraph's front end (wg_bench_compile:
// `before_glslang_es300`, load, resolve, passes, the es300 emit and the manifest, what
// `watergraph compile --target es300` does before glslang — GLSL ES 3.00 for WebGL2, as
// TSL's build() makes — and `before_glslang`, the same with the three GLSL targets'
// emits; the median of --repetitions runs of Google Benchmark, wall time) and, in headless Chromium, --warmup untimed and then --trials timed builds of each
// graph by three.js (a fresh node graph and material each, then GLSLNodeBuilder.build():
// TSL to GLSL ES 3.00 for WebGL2, before WebGL compiles it; the median of the trials). The
// table gives per size the median over rounds of each and of the per-round ratio TSL /
// watergraph, and watergraph's t(10k)/t(1k) and peak heap. Needs the three.js client's npm
// packages (clients/three: three 0.187.0, playwright-core; `npm ci` there) and Chromium.
// The machine is shared and noisy: compare ratios of one run, not times across runs.
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { parseArgs } from 'node:util';

const here = path.dirname(fileURLToPath(import.meta.url));
const root = path.resolve(here, '../..');
const clientDir = path.join(root, 'clients/three');

const { values: args } = parseArgs({
  options: {
    wg: { type: 'string' }, rounds: { type: 'string', default: '5' }, trials: { type: 'string', default: '5' },
    warmup: { type: 'string', default: '3' },
    repetitions: { type: 'string', default: '3' }, nodes: { type: 'string', default: '100,1000,10000' },
    chromium: { type: 'string', default: '/usr/bin/chromium' },
  },
});
if (!args.wg) {
  process.stderr.write('tsl_vs_watergraph: --wg PATH (the wg_bench_compile binary) is required\n');
  process.exit(2);
}
const sizes = args.nodes.split(',').map(Number);
const median = (v) => { const s = [...v].sort((a, b) => a - b); const m = s.length >> 1; return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2; };

// One watergraph round: { nodes: { ms, allTargetsMs, peakMiB } } (es300 alone, and every target).
function watergraphRound() {
  const dir = mkdtempSync(path.join(tmpdir(), 'wg_tsl_bench_'));
  const out = path.join(dir, 'bench.json');
  try {
    execFileSync(args.wg, [`--benchmark_filter=^before_glslang(_es300)?/synthetic_(${sizes.join('|')})$`,
      `--benchmark_repetitions=${args.repetitions}`, '--benchmark_report_aggregates_only=true',
      '--benchmark_min_time=0.1', `--benchmark_out=${out}`, '--benchmark_out_format=json'], { stdio: 'ignore' });
    const doc = JSON.parse(readFileSync(out, 'utf8'));
    const got = {};
    for (const b of doc.benchmarks) {
      if (b.aggregate_name !== 'median') continue;
      const n = Number(/synthetic_(\d+)$/.exec(b.run_name)[1]);
      const scale = { ns: 1e-6, us: 1e-3, ms: 1, s: 1e3 }[b.time_unit];
      got[n] ??= {};
      if (b.run_name.startsWith('before_glslang_es300/')) Object.assign(got[n], { ms: b.real_time * scale, peakMiB: b.peak_MiB });
      else got[n].allTargetsMs = b.real_time * scale;
    }
    return got;
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}

const { chromium } = await import(pathToFileURL(path.join(clientDir, 'node_modules/playwright-core/index.mjs')).href);
const { startStaticServer } = await import(pathToFileURL(path.join(clientDir, 'test/static_server.mjs')).href);
const { server, origin } = await startStaticServer({ '/three/': path.join(clientDir, 'node_modules/three'), '/bench/': here });
const browser = await chromium.launch({
  executablePath: args.chromium,
  args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist'],
});

// One TSL round: { nodes: { buildMs, constructMs, count } }, medians of the trials.
async function tslRound() {
  const page = await browser.newPage();
  try {
    await page.goto(`${origin}/bench/tsl_bench.html?nodes=${sizes.join(',')}&trials=${args.trials}&warmup=${args.warmup}`);
    await page.waitForFunction(() => window.wgBench !== undefined, null, { timeout: 600000 });
    const r = await page.evaluate(() => window.wgBench);
    if (!r.ok) throw new Error(r.error);
    const got = { revision: r.revision };
    for (const s of r.results) {
      got[s.nodes] = { buildMs: median(s.buildMs), constructMs: median(s.constructMs), count: s.count,
        chars: s.vertexChars + s.fragmentChars, trials: s.buildMs };
    }
    return got;
  } finally {
    await page.close();
  }
}

const rounds = [];
try {
  for (let i = 0; i < Number(args.rounds); ++i) {
    let wg, tsl;
    if (i % 2 === 0) { wg = watergraphRound(); tsl = await tslRound(); } else { tsl = await tslRound(); wg = watergraphRound(); }
    rounds.push({ wg, tsl });
    process.stderr.write(`round ${i + 1}: ` + sizes.map((n) => `${n}: watergraph ${wg[n].ms.toFixed(2)} ms, ` +
      `TSL build ${tsl[n].buildMs.toFixed(1)} ms (trials ${tsl[n].trials.map((t) => t.toFixed(1)).join(' ')})`).join('; ') + '\n');
  }
} finally {
  await browser.close();
  server.close();
}

const range = (v) => `${median(v).toFixed(2)} (${Math.min(...v).toFixed(2)}-${Math.max(...v).toFixed(2)})`;
process.stdout.write(`three.js r${rounds[0].tsl.revision}, ${rounds.length} rounds, medians (range over rounds)\n\n`);
process.stdout.write('| nodes | watergraph es300 ms | TSL build() ms | TSL build / watergraph es300 | watergraph three targets ms | TSL build / watergraph three targets | TSL graph construction ms |\n|---|---|---|---|---|---|---|\n');
for (const n of sizes) {
  const wg = rounds.map((r) => r.wg[n].ms), build = rounds.map((r) => r.tsl[n].buildMs);
  const construct = rounds.map((r) => r.tsl[n].constructMs), ratio = rounds.map((r) => r.tsl[n].buildMs / r.wg[n].ms);
  const all = rounds.map((r) => r.wg[n].allTargetsMs), allRatio = rounds.map((r) => r.tsl[n].buildMs / r.wg[n].allTargetsMs);
  process.stdout.write(`| ${n} (TSL port ${rounds[0].tsl[n].count}, GLSL ${rounds[0].tsl[n].chars} chars) | ${range(wg)} | ` +
    `${range(build)} | ${range(ratio)} | ${range(all)} | ${range(allRatio)} | ${range(construct)} |\n`);
}
if (sizes.includes(1000) && sizes.includes(10000)) {
  const growth = rounds.map((r) => r.wg[10000].ms / r.wg[1000].ms);
  process.stdout.write(`\nwatergraph es300 t(10k)/t(1k): ${range(growth)}; peak heap at 10k: ${rounds[0].wg[10000].peakMiB.toFixed(2)} MiB\n`);
}
