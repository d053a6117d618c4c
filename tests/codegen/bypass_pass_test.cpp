// The bypass pass (codegen/pass_bypass.cpp): a node that adds detail, switched off with its
// `bypass` option, compiles to exactly what its declared "off" values wired by hand compile
// to, and what only it needed (the nodes feeding it, its textures) leaves with it.
#include <gtest/gtest.h>

#include "codegen/compile.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg {
namespace {

std::optional<CompileResult> compileText(const std::string& text, Diagnostics& d, const std::string& preset = "") {
  auto g = parseGraph(text, "t.json", d);
  if (!g) return std::nullopt;
  CompileOptions options;
  options.validate = false;
  options.preset = preset;
  return compileGraph(*g, defaultRegistry(), options, d);
}

std::string fragmentOf(const CompileResult& r) {
  for (const auto& f : r.files)
    if (f.name == "t.glsl330.frag") return f.contents;
  return "";
}

std::string errors(const Diagnostics& d) {
  std::string s;
  for (const auto& x : d.all()) s += formatText(x) + "\n";
  return s;
}

// Caustics brighten a colour that also varies with uv, so the graph keeps a shader body
// whichever way the caustics go.
std::string causticsGraph(const std::string& causticsOptions, const std::string& brighten) {
  return test::graphJson(
      R"({"id": "uv", "type": "uv"},
         {"id": "c", "type": "voronoi_caustics", )" + causticsOptions + R"( "inputs": {"p": "uv.out"}},
         {"id": "across", "type": "length", "inputs": {"x": "uv.out"}},
         {"id": "base", "type": "mix", "inputs": {"a": [0, 0.2, 0.4], "b": [0, 0.4, 0.6], "t": "across.out"}},
         {"id": "lit", "type": "add", "inputs": {"a": "base.out", "b": )" + brighten + R"(}})",
      R"("fragment": {"color": "lit.out"})");
}

TEST(BypassPass, ABypassedNodeCompilesToItsOffValueWiredByHand) {
  Diagnostics d1, d2, d3;
  auto bypassed = compileText(causticsGraph(R"("options": {"bypass": true},)", "\"c.caustics\""), d1);
  auto byHand = compileText(causticsGraph("", "0"), d2);
  auto on = compileText(causticsGraph("", "\"c.caustics\""), d3);
  ASSERT_TRUE(bypassed && byHand && on) << errors(d1) << errors(d2) << errors(d3);
  EXPECT_EQ(fragmentOf(*bypassed), fragmentOf(*byHand));
  EXPECT_NE(fragmentOf(*on), fragmentOf(*byHand));  // the caustics really were in the shader
  EXPECT_NE(fragmentOf(*on).find("voronoi"), std::string::npos);
  bool listed = false;
  for (const auto& r : bypassed->manifest.removed) listed |= r.what == "c" && r.reason == "bypassed";
  EXPECT_TRUE(listed) << "the manifest says why the node is gone";
}

TEST(BypassPass, WhatOnlyTheBypassedNodeNeededLeavesWithIt) {
  // texture_caustics samples a texture and reads the time: off, neither remains, and the
  // node feeding only it (the scaled position) is pruned.
  std::string graph = test::graphJson(
      R"({"id": "wp", "type": "world_position"},
         {"id": "scaled", "type": "mul", "inputs": {"a": "wp.out", "b": 2}},
         {"id": "c", "type": "texture_caustics", "options": {"bypass": true}, "inputs": {"position": "scaled.out"}},
         {"id": "lit", "type": "add", "inputs": {"a": [0, 0.3, 0.5], "b": "c.caustics"}})",
      R"("fragment": {"color": "lit.out"})");
  Diagnostics d;
  auto r = compileText(graph, d);
  ASSERT_TRUE(r) << errors(d);
  EXPECT_TRUE(r->manifest.textures.empty());
  EXPECT_TRUE(r->program.ops.empty()) << r->program.ops.size() << " ops left";
  std::set<std::string> removed;
  for (const auto& x : r->manifest.removed) removed.insert(x.what + ": " + x.reason);
  EXPECT_TRUE(removed.count("c: bypassed"));
  EXPECT_TRUE(removed.count("scaled: unreachable from the outputs")) << ::testing::PrintToString(removed);
}

TEST(BypassPass, AnInputPassesThroughAndChainsOfBypassedNodesResolve) {
  // normal_map_scroll off is its `normal` input; color_variation off is its `color` input,
  // here the bypassed normal itself: the output is the builtin normal.
  std::string graph = test::graphJson(
      R"({"id": "ripples", "type": "normal_map_scroll", "options": {"bypass": true}},
         {"id": "vary", "type": "color_variation", "options": {"bypass": true}, "inputs": {"color": "ripples.normal"}})",
      R"("fragment": {"color": "vary.color"})");
  Diagnostics d;
  auto r = compileText(graph, d);
  ASSERT_TRUE(r) << errors(d);
  const ProgramOutput* color = r->program.output(OutputSlot::FragmentColor);
  ASSERT_NE(color, nullptr);
  EXPECT_EQ(color->value.kind, ValueRef::Kind::Builtin);
  EXPECT_EQ(color->value.index, static_cast<int>(Builtin::Normal));
  EXPECT_TRUE(r->manifest.textures.empty()) << "the normal map is not sampled";
}

TEST(BypassPass, APresetSwitchesANodeOff) {
  std::string graph = causticsGraph("", "\"c.caustics\"");
  graph.insert(1, R"("presets": {"plain": {"c.bypass": true}}, )");
  Diagnostics d1, d2;
  auto plain = compileText(graph, d1, "plain");
  auto byHand = compileText(causticsGraph("", "0"), d2);
  ASSERT_TRUE(plain && byHand) << errors(d1) << errors(d2);
  EXPECT_EQ(fragmentOf(*plain), fragmentOf(*byHand));
}

}  // namespace
}  // namespace wg
