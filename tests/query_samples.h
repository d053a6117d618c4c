#pragma once
// Shared by the surface-query tests (tests/codegen/query_*_test.cpp): the graphs they query,
// the double reference of the vertex stage (the CPU backend's node evals over the ops the
// vertex position and normal read, independent of codegen/query_program.h), and drivers
// that print what a generated C header or JavaScript module answers.
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "codegen/compile.h"
#include "codegen/cpu_backend.h"
#include "codegen/water_surface_eval.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg::test {

// A steep sea: four Gerstner waves with sum Q k A = 0.969 (1 folds the surface over).
inline const char* kSteepWaves = R"J([
  {"direction": [1, 0.2], "steepness": 1, "wavelength": 12, "amplitude": 1.5},
  {"direction": [0.3, 1], "steepness": 0.6, "wavelength": 7, "amplitude": 0.25},
  {"direction": [-0.7, 0.6], "steepness": 0.3, "wavelength": 4, "amplitude": 0.08, "phase": 1.3},
  {"direction": [0.9, -0.4], "steepness": 0.4, "wavelength": 2.5, "amplitude": 0.012}])J";
inline constexpr double kSteepSum = 0.969;  // sum Q k A of kSteepWaves, rounded down

// A graph of the steep sea alone (kSteepWaves displacing the grid), written to dir/steep.json.
// With `shadeByPosition` its colour is the world position, so the vertex stage passes the
// displaced point to the fragment stage (the vk450 capture of query_gpu_test reads it there).
inline std::string writeSteepGraph(const std::string& dir, bool shadeByPosition = false) {
  test::writeFile(dir + "/steep.json",
                  test::graphJson(R"J({"id": "waves", "type": "gerstner_waves", "options": {"waves": )J" +
                                      std::string(kSteepWaves) + "}}," +
                                      (shadeByPosition ? R"J({"id": "p", "type": "world_position"},)J" : "") + R"J(
      {"id": "surface", "type": "vertex_output", "inputs": {"position": "waves.position", "normal": "waves.normal"}})J",
                                  R"J("vertex": {"position": "surface.position", "normal": "surface.normal"},
      "fragment": {"color": )J" + std::string(shadeByPosition ? "\"p.out\"" : "[0, 0.2, 0.4]") + "}"));
  return dir + "/steep.json";
}

// A surface an expression folds over: x = x0 + 1.5 sin x0 (slope 1 + 1.5 cos x0, negative on
// a third of each period, where three water points reach one x), y = 0.5 cos x0; written to
// dir/fold.json.
inline std::string writeFoldGraph(const std::string& dir) {
  test::writeFile(dir + "/fold.json", test::graphJson(R"J({"id": "p", "type": "world_position"},
      {"id": "bump", "type": "expression",
       "options": {"inputs": {"p": "vec3"}, "formula": "vec3(1.5 * sin(p.x), 0.5 * cos(p.x), 0.0)"},
       "inputs": {"p": "p.out"}},
      {"id": "surface", "type": "vertex_output", "inputs": {"displacement": "bump.out"}})J",
                                                      R"J("vertex": {"position": "surface.position"},
      "fragment": {"color": [0, 0.2, 0.4]})J"));
  return dir + "/fold.json";
}

// A moderate sea (sum Q k A = 0.415), under the mixed graph's other displacements.
inline const char* kModerateWaves = R"J([
  {"direction": [1, 0.25], "steepness": 0.45, "wavelength": 14},
  {"direction": [0.6, 1], "steepness": 0.35, "wavelength": 8},
  {"direction": [-0.4, 1], "steepness": 0.3, "wavelength": 5, "phase": 0.4}])J";

