// The scene-pass resolution knob (core/node_spec.h kResolutionOption): every node that
// reads a frame-sized scene resource has the option `resolution`, a quality knob; a value
// below 1 lists the passes producing what it reads in the manifest's "pass_scales" (the
// smallest value of their readers), changes no shader, reads back byte for byte, and a
// graph that sets none has no "pass_scales" at all.
#include <gtest/gtest.h>

#include "codegen/compile.h"
#include "codegen/manifest.h"
#include "compile_text.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg {
namespace {

// Water that reads the scene depth twice (scene_depth, water_depth) and the scene colour,
// each reader at its own resolution.
std::string sceneGraph(const std::string& depthRes, const std::string& waterDepthRes, const std::string& colorRes) {
  auto opt = [](const std::string& r) { return r.empty() ? std::string("{}") : "{\"resolution\": " + r + "}"; };
  return R"({"version": 1, "name": "scaled", "nodes": [
    {"id": "d", "type": "scene_depth", "options": )" + opt(depthRes) + R"(},
    {"id": "wd", "type": "water_depth", "options": )" + opt(waterDepthRes) + R"(},
    {"id": "c", "type": "scene_color", "options": )" + opt(colorRes) + R"(},
    {"id": "m", "type": "mul", "inputs": {"a": "c.color", "b": "d.linear"}},
    {"id": "s", "type": "mul", "inputs": {"a": "m.out", "b": "wd.thickness"}}],
    "outputs": {"fragment": {"color": "s.out"}}})";
}

std::string shadersOf(const CompileResult& r) {
  std::string all;
  for (const auto& f : r.files)
    if (!f.name.ends_with(".manifest.json")) all += f.name + "\n" + f.contents;
  return all;
}

const std::string& manifestText(const CompileResult& r) {
  for (const auto& f : r.files)
    if (f.name.ends_with(".manifest.json")) return f.contents;
  throw std::logic_error("no manifest");
}

TEST(SceneResolution, EveryNodeReadingAFrameSizedResourceHasTheKnob) {
  for (const NodeSpec* spec : defaultRegistry().all()) {
    SCOPED_TRACE(spec->type);
    bool frameSized = false;
    for (SceneResource r : spec->resources) frameSized |= r != SceneResource::Environment;
    int i = spec->optionIndex(kResolutionOption);
    ASSERT_EQ(i >= 0, frameSized) << "only and every reader of a frame-sized scene resource";
    if (i < 0) continue;
    const OptionSpec& o = spec->options[static_cast<size_t>(i)];
    EXPECT_EQ(o.defaultValue, 1.0);
    EXPECT_EQ(o.levels, (std::vector<nlohmann::json>{0.25, 0.5, 0.75, 1.0})) << "cheapest to most exact";
  }
  EXPECT_LT(defaultRegistry().find("cubemap_reflection")->optionIndex(kResolutionOption), 0)
      << "the environment cube map has its own size";
}

TEST(SceneResolution, DefaultWritesNoPassScales) {
  CompileResult r = test::compileText(sceneGraph("", "", ""));
  EXPECT_TRUE(r.manifest.passScales.empty());
  EXPECT_EQ(manifestText(r).find("pass_scales"), std::string::npos);
}

TEST(SceneResolution, ReducedReadersScaleTheirPassesAndNoShader) {
  CompileResult full = test::compileText(sceneGraph("", "", ""));
  CompileResult half = test::compileText(sceneGraph("0.5", "0.5", "0.25"));
  ASSERT_EQ(half.manifest.passScales.size(), 2u);
  EXPECT_EQ(half.manifest.passScales[0].pass, RenderPass::DepthPrepass);
  EXPECT_EQ(half.manifest.passScales[0].scale, 0.5);
  EXPECT_EQ(half.manifest.passScales[1].pass, RenderPass::SceneColorCopy);
  EXPECT_EQ(half.manifest.passScales[1].scale, 0.25);
  EXPECT_EQ(half.manifest.scaleOf(RenderPass::WaterSurface), 1.0);
  EXPECT_EQ(shadersOf(half), shadersOf(full)) << "the resolution changes only the pass sizes";
  // The file says it, in the key order nlohmann gives, and reads back to the same bytes.
  const std::string& text = manifestText(half);
  EXPECT_NE(text.find("\"pass_scales\": {\n    \"depth_prepass\": 0.5,\n    \"scene_color_copy\": 0.25\n  },\n  \"passes\""),
            std::string::npos)
      << text;
  EXPECT_EQ(half.manifest.toJson().dump(2) + "\n", text);
  EXPECT_EQ(Manifest::fromJson(nlohmann::json::parse(text)).fileText(), text);
}

// One depth target serves both depth readers: either one lowered lowers it, to the
// smallest value asked for.
TEST(SceneResolution, APassReadByTwoNodesTakesTheSmallerResolution) {
  CompileResult r = test::compileText(sceneGraph("0.25", "", "0.5"));
  EXPECT_EQ(r.manifest.scaleOf(RenderPass::DepthPrepass), 0.25) << "water_depth at 1 does not hold it up";
  EXPECT_EQ(r.manifest.scaleOf(RenderPass::SceneColorCopy), 0.5);
  CompileResult q = test::compileText(sceneGraph("0.25", "0.5", ""));
  EXPECT_EQ(q.manifest.scaleOf(RenderPass::DepthPrepass), 0.25);
  EXPECT_EQ(q.manifest.scaleOf(RenderPass::SceneColorCopy), 1.0);
  CompileResult w = test::compileText(sceneGraph("", "0.5", ""));
  EXPECT_EQ(w.manifest.scaleOf(RenderPass::DepthPrepass), 0.5);
}

TEST(SceneResolution, ValuesOutsideTheRangeAreRefused) {
  for (const char* bad : {"0.1", "1.5", "\"half\""}) {
    SCOPED_TRACE(bad);
    Diagnostics diags;
    auto graph = parseGraph(sceneGraph(bad, "", ""), "inline.json", diags);
    std::optional<CompileResult> r;
    if (graph) {
      CompileOptions o;
      o.targets = {Target::Glsl330};
      r = compileGraph(*graph, defaultRegistry(), o, diags);
    }
    EXPECT_FALSE(r);
    EXPECT_TRUE(diags.hasErrors());
  }
}

}  // namespace
}  // namespace wg
