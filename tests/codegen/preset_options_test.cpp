// Presets that set node options ("detail.octaves": 2): loaded with their positions, checked
// against the node's type whichever preset is applied, applied by compile --preset and by
// the editor, and saved in file order. A preset compiles to exactly what the graph compiles
// to with the option written on the node.
#include <gtest/gtest.h>

#include "codegen/compile.h"
#include "core/graph_edit.h"
#include "core/graph_io.h"
#include "core/preset.h"
#include "nodes/registry.h"

namespace wg {
namespace {

// Quality levels of a noise graph: `fast` takes fewer octaves and moves the bias.
std::string noiseGraph(const std::string& fastPreset, const std::string& fbmOptions = "") {
  return R"({
  "version": 1, "name": "noise",
  "parameters": {"bias": {"type": "float", "default": 0.5, "min": 0, "max": 1}},
  "presets": {
    "fast": {)" + fastPreset + R"(}
  },
  "nodes": [
    {"id": "uv", "type": "uv"},
    {"id": "detail", "type": "fbm", )" + (fbmOptions.empty() ? "" : "\"options\": {" + fbmOptions + "}, ") +
         R"("inputs": {"p": "uv.out"}},
    {"id": "sum", "type": "add", "inputs": {"a": "detail.value", "b": "$bias"}}
  ],
  "outputs": {"fragment": {"color": "sum.out"}}
})";
}

std::optional<Graph> load(const std::string& text, Diagnostics& d) { return parseGraph(text, "noise.json", d); }

std::string firstError(const Diagnostics& d) { return d.all().empty() ? "" : formatText(d.all().front()); }

std::optional<CompileResult> compile(const Graph& g, const std::string& preset, Diagnostics& d) {
  CompileOptions options;
  options.validate = false;
  options.preset = preset;
  return compileGraph(g, defaultRegistry(), options, d);
}

std::string fragmentOf(const CompileResult& r) {
  for (const auto& f : r.files)
    if (f.name == "noise.glsl330.frag") return f.contents;
  return "";
}

TEST(PresetOptions, LoadWithTheirNodeOptionAndPositions) {
  Diagnostics d;
  auto g = load(noiseGraph(R"("detail.octaves": 2, "bias": 0.25)"), d);
  ASSERT_TRUE(g) << firstError(d);
  const Preset& fast = g->presets.at(0);
  ASSERT_EQ(fast.values.size(), 2u);
  EXPECT_TRUE(fast.values[0].isOption());
  EXPECT_EQ(fast.values[0].node, "detail");
  EXPECT_EQ(fast.values[0].option, "octaves");
  EXPECT_EQ(fast.values[0].optionValue, 2);
  EXPECT_EQ(fast.values[0].keyWhere.line, 5);
  EXPECT_EQ(fast.values[0].keyWhere.col, 14);
  EXPECT_EQ(fast.values[0].where.col, 32);
  EXPECT_FALSE(fast.values[1].isOption());
}

TEST(PresetOptions, CompileToWhatTheOptionWrittenOnTheNodeCompilesTo) {
  Diagnostics d;
  auto withPreset = load(noiseGraph(R"("detail.octaves": 2, "bias": 0.25)"), d);
  auto written = load(noiseGraph(R"("bias": 0.25)", R"("octaves": 2)"), d);
  auto plain = load(noiseGraph(R"("bias": 0.25)"), d);
  ASSERT_TRUE(withPreset && written && plain) << firstError(d);
  auto a = compile(*withPreset, "fast", d);
  auto b = compile(*written, "fast", d);
  auto c = compile(*plain, "fast", d);
  ASSERT_TRUE(a && b && c) << firstError(d);
  EXPECT_EQ(fragmentOf(*a), fragmentOf(*b));
  EXPECT_NE(fragmentOf(*a), fragmentOf(*c)) << "four octaves (the default) and two must differ";
  EXPECT_EQ(a->manifest.preset, "fast");
  // Without the preset the node keeps its own options.
  auto none = compile(*withPreset, "", d);
  ASSERT_TRUE(none);
  EXPECT_EQ(fragmentOf(*none), fragmentOf(*compile(*plain, "", d)));
}

