// texture_sample on the GL runtime (llvmpipe through EGL), both targets: every wrap mode,
// filter and colour space, GPU float32 against the double reference within the node's
// documented bound (4/255, tolerance derived from 8-bit quantisation). The texture is a
// 16x16 PNG of scrambled bytes the test writes beside the graph, so every blend of
// neighbouring texels differs; the cases put uv on texel centres and edges, outside
// [0, 1] both ways, and give uv gradients that select mip levels 0 to 4 and blends
// between them (the probe draws uv varying by the gradient across the pixel's quad, so
// texture()'s implicit derivatives are the case's).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "accuracy/probe.h"
#include "accuracy/probe_cases.h"
#include "core/graph_io.h"
#include "runtime/egl_context.h"
#include "sampler_test_texture.h"
#include "texture_sample_cases.h"
#include "test_support.h"

namespace wg::accuracy {
namespace {

namespace fs = std::filesystem;

class TextureSampleOnGpu : public ::testing::TestWithParam<Target> {};

TEST_P(TextureSampleOnGpu, EveryModeWithinTheDocumentedBound) {
  const std::string dir = test::makeTempDir("wg_texture_sample_probe_");
  test::writeFile(dir + "/scrambled.png", test::scrambledPng());
  auto context = rt::EglContext::create(GetParam() == Target::Es300 ? rt::GlApi::Es32 : rt::GlApi::DesktopGl45);
  int runs = 0;
  for (const char* wrap : {"repeat", "clamp", "mirror"})
    for (const char* filter : {"nearest", "linear", "mipmapped"})
      for (const char* space : {"srgb", "linear"}) {
        nlohmann::json options = {{"texture", "scrambled.png"}, {"wrap", wrap}, {"filter", filter}, {"color_space", space}};
        std::string graph = test::graphJson(
            "{\"id\": \"n\", \"type\": \"texture_sample\", \"options\": " + options.dump() + "}",
            "\"fragment\": {\"color\": \"n.rgb\"}");
        test::writeFile(dir + "/g.json", graph);
        Diagnostics diags;
        auto g = loadGraphFile(dir + "/g.json", diags);
        ASSERT_TRUE(g);
        auto cases = parseProbeCases(test::textureSampleCasesJson(std::string(filter) == "mipmapped"), "cases.json", diags);
        ASSERT_TRUE(cases);
        auto report = probeGraph(*g, ProbeOutput{"n", "rgba"}, *cases, GetParam(), diags);
        std::string why;
        for (const auto& d : diags.all()) why += formatText(d) + "\n";
        ASSERT_TRUE(report) << options.dump() << ": " << why;
        ASSERT_EQ(report->cases.size(), cases->cases.size());
        EXPECT_TRUE(report->passed()) << options.dump() << "\n" << formatProbeText(*report);
        // The largest error seen, for the record (docs/nodes.md states the bound).
        const double worst = test::worstAbsError(*report);
        std::printf("[ texture  ] %s %s: worst |gpu - ref| %.5f (%.2f 8-bit levels)\n",
                    std::string(targetName(GetParam())).c_str(), options.dump().c_str(), worst, worst * 255);
        ++runs;
      }
  EXPECT_EQ(runs, 18);
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Targets, TextureSampleOnGpu, ::testing::Values(Target::Glsl330, Target::Es300),
                         [](const auto& info) { return std::string(targetName(info.param)); });

}  // namespace
}  // namespace wg::accuracy
