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
#include "test_support.h"

namespace wg::accuracy {
namespace {

namespace fs = std::filesystem;

// The cases: (u, v) and, for the mipmapped runs, the gradient (du/dx = dv/dy, the others
// zero: rho = 16 g, lambda = log2(16 g)).
std::string casesJson(bool gradients) {
  const double uvs[][2] = {{0.3, 0.6},       {0.5, 0.5},     {0.25, 0.75},   {1.0 / 32, 3.0 / 32}, {0.0, 0.0},
                           {1.0, 1.0},       {-0.05, 0.47},  {1.05, -0.21},  {-0.3, -1.7},         {2.61, 3.13},
                           {-7.77, 5.55},    {0.999, 0.001}, {0.123, 0.877}, {100.37, -50.21}};
  // lambda -1, 0.5, 1, 1.5, 2.32, 3, 4, 6: magnification, blends, single levels, past the last.
  const double gs[] = {1.0 / 32, std::sqrt(2.0) / 16, 2.0 / 16, std::sqrt(8.0) / 16, 5.0 / 16, 8.0 / 16, 1.0, 4.0};
  nlohmann::json cases = nlohmann::json::array();
  for (const auto& uv : uvs) {
    if (!gradients) {
      cases.push_back({{"name", "uv " + std::to_string(uv[0]) + " " + std::to_string(uv[1])}, {"uv", {uv[0], uv[1]}}});
      continue;
    }
    for (double g : gs)
      cases.push_back({{"name", "uv " + std::to_string(uv[0]) + " " + std::to_string(uv[1]) + " g " + std::to_string(g)},
                       {"uv", {uv[0], uv[1]}},
                       {"uv_dx", {g, 0}},
                       {"uv_dy", {0, g}}});
  }
  return nlohmann::json{{"cases", cases}}.dump();
}

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
        auto cases = parseProbeCases(casesJson(std::string(filter) == "mipmapped"), "cases.json", diags);
        ASSERT_TRUE(cases);
        auto report = probeGraph(*g, ProbeOutput{"n", "rgba"}, *cases, GetParam(), diags);
        std::string why;
        for (const auto& d : diags.all()) why += formatText(d) + "\n";
        ASSERT_TRUE(report) << options.dump() << ": " << why;
        ASSERT_EQ(report->cases.size(), cases->cases.size());
        EXPECT_TRUE(report->passed()) << options.dump() << "\n" << formatProbeText(*report);
        // The largest error seen, for the record (docs/nodes.md states the bound).
        double worst = 0;
        for (const auto& c : report->cases)
          for (int k = 0; k < c.components; ++k)
            worst = std::max(worst, std::abs(c.gpu[static_cast<size_t>(k)] - c.reference[static_cast<size_t>(k)]));
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
