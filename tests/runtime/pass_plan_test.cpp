// Pass planning from hand-made manifests: which passes run, which targets exist, and how
// many bytes they take. No GL here.
#include <gtest/gtest.h>

#include "runtime/pass_plan.h"
#include "runtime/runtime_error.h"
#include "runtime_test_support.h"

namespace wg::rt {
namespace {

nlohmann::json manifestJsonWith(std::vector<std::string> passes) {
  nlohmann::json m;
  m["passes"] = passes;
  return m;
}

Manifest manifestWith(std::vector<std::string> passes) { return Manifest::fromJson(manifestJsonWith(std::move(passes))); }

PlanOptions small() {
  PlanOptions o;
  o.width = 320;
  o.height = 180;
  o.environmentSize = 64;
  return o;
}

constexpr size_t kPixels = 320 * 180;

std::vector<std::string> passNames(const PassPlan& p) {
  std::vector<std::string> n;
  for (auto k : p.passes) n.push_back(passName(k));
  return n;
}

std::vector<std::string> targetNames(const PassPlan& p) {
  std::vector<std::string> n;
  for (const auto& t : p.targets) n.push_back(t.name);
  return n;
}

// A picture render: the frame in RGBA16F, the output transform last into the RGBA8 display.
TEST(PassPlan, WaterOnlyRunsTheSceneAndTheSurfaceIntoOneTarget) {
  PassPlan p = planPasses(manifestWith({"water_surface"}), small());
  EXPECT_EQ(passNames(p), (std::vector<std::string>{"opaque_scene", "water_surface", "output_transform"}));
  EXPECT_EQ(targetNames(p), (std::vector<std::string>{"frame", "display"}));
  EXPECT_EQ(p.target("frame")->color, ColorFormat::Rgba16f);
  EXPECT_EQ(p.target("display")->color, ColorFormat::Rgba8);
  ASSERT_NE(p.picture(), nullptr);
  EXPECT_EQ(p.picture()->name, "display");
  // Measuring the pipeline's cost: RGBA8 targets without the transform show the frame itself.
  PlanOptions ldr = small();
  ldr.pictureFormat = ColorFormat::Rgba8;
  ldr.outputTransform = false;
  PassPlan old = planPasses(manifestWith({"water_surface"}), ldr);
  EXPECT_FALSE(old.runs(PassKind::OutputTransform));
  ASSERT_NE(old.picture(), nullptr);
  EXPECT_EQ(old.picture()->name, "frame");
  EXPECT_EQ(p.totalBytes(), kPixels * (8 + 4 + 4));  // RGBA16F + DEPTH32F, RGBA8
  EXPECT_FALSE(p.runs(PassKind::PlanarReflection));
  EXPECT_EQ(p.target("reflection"), nullptr);
}

TEST(PassPlan, ReflectionOnlyWhenListed) {
  PassPlan without = planPasses(manifestWith({"water_surface"}), small());
  PassPlan with = planPasses(manifestWith({"planar_reflection", "water_surface"}), small());
  EXPECT_FALSE(without.runs(PassKind::PlanarReflection));
  ASSERT_TRUE(with.runs(PassKind::PlanarReflection));
  ASSERT_NE(with.target("reflection"), nullptr);
  EXPECT_EQ(with.target("reflection")->sampler, "u_reflection");
  EXPECT_EQ(with.targets.size(), 3u);
  EXPECT_EQ(with.target("reflection")->color, ColorFormat::Rgba16f) << "HDR: a reflected sun is not clamped at 1";
  EXPECT_EQ(with.totalBytes() - without.totalBytes(), kPixels * (8 + 4));
}

struct OnePass {
  const char* pass;
  const char* target;
  const char* sampler;
  size_t bytes;  // of the added target, RGBA16F colour
};

class PassPlanEach : public ::testing::TestWithParam<OnePass> {};

TEST_P(PassPlanEach, AddsExactlyItsTarget) {
  const OnePass& c = GetParam();
  PassPlan p = planPasses(manifestWith({c.pass, "water_surface"}), small());
  EXPECT_EQ(passNames(p).size(), 4u);
  EXPECT_TRUE(p.runs(*parsePassName(c.pass)));
  EXPECT_EQ(targetNames(p), (std::vector<std::string>{"frame", c.target, "display"}));
  EXPECT_EQ(p.target(c.target)->sampler, c.sampler);
  EXPECT_EQ(p.target(c.target)->bytes(), c.bytes);
  EXPECT_EQ(p.totalBytes(), kPixels * (12 + 4) + c.bytes);
}

INSTANTIATE_TEST_SUITE_P(
    Passes, PassPlanEach,
    ::testing::Values(OnePass{"depth_prepass", "scene_depth", "u_scene_depth", kPixels * 4},
                      OnePass{"scene_color_copy", "scene_color", "u_scene_color", kPixels * 8},
                      OnePass{"planar_reflection", "reflection", "u_reflection", kPixels * 12},
                      OnePass{"refraction", "refraction", "u_refraction", kPixels * 12},
                      OnePass{"environment_cubemap", "environment", "u_environment", 64 * 64 * 6 * 8}),
    [](const auto& info) { return std::string(info.param.pass); });

TEST(PassPlan, AllPassesRunInDependencyOrderWhateverTheListOrder) {
  PassPlan p = planPasses(manifestWith({"water_surface", "refraction", "scene_color_copy", "environment_cubemap",
                                        "planar_reflection", "depth_prepass"}),
                          small());
  EXPECT_EQ(passNames(p), (std::vector<std::string>{"environment_cubemap", "depth_prepass", "planar_reflection",
                                                    "refraction", "opaque_scene", "scene_color_copy", "water_surface",
                                                    "output_transform"}));
  EXPECT_EQ(p.targets.size(), 7u);
  EXPECT_EQ(p.totalBytes(), kPixels * (12 + 4 + 8 + 12 + 12 + 4) + 64 * 64 * 6 * 8);
}

// Accuracy renders: RGBA32F colour, read back linear: no output transform, no display.
TEST(PassPlan, FloatColourDoublesColourBytesAndDropsTheOutputTransform) {
  PlanOptions o = small();
  o.floatColor = true;
  PassPlan p = planPasses(manifestWith({"depth_prepass", "planar_reflection", "water_surface"}), o);
  EXPECT_FALSE(p.runs(PassKind::OutputTransform));
  EXPECT_EQ(p.target("display"), nullptr);
  EXPECT_EQ(p.picture(), nullptr) << "an accuracy render has no 8-bit picture";
  EXPECT_EQ(p.target("frame")->bytes(), kPixels * (16 + 4));
  EXPECT_EQ(p.target("scene_depth")->bytes(), kPixels * 4);
  EXPECT_EQ(p.target("reflection")->bytes(), kPixels * (16 + 4));
}

TEST(PassPlan, DuplicatesCountOnce) {
  PassPlan p = planPasses(manifestWith({"refraction", "refraction", "water_surface"}), small());
  EXPECT_EQ(p.targets.size(), 3u);
}

// A "passes" list the manifest reader refuses.
void expectUnreadable(const nlohmann::json& m, const std::string& fragment) {
  try {
    Manifest::fromJson(m);
    ADD_FAILURE() << "no error for " << m.dump();
  } catch (const ManifestError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

// A manifest that reads but that the runtime cannot run.
void expectUnplannable(const Manifest& m, const std::string& fragment) {
  try {
    planPasses(m, small());
    ADD_FAILURE() << "no error for " << m.toJson().dump();
  } catch (const RuntimeError& e) {
    EXPECT_EQ(e.kind(), RuntimeError::Kind::Manifest);
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    EXPECT_EQ(e.exitCode(), 1);
  }
}

// The deferred water pass: a float G-buffer (position + depth, normal + uv) whatever the
// frame's format, planned after the scene colour copy and before the full-screen pass.
TEST(PassPlan, DeferredWaterCreatesTheFloatGbuffer) {
  PassPlan plan = planPasses(manifestWith({"water_surface", "deferred_water", "depth_prepass", "scene_color_copy"}), small());
  ASSERT_EQ(plan.passes.size(), 6u);
  EXPECT_EQ(plan.passes[3], PassKind::DeferredWater);
  EXPECT_EQ(plan.passes[4], PassKind::WaterSurface);
  const TargetSpec* normal = plan.target("water_normal");
  const TargetSpec* position = plan.target("water_position");
  ASSERT_TRUE(normal && position);
  EXPECT_EQ(normal->color, ColorFormat::Rgba32f);
  EXPECT_EQ(normal->depth, DepthFormat::None);
  EXPECT_EQ(position->color, ColorFormat::Rgba32f);
  EXPECT_EQ(position->depth, DepthFormat::Depth32f);
  EXPECT_EQ(position->sampler, "u_water_surface");
  EXPECT_EQ(normal->sampler, "u_water_normal_uv");
  EXPECT_LT(plan.target("water_normal") - &plan.targets.front(), plan.target("water_position") - &plan.targets.front())
      << "water_position's framebuffer attaches water_normal, so it is created first";
  EXPECT_FALSE(planPasses(manifestWith({"water_surface"}), small()).target("water_position"));
}

// "pass_scales": the targets of a scaled pass are that fraction of the frame (rounded, at
// least a pixel); other passes and the environment cube keep their sizes.
TEST(PassPlan, ScaledPassesGetSmallerTargets) {
  nlohmann::json m = manifestJsonWith({"water_surface", "deferred_water", "depth_prepass", "scene_color_copy",
                                       "planar_reflection", "environment_cubemap"});
  m["pass_scales"] = {{"depth_prepass", 0.5}, {"deferred_water", 0.25}};
  PlanOptions o = small();
  o.width = 321, o.height = 181;
  PassPlan plan = planPasses(Manifest::fromJson(m), o);
  auto size = [&](const char* name) {
    const TargetSpec* t = plan.target(name);
    return t ? std::pair(t->width, t->height) : std::pair(-1, -1);
  };
  EXPECT_EQ(size("frame"), std::pair(321, 181));
  EXPECT_EQ(size("scene_depth"), std::pair(161, 91)) << "160.5 and 90.5 round up";
  EXPECT_EQ(size("water_position"), std::pair(80, 45));
  EXPECT_EQ(size("water_normal"), std::pair(80, 45));
  EXPECT_EQ(size("scene_color"), std::pair(321, 181));
  EXPECT_EQ(size("reflection"), std::pair(321, 181));
  EXPECT_EQ(size("environment"), std::pair(64, 64));
  EXPECT_EQ(scaledSize(1, 0.25), 1) << "at least one pixel";
  PassPlan full = planPasses(manifestWith({"water_surface", "depth_prepass"}), o);
  EXPECT_EQ(full.totalBytes() - plan.target("frame")->bytes() - plan.target("display")->bytes(), 321u * 181u * 4u);
}

TEST(PassPlan, Errors) {
  expectUnreadable(nlohmann::json::object(), "no \"passes\"");
  expectUnplannable(manifestWith({"planar_reflection"}), "lacks water_surface");
  expectUnreadable(manifestJsonWith({"water_surface", "ssao"}), "unknown pass 'ssao'");
  expectUnreadable(manifestJsonWith({"water_surface", "opaque_scene"}), "unknown pass 'opaque_scene'");
  expectUnreadable(manifestJsonWith({"water_surface", "output_transform"}), "unknown pass 'output_transform'");
  nlohmann::json m;
  m["passes"] = {"water_surface", 3};
  expectUnreadable(m, "non-string");
  PlanOptions empty = small();
  empty.width = 0;
  EXPECT_THROW(planPasses(manifestWith({"water_surface"}), empty), RuntimeError);
}

// The compiler's manifests for the example graphs plan without errors, and a graph that
// samples nothing gets no extra targets.
TEST(PassPlan, ExampleGraphManifests) {
  for (const auto& name : test::exampleGraphNames()) {
    SCOPED_TRACE(name);
    CompileResult r = test::compileExample(name);
    PassPlan p = planPasses(r.manifest, small());
    size_t expected = r.manifest.passes.size() + 1;  // and the display image
    for (RenderPass pass : r.manifest.passes) {
      expected += pass == RenderPass::DeferredWater;  // the G-buffer: two targets
      expected -= pass == RenderPass::OceanSimulation;  // its maps belong to the simulation, not to the plan
    }
    EXPECT_EQ(p.targets.size(), expected) << "one target per listed pass besides the frame and the display";
    EXPECT_TRUE(p.runs(PassKind::WaterSurface));
  }
}

}  // namespace
}  // namespace wg::rt
