// The Fresnel error bound (NodeSpec::tolerance plus the conditioning term of
// accuracy/error_bound.h) on a dense sweep: 10,000 angles from 0 to 90 degrees, exact and
// Schlick, both directions, both GL targets, every angle within its bound with no window
// set by hand around the critical angle. The bound can fail: the same sweep with the
// GLSL index of refraction changed by 1e-4 (a mutation of the probe shader) does.
#include <cstdio>

#include <gtest/gtest.h>

#include "accuracy/node_probe.h"
#include "accuracy/sweep.h"
#include "core/number_format.h"
#include "nodes/registry.h"
#include "nodes/snell_constants.h"
#include "runtime/egl_context.h"

namespace wg::accuracy {
namespace {

struct Config {
  const char* model;
  const char* direction;
};

class FresnelBound : public ::testing::TestWithParam<Target> {
 protected:
  void SetUp() override {
    context_ = rt::EglContext::create(GetParam() == Target::Es300 ? rt::GlApi::Es32 : rt::GlApi::DesktopGl45);
  }
  ProbeReport sweep(const Config& s, const ShaderMutation& mutation = {}) {
    const NodeSpec& spec = *defaultRegistry().find("fresnel");
    SweepAxis axis{"angle", -1, 0.0, 90.0, 10000};
    ProbeCase base;
    base.name = "base";
    base.env = defaultProbeEnvironment();
    Diagnostics diags;
    nlohmann::json options = {{"model", s.model}, {"direction", s.direction}};
    auto report = probeNode(spec, options, "reflectance", sweepCases(portsOfNode(spec, options), axis, base), GetParam(),
                            diags, mutation);
    EXPECT_TRUE(report);
    return report ? *report : ProbeReport{};
  }
  std::unique_ptr<rt::EglContext> context_;
};

TEST_P(FresnelBound, TenThousandAnglesWithinTheBoundInBothDirections) {
  for (Config s : {Config{"exact", "air_to_water"}, Config{"exact", "water_to_air"}, Config{"schlick", "air_to_water"},
                  Config{"schlick", "water_to_air"}}) {
    ProbeReport r = sweep(s);
    ASSERT_EQ(r.cases.size(), 10000u);
    double worst = 0, maxError = 0;
    int shown = 0;
    for (const auto& c : r.cases) {
      worst = std::max(worst, c.bound > 0 ? c.absError / c.bound : 0.0);
      maxError = std::max(maxError, c.absError);
      if (!c.passed() && shown++ < 5) ADD_FAILURE() << s.model << " " << s.direction << " " << c.name << ": " << c.failure();
    }
    EXPECT_EQ(r.failures(), 0) << s.model << " " << s.direction;
    std::printf("[ fresnel  ] %s %s %s: max error %.3g, worst error/bound %.3f\n", std::string(targetName(GetParam())).c_str(),
                s.model, s.direction, maxError, worst);
  }
}

// The IOR reaches the shader as itself (the exact model's n1, n2) and, from below, through
// the critical angle's squared cosine 1 - 1/ior^2 (formed on the CPU): each changed as the
// IOR 1.3331 would change it must fail the sweep.
TEST_P(FresnelBound, FailsWhenTheGlslIorIsPerturbedBy1e4) {
  for (Config s : {Config{"exact", "air_to_water"}, Config{"exact", "water_to_air"}}) {
    ProbeReport r = sweep(s, ShaderMutation{"1.333", "1.3331"});
    EXPECT_GT(r.failures(), 0) << s.model << " " << s.direction << ": the sweep passed with the IOR 1.3331";
  }
  ShaderMutation critical{formatGlslFloat(nodes::snellConstants(1.333).cosCrit2),
                          formatGlslFloat(nodes::snellConstants(1.3331).cosCrit2)};
  for (Config s : {Config{"exact", "water_to_air"}, Config{"schlick", "water_to_air"}}) {
    ProbeReport r = sweep(s, critical);
    EXPECT_GT(r.failures(), 0) << s.model << " " << s.direction << ": the sweep passed with the critical angle of IOR 1.3331";
  }
}

INSTANTIATE_TEST_SUITE_P(Targets, FresnelBound, ::testing::Values(Target::Glsl330, Target::Es300),
                         [](const auto& info) { return std::string(targetName(info.param)); });

}  // namespace
}  // namespace wg::accuracy
