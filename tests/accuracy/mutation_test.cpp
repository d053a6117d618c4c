// Mutation testing of the accuracy suite: one constant of a node's GLSL changed by about
// 1e-4 (an index of refraction, a phase scale, a hash multiplier, ...) in the probe
// shader must make the hard-case suite fail for that node. In CI a sample of five runs;
// the whole table runs with WG_MUTATION_ALL=1 (docs/accuracy.md records its results):
//   WG_MUTATION_ALL=1 build/bin/wg_test_accuracy --gtest_filter='Mutation*'
#include <cstdio>
#include <cstdlib>

#include <gtest/gtest.h>

#include "accuracy/hard_case_suite.h"
#include "runtime/egl_context.h"
#include "suite_file.h"
#include "test_support.h"

namespace wg::accuracy {
namespace {

struct Mutation {
  const char* node;
  const char* what;
  ShaderMutation edit;
};

// The text to find is as the node's GLSL (nodes/glsl/) or its emitted literals write it.
const std::vector<Mutation>& mutations() {
  static const std::vector<Mutation> m = {
      {"fresnel", "index of refraction 1.333 -> 1.3331", {"1.333", "1.3331"}},
      {"refract_dir", "the critical angle's squared cosine in Snell's k scaled by 1.0001", {"c * c - cosCrit2", "c * c - 1.0001 * cosCrit2"}},
      {"reflect_dir", "the normal scaled by 1.0001 before reflect", {"reflect(-vv, nn)", "reflect(-vv, nn * 1.0001)"}},
      {"gerstner_waves", "phase scale k -> 1.0001 k", {"float theta = k * mod(", "float theta = 1.0001 * k * mod("}},
      {"trochoid_wave", "phase scale 1.0001", {"dot(waveVector, xz) + timePhase", "dot(waveVector, xz) * 1.0001 + timePhase"}},
      {"shore_waves", "phase scale 1.0001", {"d * frequency + phase", "d * frequency * 1.0001 + phase"}},
      {"absorption", "path length 1.0001 d", {"exp(-max(sigma, vec3(0.0)) * d)", "exp(-max(sigma, vec3(0.0)) * d * 1.0001)"}},
      {"subsurface", "height offset 0.5 -> 0.5001", {"height * 2.0 + 0.5,", "height * 2.0 + 0.5001,"}},
      {"ggx_specular", "pi -> 3.1419 in D", {"3.14159265358979 * d * d", "3.1419 * d * d"}},
      {"hash", "PCG multiplier 1664525 -> 1664527", {"1664525u", "1664527u"}},
      {"value_noise", "smoothstep fade 3 -> 3.0001", {"(3.0 - 2.0 * f)", "(3.0001 - 2.0 * f)"}},
      {"fbm", "octave offset 17.31 -> 17.32", {"vec2(17.31, 9.73)", "vec2(17.32, 9.73)"}},
      {"voronoi", "point offset 0.5 -> 0.5001", {"return 0.5 + clamp(jitter", "return 0.5001 + clamp(jitter"}},
      {"voronoi_caustics", "point offset 0.5 -> 0.5001", {"return 0.5 + clamp(jitter", "return 0.5001 + clamp(jitter"}},
      {"linearize_depth", "1 - d -> 1.0001 - d", {"(1.0 - d) + d * r", "(1.0001 - d) + d * r"}},
      {"depth_tint", "depth scaled by 1.0001", {"clamp(depth / max(max_depth, 1e-6)", "clamp(depth * 1.0001 / max(max_depth, 1e-6)"}},
  };
  return m;
}

using test_suite::loadSuite;

// The suite for one node, every variant, with the mutation: how many case runs failed.
SuiteResult runMutated(const ProbeCaseFile& suite, const Mutation& m, Target target) {
  SuiteOptions options;
  options.nodes = {m.node};
  options.mutation = m.edit;
  return runHardCaseSuite(suite, target, options);
}

// Besides an IOR, a phase scale and a hash constant, two that survived before the suite
// had cases at ordinary inputs and derived tolerances (absorption's path length, value
// noise's fade): both cheap, so CI keeps them caught.
TEST(MutationSample, TheSuiteFailsForAnIorAPhaseScaleAHashConstantAPathLengthAndAFade) {
  auto context = rt::EglContext::create(rt::GlApi::DesktopGl45);
  ProbeCaseFile suite = loadSuite();
  for (const char* node : {"fresnel", "gerstner_waves", "hash", "absorption", "value_noise"}) {
    for (const auto& m : mutations()) {
      if (std::string(m.node) != node) continue;
      SuiteResult r = runMutated(suite, m, Target::Glsl330);
      EXPECT_GT(r.mutatedRuns, 0) << m.node << ": the mutation changed no probe shader";
      EXPECT_GT(r.failures, 0) << m.node << " (" << m.what << "): the suite passed with the mutation";
    }
  }
}

TEST(MutationAll, EveryNodeInTheTableFailsTheSuite) {
  if (!std::getenv("WG_MUTATION_ALL")) GTEST_SKIP() << "the whole mutation table runs with WG_MUTATION_ALL=1";
  ProbeCaseFile suite = loadSuite();
  for (Target target : {Target::Glsl330, Target::Es300}) {
    auto context = rt::EglContext::create(target == Target::Es300 ? rt::GlApi::Es32 : rt::GlApi::DesktopGl45);
    for (const auto& m : mutations()) {
      SuiteResult r = runMutated(suite, m, target);
      EXPECT_GT(r.mutatedRuns, 0) << m.node << ": the mutation changed no probe shader";
      EXPECT_GT(r.failures, 0) << m.node << " (" << m.what << "): the suite passed with the mutation";
      std::printf("| %s | %s | %s | %d of %d case runs fail (%d runs mutated) |\n", std::string(targetName(target)).c_str(),
                  m.node, m.what, r.failures, r.caseRuns, r.mutatedRuns);
    }
  }
}

}  // namespace
}  // namespace wg::accuracy
