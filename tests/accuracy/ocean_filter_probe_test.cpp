// ocean_surface's filtered reader (nodes/glsl/ocean_displacement.glsl wg_ocean_footprint,
// wg_ocean_lod, wg_ocean_map_lod) on the GPU against its double reference
// (nodes/ocean_readers.cpp sumFiltered), through node probes whose maps the runtimes
// simulate: footprints from below a texel to past the whole tile, on every level of both
// cascades, exactly on level boundaries (integral levels of detail, where the trilinear
// blend hands one level to the next) and between them, at t = 3.7 s and t = 1e6 s, on
// glsl330 (GL 4.5), es300 (ES 3.2) and vk450 (lavapipe, under validation). Each output
// (normal, slopes, Jacobian, roughness) within the node's bound, no NaN/Inf.
#include <bit>
#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "accuracy/gpu_executor.h"
#include "accuracy/hard_case_suite.h"
#include "accuracy/node_probe.h"
#include "nodes/ocean_readers.h"
#include "nodes/registry.h"
#include "runtime/egl_context.h"

namespace wg::accuracy {
// Named, not anonymous: the unity build joins this file with the other tests.
namespace ocean_filter_probe_test {

// The readers' small sea: 64^2 texels over 50 m and 8 m (1.28 and 8 texels per metre).
nlohmann::json filterSea() { return nodes::oceanread::smallSea({{"wind_speed", 12}}); }

struct FootprintCase {
  double footprint;  // metres, looking straight down from above the point
  double time;
};

// Footprints F = 2^l / 8 m are exactly 2^l texels of the 8 m cascade (level l, a boundary),
// and the long cascade's levels fall between its own boundaries; 3 / 16 m and 3 m lie
// between levels; 0.05 m is below a texel; 400 m spans both tiles (the 1 x 1 means).
std::vector<FootprintCase> footprintCases() {
  std::vector<FootprintCase> out;
  for (double t : {3.7, 1e6})
    for (double f : {0.05, 0.125, 0.1875, 0.25, 0.5, 1.0, 2.0, 3.0, 4.0, 8.0, 400.0}) out.push_back({f, t});
  return out;
}

ProbeCaseFile footprintSuite() {
  ProbeCaseFile suite;
  suite.file = "ocean_filter_probe_test";
  const double pixelAngle = 1.0 / 64;
  int k = 0;
  for (const FootprintCase& fc : footprintCases()) {
    ProbeCase c;
    c.name = "footprint " + std::to_string(fc.footprint) + " m at t = " + std::to_string(fc.time);
    c.expect = "the filtered maps at the footprint's level, as the reference";
    c.env = defaultProbeEnvironment();
    c.env.time = Value::scalar(static_cast<float>(fc.time));
    // A different point per case, straight below the camera: F = height * pixel angle.
    const double x = 1.3 + 2.71 * k, z = -0.7 + 1.37 * k++;
    const double height = fc.footprint / pixelAngle;
    c.inputs = {{"position", Value::vector({x, 0, z})},
                {"camera", Value::vector({x, height, z})},
                {"pixel_angle", Value::scalar(pixelAngle)},
                {"roughness", Value::scalar(0.05)}};
    for (auto& [port, v] : c.inputs) v = toFloat32(v);
    c.options = {{"ocean_surface", {{kOceanOptionsKey, filterSea()}}}};
    c.nodes = {"ocean_surface"};
    suite.cases.push_back(std::move(c));
  }
  return suite;
}

// The cases reach what they name: every level of the 8 m cascade (64^2: levels 0..6) as
// the floor of a level of detail, integral levels among them, and the top level clamped.
TEST(OceanFilterProbe, TheFootprintsReachEveryLevelAndItsBoundaries) {
  std::set<int> floors;
  int integral = 0, clamped = 0;
  for (const FootprintCase& fc : footprintCases()) {
    const double lod = nodes::oceanread::lodOf(fc.footprint, static_cast<float>(64.0 / 8), 6);
    floors.insert(static_cast<int>(std::floor(lod)));
    integral += lod > 0 && lod < 6 && lod == std::floor(lod);
    clamped += lod == 6;
  }
  for (int l = 0; l <= 6; ++l) EXPECT_TRUE(floors.count(l)) << "no case reads level " << l << " of the 8 m cascade";
  EXPECT_GE(integral, 8);
  EXPECT_GE(clamped, 2);
}

void expectClean(const SuiteResult& r, size_t cases) {
  for (const auto& e : r.errors) ADD_FAILURE() << e;
  for (const auto& f : r.failureLines) ADD_FAILURE() << f;
  EXPECT_EQ(r.nanInf, 0);
  EXPECT_EQ(r.failures, 0);
  // Every case on each of the four outputs.
  EXPECT_GE(r.caseRuns, static_cast<int>(cases * 4));
}

SuiteOptions surfaceOnly() {
  SuiteOptions o;
  o.nodes = {"ocean_surface"};
  o.variants = false;
  o.nodeHardCases = false;
  return o;
}

class OceanFilterProbeGl : public ::testing::TestWithParam<Target> {};

TEST_P(OceanFilterProbeGl, TheFilteredReaderMatchesItsReferenceAtEveryFootprint) {
  const Target target = GetParam();
  auto context = rt::EglContext::create(target == Target::Es300 ? rt::GlApi::Es32 : rt::GlApi::DesktopGl45);
  const ProbeCaseFile suite = footprintSuite();
  expectClean(runHardCaseSuite(suite, target, surfaceOnly()), suite.cases.size());
}

INSTANTIATE_TEST_SUITE_P(Targets, OceanFilterProbeGl, ::testing::Values(Target::Glsl330, Target::Es300),
                         [](const auto& info) { return std::string(targetName(info.param)); });

TEST(OceanFilterProbe, TheFilteredReaderMatchesItsReferenceOnVulkan) {
  ExecutorOptions o;
  o.vulkanValidation = true;
  auto vk = makeGpuExecutor(Target::Vk450, o);
  const ProbeCaseFile suite = footprintSuite();
  SuiteResult r = runHardCaseSuite(suite, *vk, surfaceOnly());
  vk->finish();
  expectClean(r, suite.cases.size());
}

}  // namespace ocean_filter_probe_test
}  // namespace wg::accuracy
