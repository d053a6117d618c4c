// The spectral ocean's surface query (codegen/query_ocean.h), C form: the header of
// graphs/open_ocean.json compiles as C99 and C++ with GCC and Clang under every warning; its
// state's h0 is the compiler's (core/ocean_fft_reference's initialCascade) bit for bit, for
// every spectrum model and spreading; its maps are the double reference's fields (FFTW)
// within the double transform's error bound at t = 0, 3.5 s and 1e6 s, and its velocity
// channels their time derivative; displace agrees with the CPU backend's evaluation of the
// vertex stage (ocean_displacement's eval: the same bicubic read and distance fade) and
// height inverts it within its stated tolerance.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "codegen/query_header.h"
#include "codegen/query_ocean.h"
#include "core/ocean_fft_reference.h"
#include "query_ocean_samples.h"

namespace wg {
namespace {

using test::OceanPoint;

struct OceanQuery {
  std::string dir;
  Program program;
  ocean::OceanSettings settings;
};

// `graphPath` compiled and its query header written into a fresh folder as g.query.h.
OceanQuery compileOceanQuery(const std::string& graphPath) {
  OceanQuery q;
  q.dir = test::makeTempDir("wg_query_ocean");
  std::string errors;
  auto program = test::compileFile(graphPath, &errors);
  EXPECT_TRUE(program) << errors;
  if (!program) return q;
  q.program = std::move(*program);
  for (const Op& op : q.program.ops)
    if (op.spec->type == "ocean_spectrum") q.settings = op.parsedOptions->as<ocean::OceanSettings>();
  Diagnostics diags;
  auto header = queryCHeader("g", q.program, diags);
  EXPECT_TRUE(header);
  if (header) test::writeFile(q.dir + "/g.query.h", *header);
  return q;
}

std::vector<double> readDoubles(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<double> v(bytes.size() / sizeof(double));
  std::memcpy(v.data(), bytes.data(), v.size() * sizeof(double));
  return v;
}

// Runs the driver built by `compiler` in the query's folder (it writes its .bin files there).
std::vector<std::vector<double>> runDriver(const OceanQuery& q, const std::string& compiler,
                                           const std::vector<OceanPoint>& points, const std::vector<double>& times,
                                           const double camera[3], bool dump) {
  test::writeFile(q.dir + "/main.c", test::oceanDriverC("g.query.h", "wg_g_", points, times, camera, dump));
  std::string exe = q.dir + "/run";
  std::string out;
  int rc = test::runCommand(compiler + " -Wall -Wextra -Werror -O2 -o " + test::shellQuote(exe) + " " +
                                test::shellQuote(q.dir + "/main.c") + " -lm",
                            &out);
  EXPECT_EQ(rc, 0) << compiler << ":\n" << out;
  if (rc != 0) return {};
  return test::runNumbers("cd " + test::shellQuote(q.dir) + " && ./run");
}

// Where each cascade's texels begin in the state's flat arrays (one cascade's N_c^2 after
// another's), and their total last.
std::vector<size_t> firstTexels(const ocean::OceanSettings& s) {
  std::vector<size_t> first = {0};
  for (size_t c = 0; c < s.cascades.tileLengths.size(); ++c) {
    const size_t n = static_cast<size_t>(ocean::cascadeResolution(s.cascades, c));
    first.push_back(first.back() + n * n);
  }
  return first;
}

// Every bin's h0 of every cascade, as the query's state holds it (re, im per bin).
void expectSameH0(const OceanQuery& q, const std::string& what) {
  std::vector<double> h0 = readDoubles(q.dir + "/h0.bin");
  const std::vector<size_t> first = firstTexels(q.settings);
  ASSERT_EQ(h0.size(), first.back() * 2) << what;
  size_t differing = 0, waves = 0;
  for (size_t c = 0; c < q.settings.cascades.tileLengths.size(); ++c) {
    ocean::OceanCascade ref = ocean::initialCascade(q.settings.spectrum, q.settings.cascades, static_cast<int>(c));
    const size_t n2 = first[c + 1] - first[c];
    ASSERT_EQ(ref.h0.size(), n2) << what << " cascade " << c;
    for (size_t i = 0; i < n2; ++i) {
      const double re = h0[(first[c] + i) * 2], im = h0[(first[c] + i) * 2 + 1];
      waves += ref.h0[i] != std::complex<double>(0.0, 0.0);
      if (re != ref.h0[i].real() || im != ref.h0[i].imag()) {
        if (differing++ < 5)
          ADD_FAILURE() << what << " cascade " << c << " bin " << i << ": query (" << re << ", " << im << "), compiler "
                        << ref.h0[i];
      }
    }
  }
  EXPECT_EQ(differing, 0u) << what;
  EXPECT_GT(waves, first[1] / 8) << what << ": a sea with waves";
}

TEST(QueryOcean, OpenOceansHeaderCompilesEverywhereAndItsH0IsTheCompilers) {
  OceanQuery q = compileOceanQuery(test::sourcePath("graphs/open_ocean.json"));
  ASSERT_EQ(q.settings.cascades.tileLengths.size(), 3u);
  const double camera[3] = {0, 10, 0};
  for (const std::string& compiler : test::cCompilers()) {
    auto rows = runDriver(q, compiler, {{1.5, -2.25}}, {0.0}, camera, true);
    ASSERT_EQ(rows.size(), 1u) << compiler;
    expectSameH0(q, "open_ocean with " + compiler);
  }
  std::filesystem::remove_all(q.dir);
}

// Small seas (64^2, two cascades) of every spectrum model, spreading and a swell.
TEST(QueryOcean, EverySpectrumsH0IsTheCompilers) {
  const char* seas[] = {
      R"("model": "phillips", "spreading": "cos2", "phillips_small_wave": 0.1)",
      R"("model": "pierson_moskowitz", "spreading": "mitsuyasu", "wind_direction": -130)",
      R"("model": "tma", "depth": 4, "swell_height": 1.5, "swell_period": 12, "swell_direction": 75, "swell_spread": 40)",
      R"("model": "jonswap", "fetch": 3, "wind_speed": 25, "seed": 4000000000)",
      // a resolution per cascade: each cascade's N^2 bins after the previous one's
      R"("cascade_sizes": [16, 32], "wind_speed": 12)"};
  for (const char* options : seas) {
    std::string dir = test::makeTempDir("wg_query_ocean_seas");
    test::writeFile(dir + "/sea.json", test::graphJson(R"({"id": "sea", "type": "ocean_spectrum",
        "options": {"fft_size": 64, "tile_lengths": [60, 9], )" + std::string(options) + R"(}},
      {"id": "d", "type": "ocean_displacement", "inputs": {"ocean": "sea.ocean"}},
      {"id": "surface", "type": "vertex_output", "inputs": {"position": "d.position", "normal": "d.normal"}})",
                                                       R"("vertex": {"position": "surface.position", "normal": "surface.normal"},
      "fragment": {"color": [0, 0.2, 0.4]})"));
    OceanQuery q = compileOceanQuery(dir + "/sea.json");
    const double camera[3] = {0, 10, 0};
    auto rows = runDriver(q, "gcc -std=c99", {{0.5, 0.5}}, {0.0}, camera, true);
    ASSERT_EQ(rows.size(), 1u) << options;
    expectSameH0(q, options);
    std::filesystem::remove_all(q.dir);
    std::filesystem::remove_all(dir);
  }
}

double norm2(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x * x;
  return std::sqrt(s);
}

// The query's 11 channels against the reference's fields (lambda where the GPU's maps carry
// it): each within the bound of its packed transform (the pair's joint norm) plus FFTW's own;
// the velocity channels against central differences of the reference over h = 2^-12 s (a
// whole number of the loop's 2^-16 s steps), within the difference's truncation h^2 / 6 times
// the sum over bins of omega^3 |h0| (both terms of each bin), plus rounding.
TEST(QueryOcean, MapsAreTheDoubleReferencesFieldsWithinTheTransformsBound) {
  OceanQuery q = compileOceanQuery(test::sourcePath("graphs/open_ocean.json"));
  const std::vector<double> times = {0.0, 3.5, 1e6};
  const double camera[3] = {0, 10, 0};
  auto rows = runDriver(q, "gcc -std=c99", {{0.0, 0.0}}, times, camera, true);
  ASSERT_EQ(rows.size(), times.size());
  const std::vector<size_t> first = firstTexels(q.settings);
  const double lambda = q.settings.cascades.choppiness;
  const double h = std::ldexp(1.0, -12);
  for (size_t k = 0; k < times.size(); ++k) {
    std::vector<double> maps = readDoubles(q.dir + "/maps" + std::to_string(k) + ".bin");
    ASSERT_EQ(maps.size(), first.back() * kQueryOceanChannels);
    for (size_t c = 0; c < q.settings.cascades.tileLengths.size(); ++c) {
      const int n = ocean::cascadeResolution(q.settings.cascades, c);
      const size_t n2 = static_cast<size_t>(n) * n;
      const double bound = test::doubleTransformBound(n);
      ocean::OceanCascade cascade = ocean::initialCascade(q.settings.spectrum, q.settings.cascades, static_cast<int>(c));
      ocean::OceanFields f = ocean::oceanFields(cascade, times[k], lambda);
      ocean::OceanFields before = ocean::oceanFields(cascade, times[k] - h, lambda);
      ocean::OceanFields after = ocean::oceanFields(cascade, times[k] + h, lambda);
      // Per channel: the field, its scale, and the field packed with it in one transform.
      const std::vector<double>* fields[8] = {&f.displacementX, &f.height, &f.displacementZ, &f.dDxdz,
                                              &f.slopeX,        &f.slopeZ, &f.dDxdx,         &f.dDzdz};
      const double scale[8] = {lambda, 1, lambda, lambda, 1, 1, lambda, lambda};
      const int partner[8] = {1, 0, 3, 2, 5, 4, 7, 6};
      for (int ch = 0; ch < 8; ++ch) {
        const double a = norm2(*fields[ch]), b = norm2(*fields[partner[ch]]);
        const double allowed = scale[ch] * bound * (std::sqrt(a * a + b * b) + a);
        double worst = 0;
        for (size_t i = 0; i < n2; ++i)
          worst = std::max(worst, std::abs(maps[(first[c] + i) * kQueryOceanChannels + ch] - scale[ch] * (*fields[ch])[i]));
        EXPECT_LE(worst, allowed) << "t " << times[k] << " cascade " << c << " channel " << ch;
        EXPECT_GT(a, 0.0);
      }
      // Velocity: d/dt of lambda Dx, h, lambda Dz.
      double omega3 = 0;
      for (size_t i = 0; i < n2; ++i) {
        const size_t iz = i / n, ix = i % n, m = ((n - iz) % n) * n + (n - ix) % n;
        const double w = ocean::angularFrequencyOf(cascade.frequency[i]);
        omega3 += w * w * w * (std::abs(cascade.h0[i]) + std::abs(cascade.h0[m]));
      }
      const std::vector<double>* at[3][2] = {{&before.displacementX, &after.displacementX},
                                            {&before.height, &after.height},
                                            {&before.displacementZ, &after.displacementZ}};
      for (int v = 0; v < 3; ++v) {
        const double s = v == 1 ? 1.0 : lambda;
        const double allowed = s * (h * h / 6 * omega3 + 4 * bound * norm2(f.height) / h);
        double worst = 0, largest = 0;
        for (size_t i = 0; i < n2; ++i) {
          const double difference = s * ((*at[v][1])[i] - (*at[v][0])[i]) / (2 * h);
          worst = std::max(worst, std::abs(maps[(first[c] + i) * kQueryOceanChannels + 8 + v] - difference));
          largest = std::max(largest, std::abs(difference));
        }
        EXPECT_LE(worst, allowed) << "t " << times[k] << " cascade " << c << " velocity " << v;
        EXPECT_LT(allowed, 0.05 * largest) << "the velocity check must be able to fail";
      }
    }
  }
  std::filesystem::remove_all(q.dir);
}

// Points near the camera (every cascade), beyond the finest cascade's fade (12 tiles of 5 m:
// 60 to 120 m), beyond the middle one's (288 to 576 m), on tile edges and far away.
std::vector<OceanPoint> oceanPoints() {
  std::vector<OceanPoint> v;
  for (double x0 : {-7.3, 0.0, 2.1, 5.0, 24.0})
    for (double z0 : {-3.3, 1.7, 120.0}) v.push_back({x0, z0});
  for (double r : {59.0, 75.0, 90.0, 130.0, 300.0, 450.0, 700.0}) v.push_back({r * 0.8, r * 0.6});
  v.push_back({1e4 + 0.3, -2e4});
  return v;
}

// displace against the CPU backend's node evals of the vertex stage (ocean_displacement's
// eval reads the FFTW fields bicubic, with the fade from the environment's camera, which
// the query's state is given): per cascade the maps' transform bound over the fields' norms.
// height at the displaced point answers its y within the stated tolerance.
TEST(QueryOcean, DisplaceIsTheVertexStageInDoubleAndHeightInvertsIt) {
  OceanQuery q = compileOceanQuery(test::sourcePath("graphs/open_ocean.json"));
  const std::vector<double> times = {0.0, 3.5, 1e6};
  EvalEnvironment env;
  const double camera[3] = {env.cameraPosition[0], env.cameraPosition[1], env.cameraPosition[2]};
  const std::vector<OceanPoint> points = oceanPoints();
  auto rows = runDriver(q, "gcc -std=c99", points, times, camera, false);
  ASSERT_EQ(rows.size(), times.size() * points.size());
  std::vector<Value> params;
  for (const auto& p : q.program.parameters) params.push_back(p.defaultValue);
  double allowed = 0;  // the sum of the cascades' bounds, at full weight
  for (size_t c = 0; c < q.settings.cascades.tileLengths.size(); ++c) {
    ocean::OceanFields f = ocean::oceanFields(
        ocean::initialCascade(q.settings.spectrum, q.settings.cascades, static_cast<int>(c)), 0.0, 1.0);
    const double norms = norm2(f.height) + norm2(f.displacementX) + norm2(f.displacementZ);
    allowed += 2 * (1 + q.settings.cascades.choppiness) *
               test::doubleTransformBound(ocean::cascadeResolution(q.settings.cascades, c)) * norms;
  }
  double worstHeight = 0;
  for (size_t k = 0; k < times.size(); ++k)
    for (size_t i = 0; i < points.size(); ++i) {
      const auto& row = rows[k * points.size() + i];
      ASSERT_EQ(row.size(), 10u);
      auto ref = test::vertexReference(q.program, points[i].x0, points[i].z0, times[k], params);
      const std::string where = "t " + std::to_string(times[k]) + " at (" + std::to_string(points[i].x0) + ", " +
                                std::to_string(points[i].z0) + ")";
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(row[static_cast<size_t>(j)], ref.position[j], allowed) << where << " " << j;
      // The query's normal is the shader's (from the slope maps), oriented up.
      const double up = ref.normal[1] < 0 ? -1.0 : 1.0;
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(row[3 + static_cast<size_t>(j)], up * ref.normal[j], 1e-9) << where;
      const double tolerance = kQueryOceanHeightTolerance * (1 + std::abs(row[0]) + std::abs(row[2]));
      worstHeight = std::max(worstHeight, std::abs(row[9] - row[1]) / tolerance);
      EXPECT_NEAR(row[9], row[1], tolerance) << where << " height at the displaced point";
    }
  std::printf("open_ocean: worst |height(displace(x0).xz) - displace(x0).y| %.3g of the stated tolerance\n", worstHeight);
  std::filesystem::remove_all(q.dir);
}

// The height where the readers' camera is given as NULL: every cascade at full weight, so a
// point far from the origin still carries the finest waves (they are faded out with a camera).
TEST(QueryOcean, WithoutACameraEveryCascadeKeepsItsFullWeight) {
  OceanQuery q = compileOceanQuery(test::sourcePath("graphs/open_ocean.json"));
  std::string c = test::oceanDriverC("g.query.h", "wg_g_", {{700.0, 300.0}}, {2.0}, std::array<double, 3>{0, 10, 0}.data(), false);
  // The same driver twice: with the camera, and with the camera replaced by NULL.
  test::writeFile(q.dir + "/main.c", c);
  auto faded = test::compileAndRunC(q.dir, "gcc -std=c99");
  const std::string call = "wg_g_ocean_update(&o, times[k], camera);";
  c.replace(c.find(call), call.size(), "wg_g_ocean_update(&o, times[k], NULL); (void)camera;");
  test::writeFile(q.dir + "/main.c", c);
  auto full = test::compileAndRunC(q.dir, "gcc -std=c99");
  ASSERT_EQ(faded.size(), 1u);
  ASSERT_EQ(full.size(), 1u);
  // The fine cascades' waves are centimetres high: they move the point, but by less than a metre.
  EXPECT_GT(std::abs(full[0][1] - faded[0][1]), 1e-4);
  EXPECT_LT(std::abs(full[0][1] - faded[0][1]), 1.0);
  std::filesystem::remove_all(q.dir);
}

}  // namespace
}  // namespace wg
