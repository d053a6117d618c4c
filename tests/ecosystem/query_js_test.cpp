// The surface query's JavaScript module (`compile --target query-js`) against its C header
// (`--target query-c`): the same points, run under node and as a compiled C program, agree
// to 1e-12 in every output (position, normal, velocity, the height at the displaced point)
// for the ocean, a steep sea, a graph of expressions, a subgraph and parameters set out of
// range, and a surface an expression folds over; non-finite input is NaN in both.
#include <gtest/gtest.h>

#include <filesystem>

#include "codegen/query_header.h"
#include "query_ocean_samples.h"
#include "query_samples.h"

namespace wg {
namespace {

using test::QueryPoint;

std::vector<QueryPoint> points() {
  std::vector<QueryPoint> v;
  for (double x0 : {-9.5, -0.25, 3.0, 11.75})
    for (double z0 : {-4.0, 0.5, 6.25})
      for (double t : {0.0, 2.5, 1e6}) v.push_back({x0, z0, t});
  v.push_back({2.5e4, -1.5e4, 60.0});
  v.push_back({NAN, 1, 2});
  v.push_back({1, 2, INFINITY});
  return v;
}

void expectSameAnswers(const std::string& graphPath, const std::string& setC, const std::string& setJs,
                       const std::vector<QueryPoint>& at = points()) {
  std::string dir = test::makeTempDir("wg_query_js");
  std::string errors;
  auto program = test::compileFile(graphPath, &errors);
  ASSERT_TRUE(program) << errors;
  Diagnostics diags;
  auto header = queryCHeader("g", *program, diags);
  auto module = queryJsModule("g", *program, diags);
  ASSERT_TRUE(header && module);
  test::writeFile(dir + "/g.query.h", *header);
  test::writeFile(dir + "/g.query.js", *module);
  test::writeFile(dir + "/package.json", "{\"type\": \"module\"}\n");
  test::writeFile(dir + "/main.c", test::queryDriverC("g.query.h", "wg_g_", at, setC));
  test::writeFile(dir + "/main.js", test::queryDriverJs("g.query.js", "wg_g_", at, setJs));
  auto c = test::compileAndRunC(dir, "gcc -std=c99");
  auto js = test::runNumbers("cd " + test::shellQuote(dir) + " && timeout 60 node main.js");
  ASSERT_EQ(c.size(), at.size());
  ASSERT_EQ(js.size(), c.size());
  size_t compared = 0;
  for (size_t k = 0; k < c.size(); ++k) {
    ASSERT_EQ(js[k].size(), c[k].size()) << "point " << k;
    for (size_t i = 0; i < c[k].size(); ++i, ++compared) {
      if (std::isnan(c[k][i])) {
        EXPECT_TRUE(std::isnan(js[k][i])) << "point " << k << " output " << i;
        continue;
      }
      EXPECT_NEAR(js[k][i], c[k][i], 1e-12 * (1 + std::abs(c[k][i]))) << graphPath << " point " << k << " output " << i;
    }
  }
  EXPECT_GT(compared, 300u);
  std::filesystem::remove_all(dir);
}

TEST(QueryJs, OceanAgreesWithTheCHeader) { expectSameAnswers(test::sourcePath("graphs/ocean.json"), "", ""); }

TEST(QueryJs, SteepSeaAgreesWithTheCHeader) {
  std::string dir = test::makeTempDir("wg_query_js_steep");
  expectSameAnswers(test::writeSteepGraph(dir), "", "");
  std::filesystem::remove_all(dir);
}

TEST(QueryJs, ExpressionsSubgraphsAndParametersAgreeWithTheCHeader) {
  std::string dir = test::makeTempDir("wg_query_js_mixed");
  std::string path = test::writeMixedGraph(dir);
  expectSameAnswers(path, "  p.lift = 5.0;\n  p.zzint = NAN;\n  p.zzint_5f[0] = -0.3;\n  p.zzlinux = 100.0;\n",
                    "p.lift = 5.0;\np.zzint = NaN;\np.zzint_5f[0] = -0.3;\np.zzlinux = 100.0;\n");
  std::filesystem::remove_all(dir);
}

// height() where the surface folds starts again from the same points in both languages:
// 801 water points 0.025 m apart, the heights at their displaced x, 94 of which start again
// at least once (a module that never started again answers 46 of them differently).
TEST(QueryJs, AFoldedSurfaceAgreesWithTheCHeader) {
  std::string dir = test::makeTempDir("wg_query_js_fold");
  std::vector<QueryPoint> at;
  for (int i = 0; i <= 800; ++i) at.push_back({-10.0 + 0.025 * i, 0.3, 0.0});
  expectSameAnswers(test::writeFoldGraph(dir), "", "", at);
  std::filesystem::remove_all(dir);
}

// The spectral ocean (graphs/open_ocean.json, three cascades of 256^2): the module's state,
// recomputed from the same spectrum and seed with its own transform, answers as the header's
// at t = 0, 3.5 s and 1e6 s, near the camera, in the cascades' fades and far out.
TEST(QueryJs, SpectralOceanAgreesWithTheCHeader) {
  std::string dir = test::makeTempDir("wg_query_js_ocean");
  auto program = test::compileFile(test::sourcePath("graphs/open_ocean.json"));
  ASSERT_TRUE(program);
  Diagnostics diags;
  auto header = queryCHeader("g", *program, diags);
  auto module = queryJsModule("g", *program, diags);
  ASSERT_TRUE(header && module);
  std::vector<test::OceanPoint> at;
  for (double x0 : {-9.5, -0.25, 3.0, 11.75})
    for (double z0 : {-4.0, 0.5, 6.25}) at.push_back({x0, z0});
  for (double r : {70.0, 100.0, 400.0, 2.5e4}) at.push_back({0.6 * r, -0.8 * r});
  const std::vector<double> times = {0.0, 3.5, 1e6};
  const double camera[3] = {1.0, 8.0, -2.0};
  test::writeFile(dir + "/g.query.h", *header);
  test::writeFile(dir + "/g.query.js", *module);
  test::writeFile(dir + "/package.json", "{\"type\": \"module\"}\n");
  test::writeFile(dir + "/main.c", test::oceanDriverC("g.query.h", "wg_g_", at, times, camera, false));
  test::writeFile(dir + "/main.js", test::oceanDriverJs("g.query.js", "wg_g_", at, times, camera));
  auto c = test::compileAndRunC(dir, "gcc -std=c99");
  auto js = test::runNumbers("cd " + test::shellQuote(dir) + " && timeout 120 node main.js");
  ASSERT_EQ(c.size(), at.size() * times.size());
  ASSERT_EQ(js.size(), c.size());
  for (size_t k = 0; k < c.size(); ++k) {
    ASSERT_EQ(js[k].size(), c[k].size());
    for (size_t i = 0; i < c[k].size(); ++i)
      EXPECT_NEAR(js[k][i], c[k][i], 1e-12 * (1 + std::abs(c[k][i]))) << "row " << k << " output " << i;
  }
  std::filesystem::remove_all(dir);
}

// The module's batched forms give exactly what one call per point gives.
TEST(QueryJs, BatchedFormsAnswerAsSingleCalls) {
  std::string dir = test::makeTempDir("wg_query_js_batch");
  auto program = test::compileFile(test::sourcePath("graphs/ocean.json"));
  ASSERT_TRUE(program);
  Diagnostics diags;
  auto module = queryJsModule("g", *program, diags);
  ASSERT_TRUE(module);
  test::writeFile(dir + "/g.query.js", *module);
  test::writeFile(dir + "/package.json", "{\"type\": \"module\"}\n");
  test::writeFile(dir + "/main.js", R"JS(import * as q from './g.query.js';
const p = q.wg_g_params_default();
const x = [-3.5, 0, 2.25, 10, 1e4], z = [1, -7.5, 0.5, 3, -2e3];
const P = new Float64Array(15), N = new Float64Array(15), V = new Float64Array(15), h = new Float64Array(5);
q.wg_g_displace_batch(p, 5, x, z, 12.5, P, N, V);
q.wg_g_height_batch(p, 5, x, z, 12.5, h);
q.wg_g_displace_batch(p, 5, x, z, 12.5, null, null, null);
let bad = 0;
for (let i = 0; i < 5; ++i) {
  const p1 = [0, 0, 0], n1 = [0, 0, 0], v1 = [0, 0, 0];
  q.wg_g_displace(p, x[i], z[i], 12.5, p1, n1, v1);
  for (let k = 0; k < 3; ++k) bad += P[3 * i + k] !== p1[k] || N[3 * i + k] !== n1[k] || V[3 * i + k] !== v1[k];
  bad += h[i] !== q.wg_g_height(p, x[i], z[i], 12.5);
}
console.log(bad);
)JS");
  auto rows = test::runNumbers("cd " + test::shellQuote(dir) + " && timeout 60 node main.js");
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0], std::vector<double>{0.0});
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace wg