// A graph whose displacement is Gerstner waves, an expression over the point, the time
// and a parameter, and a subgraph (swell.json, written beside it by writeMixedGraph), with
// parameters named like C keywords and macros.
inline std::string mixedGraphJson(const std::string& waves) {
  return R"J({"version": 1, "name": "mixed",
  "imports": {"swell": "swell.json"},
  "parameters": {
    "lift": {"type": "float", "default": 0.3, "min": 0, "max": 1},
    "int": {"type": "float", "default": 0.5, "min": 0.1, "max": 1},
    "int_": {"type": "vec2", "default": [0.2, -0.1]},
    "errno": {"type": "float", "default": 0.7},
    "linux": {"type": "float", "default": 1.5, "max": 3},
    "unix": {"type": "vec3", "default": [0, 0.1, 0.2], "min": 0, "max": 1, "hint": "color"}},
  "nodes": [
    {"id": "waves", "type": "gerstner_waves", "options": {"waves": )J" +
         waves + R"J(}},
    {"id": "p", "type": "world_position"},
    {"id": "t", "type": "time"},
    {"id": "bump", "type": "expression",
     "options": {"inputs": {"p": "vec3", "t": "float", "h": "float", "k": "float", "d": "vec2"},
                 "formula": "vec3(d.x * h * sin(0.7 * p.z + t), h * k * cos(0.5 * p.x - 1.3 * t), d.y * h)"},
     "inputs": {"p": "p.out", "t": "t.out", "h": "$lift", "k": "$int", "d": "$int_"}},
    {"id": "sw", "type": "swell", "inputs": {"position": "p.out", "speed": "$linux", "gain": "$errno"}},
    {"id": "sum", "type": "add", "inputs": {"a": "bump.out", "b": "sw.displacement"}},
    {"id": "surface", "type": "vertex_output",
     "inputs": {"position": "waves.position", "displacement": "sum.out", "normal": "waves.normal"}},
    {"id": "tint", "type": "mul", "inputs": {"a": "$unix", "b": 0.5}}
  ],
  "outputs": {"vertex": {"position": "surface.position", "normal": "surface.normal"},
              "fragment": {"color": "tint.out"}}})J";
}

inline const char* kSwellJson = R"J({"version": 1, "name": "swell",
  "interface": {"description": "a slow vertical swell over the point",
                "outputs": {"displacement": {"type": "vec3", "source": "d.out", "description": "the offset"}}},
  "parameters": {
    "position": {"type": "vec3", "default": [0, 0, 0], "description": "the point"},
    "speed": {"type": "float", "default": 1, "min": 0, "description": "rad/s"},
    "gain": {"type": "float", "default": 1, "description": "height"}},
  "nodes": [
    {"id": "t", "type": "time"},
    {"id": "d", "type": "expression",
     "options": {"inputs": {"p": "vec3", "s": "float", "g": "float", "t": "float"},
                 "formula": "vec3(0.0, 0.2 * g * smoothstep(-1.0, 1.0, sin(0.05 * (p.x + p.z) + s * t)) + 0.02 * length(p.xz * 0.01), 0.0)"},
     "inputs": {"p": "$position", "s": "$speed", "g": "$gain", "t": "t.out"}}
  ]})J";

// Writes mixed.json and swell.json into `dir`; returns mixed.json's path.
inline std::string writeMixedGraph(const std::string& dir, const std::string& waves = kModerateWaves) {
  writeFile(dir + "/swell.json", kSwellJson);
  writeFile(dir + "/mixed.json", mixedGraphJson(waves));
  return dir + "/mixed.json";
}

// The graph at `path` after the compiler's passes (what compile emits and queries from).
inline std::optional<Program> compileFile(const std::string& path, std::string* errors = nullptr) {
  Diagnostics diags;
  auto graph = loadGraphFile(path, diags);
  std::optional<Program> program;
  if (graph) program = buildProgram(*graph, defaultRegistry(), diags);
  if (errors)
    for (const auto& d : diags.sorted()) *errors += d.message + "\n";
  return program;
}

// The vertex stage in double: the ops the vertex position and normal outputs read (every
// input of each), evaluated by their node evals at the water point (x0, 0, z0), time t
// (codegen/water_surface_eval.h: the CPU backend, not the query's own extraction).
using VertexReference = WaterSurfacePoint;
inline VertexReference vertexReference(const Program& program, double x0, double z0, double t,
                                       const std::vector<Value>& parameters) {
  return waterSurfaceAt(program, parameters, x0, z0, t);
}

// A parameter value clamped as the runtime clamps an uploaded uniform (NaN to the lower end).
inline Value clampedTo(const ProgramParameter& p, Value v) {
  for (int i = 0; i < v.size(); ++i) {
    if (p.min && !(v[i] >= *p.min)) v[i] = *p.min;
    else if (!p.min && p.max && std::isnan(v[i])) v[i] = *p.max;
    if (p.max && *p.max < v[i]) v[i] = *p.max;
  }
  return v;
}

struct QueryPoint {
  double x0, z0, t;
};

