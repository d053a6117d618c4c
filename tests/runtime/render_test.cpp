// Every example graph runs on both GL targets (desktop 4.5 core and ES 3.2) on llvmpipe:
// the image is not blank, a float render has no NaN or Inf, the two targets agree, and the
// glsl330 image matches the checked-in golden (tests/golden/images/, see its README).
#include <filesystem>

#include <gtest/gtest.h>

#include "runtime/image.h"
#include "runtime/preview.h"
#include "runtime/runtime_error.h"
#include "runtime_test_support.h"
#include "test_support.h"

namespace wg::rt {
namespace {

// Rows of the 320 x 180 "above" view that show only water (below the far shore and the
// pillars' feet): the bottom quarter of the image.
double waterVariance(const Image& img) { return lumaVariance(img, 0, img.height * 3 / 4, img.width, img.height); }

// Variance of the luminance of a float render (0..1 scale), over the whole image.
double floatLumaVariance(const Image& img) {
  double sum = 0, sum2 = 0;
  size_t n = img.rgba32f.size() / 4;
  for (size_t i = 0; i < n; ++i) {
    const float* p = &img.rgba32f[i * 4];
    double l = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
    sum += l;
    sum2 += l * l;
  }
  double mean = sum / static_cast<double>(n);
  return sum2 / static_cast<double>(n) - mean * mean;
}

struct Case {
  std::string graph;
  Target target;
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.graph << "/" << targetName(c.target); }

std::vector<Case> allCases() {
  std::vector<Case> c;
  for (const auto& g : test::exampleGraphNames())
    for (Target t : {Target::Glsl330, Target::Es300}) c.push_back({g, t});
  return c;
}

class ExampleGraph : public ::testing::TestWithParam<Case> {};

TEST_P(ExampleGraph, RendersNotBlankAndFinite) {
  const Case& c = GetParam();
  CompileResult r = test::compileExample(c.graph);
  Preview p = renderPreview(r, c.target, test::smallSettings());
  EXPECT_EQ(p.image.width, 320);
  EXPECT_EQ(p.image.height, 180);
  EXPECT_GT(waterVariance(p.image), 0.5) << "the water region is flat";

  RenderSettings f = test::smallSettings();
  f.floatColor = true;
  Preview pf = renderPreview(r, c.target, f);
  ASSERT_EQ(pf.image.rgba32f.size(), 320u * 180u * 4u);
  EXPECT_EQ(countNonFinite(pf.image), 0u);
  EXPECT_EQ(pf.targetBytes, pf.plan.totalBytes());
}

// Through the graph's own view (its "view": tone mapper and exposure), as `render` shows it.
TEST_P(ExampleGraph, MatchesGoldenImage) {
  const Case& c = GetParam();
  CompileResult r = test::compileExample(c.graph);
  RenderSettings s = test::smallSettings();
  s.view = r.program.view;
  Preview p = renderPreview(r, c.target, s);
  std::string golden = test::sourcePath("tests/golden/images/" + c.graph + ".png");
  if (test::updatingGoldens()) {
    if (c.target == Target::Glsl330) writePng(golden, p.image);  // the reference is the desktop GL image
    GTEST_SKIP() << "updated " << golden;
  }
  ASSERT_TRUE(std::filesystem::exists(golden)) << golden << " is missing; run with WG_UPDATE_GOLDEN=1";
  Image expected = readPng(golden);
  ASSERT_EQ(expected.width, p.image.width);
  ASSERT_EQ(expected.height, p.image.height);
  double psnr = psnrRgb8(expected, p.image);
  EXPECT_GE(psnr, 40.0) << c.graph << " (" << targetName(c.target) << ") differs from " << golden;
  if (psnr < 40.0) {
    std::string actual = (std::filesystem::temp_directory_path() / (c.graph + "." + std::string(targetName(c.target)) + ".actual.png")).string();
    writePng(actual, p.image);
    ADD_FAILURE() << "the rendered image is in " << actual;
  }
}

INSTANTIATE_TEST_SUITE_P(Graphs, ExampleGraph, ::testing::ValuesIn(allCases()), [](const auto& info) {
  return info.param.graph + "_" + std::string(targetName(info.param.target));
});

TEST(TargetsAgree, Glsl330AndEs300RendersOfEachGraph) {
  for (const auto& g : test::exampleGraphNames()) {
    SCOPED_TRACE(g);
    CompileResult r = test::compileExample(g);
    Preview gl = renderPreview(r, Target::Glsl330, test::smallSettings());
    Preview es = renderPreview(r, Target::Es300, test::smallSettings());
    EXPECT_GE(psnrRgb8(gl.image, es.image), 40.0);
  }
}

TEST_P(ExampleGraph, EveryCameraPresetRendersFinite) {
  const Case& c = GetParam();
  CompileResult r = test::compileExample(c.graph);
  for (const auto& cam : cameraPresetNames()) {
    SCOPED_TRACE(cam);
    RenderSettings s = test::smallSettings();
    s.width = 160;
    s.height = 90;
    s.camera = cam;
    s.floatColor = true;
    Preview p = renderPreview(r, c.target, s);
    EXPECT_EQ(countNonFinite(p.image), 0u);
    EXPECT_GT(floatLumaVariance(p.image), 1e-4) << "a flat image";
  }
}

TEST(Deterministic, SameSettingsSameBytes) {
  CompileResult r = test::compileExample(test::exampleGraphNames().front());
  Preview a = renderPreview(r, Target::Glsl330, test::smallSettings());
  Preview b = renderPreview(r, Target::Glsl330, test::smallSettings());
  EXPECT_EQ(a.image.rgba8, b.image.rgba8);
}

TEST(Errors, Vk450IsNotRunByTheGlRuntime) {
  CompileResult r = test::compileExample(test::exampleGraphNames().front());
  try {
    renderPreview(r, Target::Vk450, test::smallSettings());
    ADD_FAILURE() << "no error";
  } catch (const RuntimeError& e) {
    EXPECT_EQ(e.kind(), RuntimeError::Kind::Manifest);
  }
}

}  // namespace
}  // namespace wg::rt
