#!/usr/bin/env python3
"""Compile speed of two or more wg_bench_compile binaries, side by side in one run.

The machines these figures come from are shared and their speed drifts by 2x within an
hour, so absolute times mean little and a comparison is only worth what its pairing is:
the binaries run in turn, round after round (the order rotating), and every round gives
each binary the median of a few repetitions of the same benchmarks. The table reports,
per binary, the median over rounds, and per pair the median of the per-round ratios.

  bench/compile_side_by_side.py OLD_BIN NEW_BIN [--rounds 7]

CPU time of the benchmark thread (Google Benchmark's cpu_time), as the benchmarks report it.
"""
import argparse
import json
import statistics
import os
import subprocess
import sys
import tempfile

# before_glslang_es300: the one target a WebGL page compiles (and three.js TSL's build() makes).
PHASES = ["json_sax_floor", "load", "resolve", "emit_glsl330", "manifest", "before_glslang", "before_glslang_es300"]
SIZES = ["1000", "10000"]


def run_once(binary, repetitions, min_time):
    pattern = "^(%s)/synthetic_(%s)$" % ("|".join(PHASES), "|".join(SIZES))
    # The binary's console reporter is its own (a markdown summary); the JSON goes to a file.
    fd, path = tempfile.mkstemp(suffix=".json")
    os.close(fd)
    try:
        subprocess.run(
            [binary, "--benchmark_filter=" + pattern, "--benchmark_repetitions=%d" % repetitions,
             "--benchmark_report_aggregates_only=true", "--benchmark_min_time=%g" % min_time,
             "--benchmark_out=" + path, "--benchmark_out_format=json"],
            check=True, stdout=subprocess.DEVNULL)
        with open(path) as f:
            doc = json.load(f)
    finally:
        os.unlink(path)
    times, peaks = {}, {}
    for b in doc["benchmarks"]:
        if b.get("aggregate_name") != "median":
            continue
        name = b["run_name"]
        scale = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[b["time_unit"]]
        times[name] = b["cpu_time"] * scale
        if "peak_MiB" in b:
            peaks[name] = b["peak_MiB"]
    return times, peaks


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("binaries", nargs="+")
    ap.add_argument("--rounds", type=int, default=7)
    ap.add_argument("--repetitions", type=int, default=3)
    ap.add_argument("--min-time", type=float, default=0.1)
    args = ap.parse_args()
    bins = args.binaries
    per = {b: [] for b in bins}
    peaks = {}
    for r in range(args.rounds):
        order = bins[r % len(bins):] + bins[:r % len(bins)]
        for b in order:
            t, p = run_once(b, args.repetitions, args.min_time)
            per[b].append(t)
            peaks[b] = p
            print("round %d %s: before_glslang 1k %.3f ms, 10k %.2f ms" %
                  (r + 1, b, t.get("before_glslang/synthetic_1000", float("nan")),
                   t.get("before_glslang/synthetic_10000", float("nan"))), file=sys.stderr)

    names = sorted({n for b in bins for rnd in per[b] for n in rnd},
                   key=lambda n: (SIZES.index(n.split("_")[-1]), PHASES.index(n.split("/")[0])))
    print("| phase | " + " | ".join("%s (median, range)" % b for b in bins) +
          "".join(" | %s / %s (median of round ratios)" % (b, bins[0]) for b in bins[1:]) + " |")
    print("|---|" + "---|" * (len(bins) + len(bins) - 1))
    for n in names:
        cells = []
        for b in bins:
            v = [rnd[n] for rnd in per[b] if n in rnd]
            cells.append("%.3f (%.3f-%.3f)" % (statistics.median(v), min(v), max(v)) if v else "-")
        for b in bins[1:]:
            ratios = [nb[n] / na[n] for na, nb in zip(per[bins[0]], per[b]) if n in na and n in nb]
            cells.append("%.3f" % statistics.median(ratios) if ratios else "-")
        print("| %s ms | %s |" % (n, " | ".join(cells)))
    for b in bins:
        r = [rnd["before_glslang/synthetic_10000"] / rnd["before_glslang/synthetic_1000"] for rnd in per[b]
             if "before_glslang/synthetic_10000" in rnd and "before_glslang/synthetic_1000" in rnd]
        if r:
            print("%s: t(10k)/t(1k) before glslang, per round: median %.2f (%.2f-%.2f)" %
                  (b, statistics.median(r), min(r), max(r)))
        for n, v in sorted(peaks[b].items()):
            print("%s: peak heap %s %.2f MiB" % (b, n, v))


if __name__ == "__main__":
    main()