TEST(PresetOptions, ReplaceAnOptionWrittenOnTheNode) {
  Diagnostics d;
  auto g = load(noiseGraph(R"("detail.octaves": 2)", R"("octaves": 6)"), d);
  ASSERT_TRUE(g) << firstError(d);
  ASSERT_TRUE(applyPreset(*g, "fast", d));
  const Node* n = g->findNode("detail");
  ASSERT_EQ(n->options.size(), 1u);
  EXPECT_EQ(n->options[0].value, 2);
  EXPECT_EQ(n->options[0].where.line, 5) << "the value keeps the preset's position";
}

TEST(PresetOptions, AnUnknownNodeIsReportedAtTheKeyByTheLoader) {
  Diagnostics d;
  EXPECT_FALSE(load(noiseGraph(R"("detial.octaves": 2)"), d));
  EXPECT_EQ(firstError(d),
            "noise.json:5:14: error: [WG024] preset 'fast' sets an option of node 'detial', which the graph does not have "
            "(did you mean 'detail'?)");
}

TEST(PresetOptions, AKeyThatIsNotNodeDotOptionIsRefused) {
  for (const char* key : {"detail.octaves.x", ".octaves", "detail.", "detail.2x"}) {
    Diagnostics d;
    EXPECT_FALSE(load(noiseGraph("\"" + std::string(key) + "\": 2"), d)) << key;
    EXPECT_NE(firstError(d).find("noise.json:5:14: error: [WG008]"), std::string::npos) << key << ": " << firstError(d);
  }
}

// Whichever preset is applied (or none), every preset's options are checked.
TEST(PresetOptions, AnOptionTheTypeLacksOrAValueItRefusesIsReportedInThePreset) {
  Diagnostics d;
  auto g = load(noiseGraph(R"("detail.octave": 2)"), d);
  ASSERT_TRUE(g) << firstError(d);
  EXPECT_FALSE(compile(*g, "", d));
  EXPECT_EQ(firstError(d),
            "noise.json:5:14: error: [WG022] preset 'fast': node type 'fbm' has no option 'octave' (did you mean "
            "'octaves'?) (node 'detail', option 'octave')");

  Diagnostics d2;
  auto g2 = load(noiseGraph(R"("detail.octaves": 12)"), d2);
  ASSERT_TRUE(g2);
  EXPECT_FALSE(compile(*g2, "", d2));
  EXPECT_EQ(firstError(d2), "noise.json:5:32: error: [WG030] preset 'fast': option 'octaves' 12 is above the maximum 8 (node 'detail', "
                            "option 'octaves')");
  // Applied, the value is the node's option, and is reported once, at the preset.
  Diagnostics d3;
  EXPECT_FALSE(compile(*g2, "fast", d3));
  ASSERT_EQ(d3.errorCount(), 1u) << firstError(d3);
  EXPECT_NE(firstError(d3).find("noise.json:5:32: error: [WG030]"), std::string::npos) << firstError(d3);
}

TEST(PresetOptions, SavedInFileOrderAndReadBack) {
  Diagnostics d;
  auto g = load(noiseGraph(R"("bias": 0.25, "detail.octaves": 2)"), d);
  ASSERT_TRUE(g);
  std::string text = saveGraph(*g);
  EXPECT_NE(text.find("\"fast\": {\"bias\": 0.25, \"detail.octaves\": 2}"), std::string::npos) << text;
  auto back = parseGraph(text, "noise.json", d);
  ASSERT_TRUE(back) << firstError(d);
  EXPECT_EQ(saveGraph(*back), text);
}

TEST(PresetOptions, TheEditorAppliesThemAsOneUndoableEdit) {
  Diagnostics d;
  auto g = load(noiseGraph(R"("detail.octaves": 2, "bias": 0.25)"), d);
  ASSERT_TRUE(g);
  GraphEditor e(*g);
  EXPECT_EQ(e.applyPreset("fast"), "");
  ASSERT_EQ(e.graph().findNode("detail")->options.size(), 1u);
  EXPECT_EQ(e.graph().findNode("detail")->options[0].value, 2);
  EXPECT_EQ(e.graph().findParameter("bias")->defaultValue, (std::vector<double>{0.25}));
  ASSERT_TRUE(e.undo());
  EXPECT_TRUE(e.graph().findNode("detail")->options.empty());
}

}  // namespace
}  // namespace wg
