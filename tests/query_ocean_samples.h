#pragma once
// Shared by the spectral ocean's surface-query tests (tests/codegen/query_ocean_test.cpp,
// tests/ecosystem/query_js_test.cpp, tests/runtime/query_gpu_test.cpp): drivers that bring a
// generated header's or module's ocean state to each time and print what displace and height
// answer there, and the double transform's error bound.
#include <cmath>
#include <string>
#include <vector>

#include "query_samples.h"

namespace wg::test {

// Points of still water (x0, z0); each time's rows are printed in this order.
struct OceanPoint {
  double x0, z0;
};

// The C driver: init, then per time update(t, camera) and one line per point: position,
// normal, velocity, then the height at the displaced point's (x, z) (10 numbers). With
// `dumpMaps`, it also writes h0.bin (the state's h0) and maps<k>.bin (the maps at time k).
inline std::string oceanDriverC(const std::string& header, const std::string& prefix, const std::vector<OceanPoint>& points,
                                const std::vector<double>& times, const double camera[3], bool dumpMaps) {
  std::string c = "#include <math.h>\n#include <stdio.h>\n#include \"" + header + "\"\n";
  c += "static const double points[][2] = {\n";
  for (const auto& q : points) c += "  {" + cDouble(q.x0) + ", " + cDouble(q.z0) + "},\n";
  c += "};\nstatic const double times[] = {";
  for (double t : times) c += cDouble(t) + ", ";
  c += "};\nstatic " + prefix + "ocean o; /* static storage: megabytes */\n";
  c += "int main(void) {\n  " + prefix + "params p;\n  size_t i, k;\n";
  c += "  const double camera[3] = {" + cDouble(camera[0]) + ", " + cDouble(camera[1]) + ", " + cDouble(camera[2]) + "};\n";
  c += "  " + prefix + "params_default(&p);\n  " + prefix + "ocean_init(&o);\n";
  if (dumpMaps) c += "  {\n    FILE* f = fopen(\"h0.bin\", \"wb\");\n    fwrite(o.h0, sizeof o.h0, 1, f);\n    fclose(f);\n  }\n";
  c += "  for (k = 0; k < sizeof times / sizeof times[0]; ++k) {\n";
  c += "    " + prefix + "ocean_update(&o, times[k], camera);\n";
  if (dumpMaps) {
    c += "    {\n      char name[32];\n      FILE* f;\n      snprintf(name, sizeof name, \"maps%u.bin\", (unsigned)k);\n";
    c += "      f = fopen(name, \"wb\");\n      fwrite(o.maps, sizeof o.maps, 1, f);\n      fclose(f);\n    }\n";
  }
  c += "    for (i = 0; i < sizeof points / sizeof points[0]; ++i) {\n";
  c += "      double P[3], N[3], V[3], h;\n";
  c += "      " + prefix + "displace(&p, &o, points[i][0], points[i][1], P, N, V);\n";
  c += "      h = " + prefix + "height(&p, &o, P[0], P[2]);\n";
  c += "      printf(\"%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\\n\", P[0], P[1], P[2], N[0], N[1], "
       "N[2], V[0], V[1], V[2], h);\n    }\n  }\n  return 0;\n}\n";
  return c;
}

// The same for the ES module (run by node).
inline std::string oceanDriverJs(const std::string& module, const std::string& prefix, const std::vector<OceanPoint>& points,
                                 const std::vector<double>& times, const double camera[3]) {
  const auto num = jsDouble;
  std::string js = "import * as q from './" + module + "';\nconst points = [\n";
  for (const auto& pt : points) js += "  [" + num(pt.x0) + ", " + num(pt.z0) + "],\n";
  js += "];\nconst times = [";
  for (double t : times) js += num(t) + ", ";
  js += "];\nconst camera = [" + num(camera[0]) + ", " + num(camera[1]) + ", " + num(camera[2]) + "];\n";
  js += "const p = q." + prefix + "params_default();\nconst o = q." + prefix + "ocean_init();\nconst lines = [];\n";
  js += "for (const t of times) {\n  q." + prefix + "ocean_update(o, t, camera);\n";
  js += "  for (const [x0, z0] of points) {\n";
  js += "    const P = [0, 0, 0], N = [0, 0, 0], V = [0, 0, 0];\n";
  js += "    q." + prefix + "displace(p, o, x0, z0, P, N, V);\n";
  js += "    const h = q." + prefix + "height(p, o, P[0], P[2]);\n";
  js += "    lines.push([...P, ...N, ...V, h].map((v) => v.toPrecision(17)).join(' '));\n  }\n}\n";
  js += "console.log(lines.join('\\n'));\n";
  return js;
}

// The relative error bound of a radix-2 FFT of length n x n in double (Higham, Accuracy and
// Stability of Numerical Algorithms, 2nd ed., thm. 24.2; tests/runtime/ocean_transform_bound.h
// has its float32 form): ||y^ - y||_2 <= (log2 n) eta / (1 - (log2 n) eta) ||y||_2 with
// log2 n = 2 log2 N for the 2-D transform, eta = mu + gamma_4 (sqrt 2 + mu), twiddles
// accurate to mu = u; the evolution and the wavenumber factors add 16 u.
inline double doubleTransformBound(int resolution) {
  const double u = std::ldexp(1.0, -53);
  const double stages = 2 * std::log2(resolution);
  const double gamma4 = 4 * u / (1 - 4 * u);
  const double eta = u + gamma4 * (std::sqrt(2.0) + u);
  return stages * eta / (1 - stages * eta) + 16 * u;
}

}  // namespace wg::test
