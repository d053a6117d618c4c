// The surface-query C header (codegen/query_header.h): compiled as C99 and C++ by GCC and
// Clang with every warning an error, it answers what the vertex stage computes in double
// (the CPU backend's node evals) for Gerstner waves, expressions and a subgraph over the
// point, the time and parameters; its height inverts its displacement within the stated
// tolerance on a steep sea, near crests and at t = 1e6 s; bad input gives NaN, a parameter
// out of range is clamped as the runtime clamps it, and a displacement it cannot evaluate
// is refused naming the node.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "codegen/query_header.h"
#include "nodes/gerstner_waves.h"
#include "query_samples.h"

namespace wg {
namespace {

using test::QueryPoint;

// Points on and off the origin, over a day, at 1e4 m and at t = 1e6 s.
std::vector<QueryPoint> samplePoints() {
  std::vector<QueryPoint> v;
  for (double x0 : {-7.3, 0.0, 2.1, 5.9})
    for (double z0 : {-3.3, 1.7})
      for (double t : {0.0, 1.25, 37.5}) v.push_back({x0, z0, t});
  v.push_back({1e4 + 0.3, -2e4, 3.0});
  v.push_back({1.1, 2.2, 1e6});
  v.push_back({-4.4, 0.3, 1e6 + 0.25});
  v.push_back({123.456, -654.321, 86400.0});
  return v;
}

// Points on and around the crests of the first wave of kSteepWaves (direction (1, 0.2),
// wavelength 12, no phase): at t = 0 the crest is where D.x = 3, and there the horizontal
// map's Jacobian is nearly singular (1 - sum Q k A = 0.03).
std::vector<QueryPoint> crestPoints() {
  std::vector<QueryPoint> v;
  const double n = std::sqrt(1.0 + 0.04), dx = 1.0 / n, dz = 0.2 / n;
  for (double s : {2.8, 2.95, 3.0, 3.02, 3.1, 15.0, 27.0})
    for (double off : {0.0, 0.7}) v.push_back({s * dx - off * dz, s * dz + off * dx, 0.0});
  for (double s : {3.0, 15.0}) v.push_back({s * dx, s * dz, 1e6});  // the same phase places, a million seconds on
  return v;
}

struct QueryCompiled {
  std::string dir;
  Program program;
};

// `graphPath` compiled, its query header written into a fresh folder as g.query.h.
QueryCompiled compileQuery(const std::string& graphPath, const std::string& name) {
  QueryCompiled c;
  c.dir = test::makeTempDir("wg_query_c");
  std::string errors;
  auto result = test::compileFile(graphPath, &errors);
  EXPECT_TRUE(result) << errors;
  if (!result) return c;
  c.program = std::move(*result);
  Diagnostics diags;
  auto header = queryCHeader(name, c.program, diags);
  EXPECT_TRUE(header);
  if (header) test::writeFile(c.dir + "/g.query.h", *header);
  return c;
}

double norm3(const double* a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

// The reference's derivatives by central differences (for normals and velocities a graph's
// own outputs do not give): h = 1e-5 leaves ~1e-10 of truncation and ~1e-11 (1 + |P|) of
// rounding (and more at large t, see below).
struct Differences {
  double dx[3], dz[3], dt[3];
};
Differences differences(const Program& program, const QueryPoint& q, const std::vector<Value>& params) {
  const double h = 1e-5;
  Differences d;
  auto at = [&](double x0, double z0, double t) { return test::vertexReference(program, x0, z0, t, params); };
  auto px = at(q.x0 + h, q.z0, q.t), mx = at(q.x0 - h, q.z0, q.t);
  auto pz = at(q.x0, q.z0 + h, q.t), mz = at(q.x0, q.z0 - h, q.t);
  auto pt = at(q.x0, q.z0, q.t + h), mt = at(q.x0, q.z0, q.t - h);
  for (int i = 0; i < 3; ++i) {
    d.dx[i] = (px.position[i] - mx.position[i]) / (2 * h);
    d.dz[i] = (pz.position[i] - mz.position[i]) / (2 * h);
    d.dt[i] = (pt.position[i] - mt.position[i]) / (2 * h);
  }
  return d;
}

// Every compiler's answers against the reference: positions to 1e-12 (1 + |x0| + |z0|);
// normals to 1e-12 where the graph's own normal is the surface's (`normalIsExact`), else
// and velocities to the differences' accuracy; and the height at the displaced point to
// the stated tolerance.
void expectAgreement(const QueryCompiled& c, const std::vector<QueryPoint>& points, const std::vector<Value>& params,
                     const std::string& setParameters, bool normalIsExact, double heightBound) {
  test::writeFile(c.dir + "/main.c", test::queryDriverC("g.query.h", "wg_g_", points, setParameters));
  for (const std::string& compiler : test::cCompilers()) {
    auto rows = test::compileAndRunC(c.dir, compiler);
    ASSERT_EQ(rows.size(), points.size()) << compiler;
    for (size_t k = 0; k < points.size(); ++k) {
      const QueryPoint& q = points[k];
      ASSERT_EQ(rows[k].size(), 10u);
      const double* P = &rows[k][0];
      const double* N = &rows[k][3];
      const double* V = &rows[k][6];
      const double h = rows[k][9];
      auto ref = test::vertexReference(c.program, q.x0, q.z0, q.t, params);
      std::string where = compiler + " at (" + std::to_string(q.x0) + ", " + std::to_string(q.z0) + ", t " + std::to_string(q.t) + ")";
      const double scale = 1 + std::abs(q.x0) + std::abs(q.z0);
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(P[i], ref.position[i], 1e-12 * scale) << where << " position " << i;
      EXPECT_NEAR(norm3(N), 1.0, 1e-14) << where;
      Differences d = differences(c.program, q, params);
      double fd[3] = {d.dz[1] * d.dx[2] - d.dz[2] * d.dx[1], d.dz[2] * d.dx[0] - d.dz[0] * d.dx[2],
                      d.dz[0] * d.dx[1] - d.dz[1] * d.dx[0]};
      double l = norm3(fd);
      for (int i = 0; i < 3; ++i) {
        if (normalIsExact) EXPECT_NEAR(N[i], ref.normal[i], 1e-12) << where << " normal " << i;
        EXPECT_NEAR(N[i], fd[i] / l, 1e-6 * scale) << where << " normal " << i << " against differences";
        // At large t the differences' own rounding grows: the phase omega t is rounded to
        // ~1e-16 omega |t| in each evaluation, over 2 h.
        EXPECT_NEAR(V[i], d.dt[i], 1e-6 * scale + 1e-10 * std::abs(q.t)) << where << " velocity " << i;
      }
      EXPECT_NEAR(h, P[1], heightBound * (1 + std::abs(P[0]) + std::abs(P[2]))) << where << " height at the displaced point";
    }
  }
}

TEST(QueryHeader, OceanAgreesWithTheVertexStageInDouble) {
  QueryCompiled c = compileQuery(test::sourcePath("graphs/ocean.json"), "g");
  std::vector<Value> params;
  for (const auto& p : c.program.parameters) params.push_back(p.defaultValue);
  // ocean: the height is at a point within 1e-13 (1 + |x| + |z|) of the inverse in x and z;
  // over the slope sum k A = sum Q (1.35) and the inverse's conditioning 1 / (1 - sum Q k A),
  // sum Q k A = sum Q^2 = 0.4775.
  expectAgreement(c, samplePoints(), params, "", true, 1e-13 * 1.35 / (1 - 0.4775) + 1e-15);
  std::filesystem::remove_all(c.dir);
}

TEST(QueryHeader, SteepWavesAndTheirCrestsInvertWithinTheTolerance) {
  std::string dir = test::makeTempDir("wg_query_steep");
  test::writeFile(dir + "/steep.json", test::graphJson(R"J({"id": "waves", "type": "gerstner_waves", "options": {"waves": )J" +
                                                           std::string(test::kSteepWaves) + R"J(}},
      {"id": "surface", "type": "vertex_output", "inputs": {"position": "waves.position", "normal": "waves.normal"}})J",
                                                       R"J("vertex": {"position": "surface.position", "normal": "surface.normal"},
      "fragment": {"color": [0, 0.2, 0.4]})J"));
  QueryCompiled c = compileQuery(dir + "/steep.json", "g");
  std::vector<QueryPoint> points = samplePoints();
  for (const auto& q : crestPoints()) points.push_back(q);
  // sum k A = 1.17 of slope over 1 - sum Q k A = 0.031 of the inverse's conditioning.
  expectAgreement(c, points, {}, "", true, 1e-13 * 1.17 / (1 - test::kSteepSum) + 1e-15);
  std::filesystem::remove_all(c.dir);
  std::filesystem::remove_all(dir);
}

// Expressions, a subgraph, the time and parameters feed the displacement; parameters named
// int, int_, errno and linux compile; values out of range are clamped as the runtime does.
TEST(QueryHeader, ExpressionsSubgraphsAndClampedParameters) {
  std::string dir = test::makeTempDir("wg_query_mixed");
  QueryCompiled c = compileQuery(test::writeMixedGraph(dir), "g");
  const auto& ps = c.program.parameters;
  auto indexOf = [&](const std::string& name) {
    for (size_t i = 0; i < ps.size(); ++i)
      if (ps[i].name == name) return i;
    ADD_FAILURE() << "no parameter " << name;
    return size_t{0};
  };
  std::vector<Value> params;
  for (const auto& p : ps) params.push_back(p.defaultValue);
  // Out of range, NaN, and in range: the header clamps; the reference takes the clamped values.
  const std::string set =
      "  p.lift = 5.0;\n  p.zzint = NAN;\n  p.zzint_5f[0] = -0.3;\n  p.zzerrno = -1.25;\n  p.zzlinux = 100.0;\n";
  params[indexOf("lift")] = Value::scalar(5.0);
  params[indexOf("int")] = Value::scalar(NAN);
  params[indexOf("int_")] = Value::vector({-0.3, -0.1});
  params[indexOf("errno")] = Value::scalar(-1.25);
  params[indexOf("linux")] = Value::scalar(100.0);
  for (size_t i = 0; i < ps.size(); ++i) params[i] = test::clampedTo(ps[i], params[i]);
  EXPECT_EQ(params[indexOf("lift")][0], 1.0);
  EXPECT_EQ(params[indexOf("int")][0], 0.1);
  // Slopes: the waves' sum k A (1.1), the expression's and the swell's (0.05, 0.03); the
  // horizontal map stays invertible: the waves' sum Q k A (0.415) and the expression's
  // 0.7 * 0.3 * lift (0.21) leave it 1 - 0.625 from singular.
  expectAgreement(c, samplePoints(), params, set, false, 1e-13 * 1.2 / (1 - 0.415 - 0.21) + 1e-15);
  std::filesystem::remove_all(c.dir);
  std::filesystem::remove_all(dir);
}

// An expression folds the surface over (test::writeFoldGraph: x = x0 + 1.5 sin x0), so up
// to three water points reach one x and the residual of the inversion has minima that are
// no root. Every height must be the height
// 0.5 cos x0 of one of the sheets over x, found here by bisection in double, within the
// stated tolerance carried through the sheet's conditioning: 0.5 tol / |1 + 1.5 cos x0|.
TEST(QueryHeader, WhereTheSurfaceFoldsHeightAnswersOneOfItsSheets) {
  std::string dir = test::makeTempDir("wg_query_fold");
  QueryCompiled c = compileQuery(test::writeFoldGraph(dir), "g");
  const double z = 0.3;
  std::string main = "#include <stdio.h>\n#include \"g.query.h\"\nint main(void) {\n  wg_g_params p;\n  int i;\n"
                     "  wg_g_params_default(&p);\n  for (i = 0; i <= 2000; ++i)\n"
                     "    printf(\"%.17g\\n\", wg_g_height(&p, -10.0 + 0.01 * i, 0.3, 0.0));\n  return 0;\n}\n";
  test::writeFile(c.dir + "/main.c", main);
  auto rows = test::compileAndRunC(c.dir, "gcc -std=c99");
  ASSERT_EQ(rows.size(), 2001u);
  auto f = [](double x0, double x) { return x0 + 1.5 * std::sin(x0) - x; };
  int folded = 0;
  for (int i = 0; i <= 2000; ++i) {
    const double x = -10.0 + 0.01 * i, h = rows[static_cast<size_t>(i)].at(0);
    const double tolerance = kQueryHeightTolerance * (1 + std::abs(x) + z);
    std::vector<double> sheets;  // roots of f within the displacement's reach of x
    for (double a = x - 1.6; a < x + 1.6; a += 1e-3) {
      double lo = a, hi = a + 1e-3;
      if ((f(lo, x) < 0) == (f(hi, x) < 0)) continue;
      for (int k = 0; k < 100; ++k) {
        const double mid = 0.5 * (lo + hi);
        if ((f(lo, x) < 0) == (f(mid, x) < 0)) lo = mid;
        else hi = mid;
      }
      sheets.push_back(lo);
    }
    ASSERT_FALSE(sheets.empty()) << x;
    folded += sheets.size() > 1;
    bool onASheet = false;
    for (double x0 : sheets)
      onASheet |= std::abs(h - 0.5 * std::cos(x0)) <= 0.5 * tolerance / std::abs(1 + 1.5 * std::cos(x0)) + 1e-15;
    EXPECT_TRUE(onASheet) << "x " << x << ": height " << h << " is on none of the " << sheets.size() << " sheets";
  }
  EXPECT_GT(folded, 100) << "the points reach the folded region";
  std::filesystem::remove_all(c.dir);
  std::filesystem::remove_all(dir);
}

TEST(QueryHeader, NonFiniteInputGivesNaNWithoutHanging) {
  QueryCompiled c = compileQuery(test::sourcePath("graphs/ocean.json"), "g");
  const double inf = INFINITY;
  std::vector<QueryPoint> points = {{NAN, 0, 0}, {0, NAN, 0}, {0, 0, NAN}, {inf, 0, 0}, {0, -inf, 0}, {0, 0, inf}, {1e300, 2, 3}};
  test::writeFile(c.dir + "/main.c", test::queryDriverC("g.query.h", "wg_g_", points, ""));
  auto rows = test::compileAndRunC(c.dir, "gcc -std=c99");
  ASSERT_EQ(rows.size(), points.size());
  for (size_t k = 0; k + 1 < points.size(); ++k)
    for (double v : rows[k]) EXPECT_TRUE(std::isnan(v)) << "point " << k;
  // 1e300 is finite: mod reduces it to garbage phases but the answer is a number or NaN,
  // and the program returned (no hang).
  EXPECT_EQ(rows.back().size(), 10u);
  std::filesystem::remove_all(c.dir);
}

// The batched forms give exactly what one call per point gives, and take NULL outputs.
TEST(QueryHeader, BatchedFormsAnswerAsSingleCalls) {
  QueryCompiled c = compileQuery(test::sourcePath("graphs/ocean.json"), "g");
  test::writeFile(c.dir + "/main.c", R"C(#include <stdio.h>
#include "g.query.h"
int main(void) {
  double x[5] = {-3.5, 0.0, 2.25, 10.0, 1e4}, z[5] = {1.0, -7.5, 0.5, 3.0, -2e3};
  double P[15], N[15], V[15], h[5], p1[3], n1[3], v1[3];
  size_t i, k, bad = 0;
  wg_g_params p;
  wg_g_params_default(&p);
  wg_g_displace_batch(&p, 5, x, z, 12.5, P, N, V);
  wg_g_height_batch(&p, 5, x, z, 12.5, h);
  wg_g_displace_batch(&p, 5, x, z, 12.5, NULL, NULL, NULL);
  for (i = 0; i < 5; ++i) {
    wg_g_displace(&p, x[i], z[i], 12.5, p1, n1, v1);
    for (k = 0; k < 3; ++k) bad += P[3 * i + k] != p1[k] || N[3 * i + k] != n1[k] || V[3 * i + k] != v1[k];
    bad += h[i] != wg_g_height(&p, x[i], z[i], 12.5);
  }
  printf("%zu\n", bad);
  return 0;
}
)C");
  auto rows = test::compileAndRunC(c.dir, "gcc -std=c99");
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0], std::vector<double>{0.0});
  std::filesystem::remove_all(c.dir);
}

TEST(QueryHeader, GeneratedTwiceIsTheSameText) {
  auto result = test::compileFile(test::sourcePath("graphs/ocean.json"));
  ASSERT_TRUE(result);
  Diagnostics d1, d2;
  auto a = queryCHeader("ocean", *result, d1), b = queryCHeader("ocean", *result, d2);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(*a, *b);
  EXPECT_NE(a->find("static inline double wg_ocean_height(const wg_ocean_params* p, double x, double z, double t)"),
            std::string::npos);
  EXPECT_NE(a->find("#ifndef WG_ocean_QUERY_H"), std::string::npos);
}

// A graph whose displacement the query cannot evaluate: the camera, a wave's or an ocean's
// normal used as a displacement, two spectral oceans (a query keeps one ocean state). Each is WG044 at the node; the CLI writes nothing for it.
TEST(QueryHeader, AnUnqueryableDisplacementIsAnErrorNamingTheNode) {
  struct Case {
    std::string nodes, why;
  };
  const std::vector<Case> cases = {
      {R"J({"id": "cam", "type": "camera_position"},
          {"id": "off", "type": "mul", "inputs": {"a": "cam.out", "b": 0.01}},
          {"id": "surface", "type": "vertex_output", "inputs": {"displacement": "off.out"}})J",
       "node 'cam' (camera_position) feeds the vertex displacement, but a surface query cannot evaluate it"},
      {R"J({"id": "waves", "type": "gerstner_waves"},
          {"id": "surface", "type": "vertex_output", "inputs": {"displacement": "waves.normal"}})J",
       "the displacement reads its output 'normal'"},
      {R"J({"id": "sea", "type": "ocean_spectrum", "options": {"fft_size": 64, "tile_lengths": [50, 8]}},
          {"id": "d", "type": "ocean_displacement", "inputs": {"ocean": "sea.ocean"}},
          {"id": "surface", "type": "vertex_output", "inputs": {"displacement": "d.normal"}})J",
       "node 'd' (ocean_displacement) feeds the vertex displacement, but a surface query cannot evaluate it: the "
       "displacement reads its output 'normal'"},
      {R"J({"id": "sea", "type": "ocean_spectrum", "options": {"fft_size": 64, "tile_lengths": [50, 8]}},
          {"id": "swell", "type": "ocean_spectrum", "options": {"fft_size": 64, "tile_lengths": [300, 40], "seed": 7}},
          {"id": "d", "type": "ocean_displacement", "inputs": {"ocean": "sea.ocean"}},
          {"id": "e", "type": "ocean_displacement", "inputs": {"ocean": "swell.ocean", "position": "d.position"}},
          {"id": "surface", "type": "vertex_output", "inputs": {"position": "e.position"}})J",
       "a query keeps the state of one"},
  };
  for (const Case& k : cases) {
    std::string dir = test::makeTempDir("wg_query_refused");
    test::writeFile(dir + "/bad.json", test::graphJson(k.nodes, R"J("vertex": {"position": "surface.position"},
        "fragment": {"color": [0, 0.2, 0.4]})J"));
    auto result = test::compileFile(dir + "/bad.json");
    ASSERT_TRUE(result);
    Diagnostics diags;
    EXPECT_FALSE(queryCHeader("bad", *result, diags));
    ASSERT_FALSE(diags.all().empty());
    EXPECT_EQ(diags.all()[0].code, DiagCode::NotQueryable);
    EXPECT_NE(diags.all()[0].message.find(k.why), std::string::npos) << diags.all()[0].message;
    Diagnostics jsDiags;
    EXPECT_FALSE(queryJsModule("bad", *result, jsDiags));
    auto r = test::runWatergraph("compile " + test::shellQuote(dir + "/bad.json") + " -o " + test::shellQuote(dir + "/out") +
                                 " --target glsl330,query-c");
    EXPECT_EQ(r.exit, 1) << r.err;
    EXPECT_NE(r.err.find("bad.json:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("error: [WG044] node '"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(k.why), std::string::npos) << r.err;
    EXPECT_TRUE(test::listFiles(dir + "/out").empty()) << "nothing is written for a refused graph";
    std::filesystem::remove_all(dir);
  }
}

// deferred_underwater draws the trochoid wave found per pixel on a flat mesh: its query is
// refused at that node rather than answered flat.
TEST(QueryHeader, AFragmentStageSurfaceIsRefusedNotAnsweredFlat) {
  auto program = test::compileFile(test::sourcePath("graphs/deferred_underwater.json"));
  ASSERT_TRUE(program);
  Diagnostics diags;
  EXPECT_FALSE(queryCHeader("deferred_underwater", *program, diags));
  ASSERT_EQ(diags.all().size(), 1u);
  EXPECT_EQ(diags.all()[0].code, DiagCode::NotQueryable);
  EXPECT_NE(diags.all()[0].message.find("node 'wave' (trochoid_wave) draws a surface"), std::string::npos)
      << diags.all()[0].message;
}

}  // namespace
}  // namespace wg