// A double as a JavaScript literal that reads back to the same double.
inline std::string jsDouble(double x) {
  if (std::isnan(x)) return "NaN";
  if (std::isinf(x)) return x > 0 ? "Infinity" : "-Infinity";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

inline std::string cDouble(double x) {
  if (std::isnan(x)) return "NAN";
  if (std::isinf(x)) return x > 0 ? "HUGE_VAL" : "-HUGE_VAL";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

// One output line per point: position, normal, velocity (3 each), then the height at the
// displaced point's (x, z) (10 numbers). `setParameters` are C statements on `p`.
inline std::string queryDriverC(const std::string& header, const std::string& prefix, const std::vector<QueryPoint>& points,
                                const std::string& setParameters) {
  std::string c = "#include <errno.h>\n#include <math.h>\n#include <stdio.h>\n#include \"" + header + "\"\n";
  c += "static const double points[][3] = {\n";
  for (const auto& q : points) c += "  {" + cDouble(q.x0) + ", " + cDouble(q.z0) + ", " + cDouble(q.t) + "},\n";
  c += "};\nint main(void) {\n  " + prefix + "params p;\n  size_t i;\n  " + prefix + "params_default(&p);\n" + setParameters;
  c += "  for (i = 0; i < sizeof points / sizeof points[0]; ++i) {\n";
  c += "    double P[3], N[3], V[3], h;\n";
  c += "    " + prefix + "displace(&p, points[i][0], points[i][1], points[i][2], P, N, V);\n";
  c += "    h = " + prefix + "height(&p, P[0], P[2], points[i][2]);\n";
  c += "    printf(\"%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\\n\", P[0], P[1], P[2], N[0], N[1], N[2], "
       "V[0], V[1], V[2], h);\n  }\n  return 0;\n}\n";
  return c;
}

// The same for the ES module (run by node); `setParameters` are statements on `p`.
inline std::string queryDriverJs(const std::string& module, const std::string& prefix, const std::vector<QueryPoint>& points,
                                 const std::string& setParameters) {
  std::string js = "import * as q from './" + module + "';\nconst points = [\n";
  const auto num = jsDouble;
  for (const auto& pt : points) js += "  [" + num(pt.x0) + ", " + num(pt.z0) + ", " + num(pt.t) + "],\n";
  js += "];\nconst p = q." + prefix + "params_default();\n" + setParameters;
  js += "const lines = [];\nfor (const [x0, z0, t] of points) {\n";
  js += "  const P = [0, 0, 0], N = [0, 0, 0], V = [0, 0, 0];\n";
  js += "  q." + prefix + "displace(p, x0, z0, t, P, N, V);\n";
  js += "  const h = q." + prefix + "height(p, P[0], P[2], t);\n";
  js += "  lines.push([...P, ...N, ...V, h].map((v) => v.toPrecision(17)).join(' '));\n}\n";
  js += "console.log(lines.join('\\n'));\n";
  return js;
}

// Runs `command` and parses each line of its output into numbers.
inline std::vector<std::vector<double>> runNumbers(const std::string& command) {
  std::string out;
  int rc = runCommand(command, &out);
  EXPECT_EQ(rc, 0) << command << "\n" << out;
  std::vector<std::vector<double>> rows;
  if (rc != 0) return rows;
  for (const std::string& line : splitLines(out)) {
    std::vector<double> row;
    const char* s = line.c_str();
    char* end = nullptr;
    for (double v = std::strtod(s, &end); end != s; v = std::strtod(s, &end)) {
      row.push_back(v);
      s = end;
    }
    rows.push_back(row);
  }
  return rows;
}

// Builds `dir/main.c` with `compiler` and every warning an error, and runs it.
inline std::vector<std::vector<double>> compileAndRunC(const std::string& dir, const std::string& compiler) {
  std::string exe = dir + "/run_" + std::to_string(std::hash<std::string>{}(compiler));
  std::string out;
  int rc = runCommand(compiler + " -Wall -Wextra -Werror -O2 -o " + shellQuote(exe) + " " + shellQuote(dir + "/main.c") + " -lm", &out);
  EXPECT_EQ(rc, 0) << compiler << ":\n" << out;
  if (rc != 0) return {};
  return runNumbers(shellQuote(exe));
}

// The compilers each header is held to: C99 and C++ with GCC and Clang, GCC in its GNU
// dialects (which predefine `linux` and `unix`), Clang in strict ISO mode.
inline const std::vector<std::string>& cCompilers() {
  static const std::vector<std::string> c = {"gcc -std=gnu99", "g++ -x c++ -std=gnu++17", "clang -std=c99 -pedantic",
                                             "clang++ -x c++ -std=c++17 -pedantic"};
  return c;
}

}  // namespace wg::test
