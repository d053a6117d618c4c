// Graph-level presets: loaded with positions, saved in the canonical form, applied by name.
#include <gtest/gtest.h>

#include "core/graph_io.h"
#include "core/preset.h"

namespace wg {
namespace {

const char* kWeather = R"({
  "version": 1, "name": "weather",
  "parameters": {
    "height": {"type": "float", "default": 0.5, "min": 0, "max": 1, "static": true},
    "tint": {"type": "vec3", "default": [0, 0.2, 0.4]}
  },
  "presets": {
    "choppy": {"tint": [0.1, 0.3, 0.5], "height": 1},
    "calm": {"height": 0.1}
  },
  "nodes": [{"id": "u", "type": "uv"}],
  "outputs": {"fragment": {"color": "$tint"}}
})";

Graph parsePresetGraph(const std::string& text) {
  Diagnostics d;
  auto g = parseGraph(text, "w.json", d);
  EXPECT_TRUE(g) << (d.all().empty() ? "" : formatText(d.all().front()));
  return g ? *g : Graph{};
}

TEST(Presets, LoadInFileOrderWithPositions) {
  Graph g = parsePresetGraph(kWeather);
  ASSERT_EQ(g.presets.size(), 2u);
  EXPECT_EQ(g.presets[0].name, "choppy");
  EXPECT_EQ(g.presets[1].name, "calm");
  ASSERT_EQ(g.presets[0].values.size(), 2u);
  EXPECT_EQ(g.presets[0].values[0].parameter, "tint");
  EXPECT_EQ(g.presets[0].values[0].value, (std::vector<double>{0.1, 0.3, 0.5}));
  EXPECT_EQ(g.presets[0].where.line, 8);
  EXPECT_EQ(g.presets[0].where.col, 5);
}

TEST(Presets, SaveKeepsThemAndRoundTrips) {
  Graph g = parsePresetGraph(kWeather);
  std::string text = saveGraph(g);
  EXPECT_NE(text.find("\"presets\": {\n    \"choppy\": {\"tint\": [0.1, 0.3, 0.5], \"height\": 1}"),
            std::string::npos)
      << text;
  // Between the parameters and the nodes, as docs/graph-format.md lists the keys.
  EXPECT_LT(text.find("\"parameters\""), text.find("\"presets\""));
  EXPECT_LT(text.find("\"presets\""), text.find("\"nodes\""));
  EXPECT_EQ(saveGraph(parsePresetGraph(text)), text);
}

TEST(Presets, ApplyMakesTheValuesDefaults) {
  Graph g = parsePresetGraph(kWeather);
  Diagnostics d;
  ASSERT_TRUE(applyPreset(g, "choppy", d));
  EXPECT_EQ(g.findParameter("height")->defaultValue, (std::vector<double>{1}));
  EXPECT_EQ(g.findParameter("tint")->defaultValue, (std::vector<double>{0.1, 0.3, 0.5}));
  ASSERT_TRUE(applyPreset(g, "calm", d));
  EXPECT_EQ(g.findParameter("height")->defaultValue, (std::vector<double>{0.1}));
  EXPECT_EQ(g.findParameter("tint")->defaultValue, (std::vector<double>{0.1, 0.3, 0.5})) << "calm leaves tint";
  EXPECT_TRUE(d.empty());
}

TEST(Presets, UnknownNameIsWG052ListingThePresets) {
  Graph g = parsePresetGraph(kWeather);
  Graph before = g;
  Diagnostics d;
  EXPECT_FALSE(applyPreset(g, "clam", d));
  ASSERT_EQ(d.all().size(), 1u);
  std::string line = formatText(d.all()[0]);
  EXPECT_NE(line.find("[WG052]"), std::string::npos) << line;
  EXPECT_NE(line.find("did you mean 'calm'?"), std::string::npos) << line;
  EXPECT_NE(line.find("its presets: choppy, calm"), std::string::npos) << line;
  EXPECT_EQ(line.rfind("w.json:8:5: error:", 0), 0u) << line;
  EXPECT_EQ(saveGraph(g), saveGraph(before)) << "the graph is left unchanged";
}

TEST(Presets, AGraphWithoutPresetsSaysSo) {
  Graph g = parsePresetGraph(R"({"version": 1, "name": "n", "nodes": [], "outputs": {"fragment": {"color": [1, 0, 0]}}})");
  Diagnostics d;
  EXPECT_FALSE(applyPreset(g, "calm", d));
  ASSERT_EQ(d.all().size(), 1u);
  EXPECT_NE(formatText(d.all()[0]).find("it defines no presets"), std::string::npos);
}

}  // namespace
}  // namespace wg
