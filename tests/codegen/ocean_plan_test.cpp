// The spectral ocean in the compiler: ocean_spectrum feeds its readers through `ocean`
// ports, the planner lists each ocean and only the maps the reached readers sample, the
// manifest carries both and reads back, and meaningless settings are errors at their option.
#include <gtest/gtest.h>

#include <string>

#include "codegen/compile.h"
#include "core/diagnostic.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg {
namespace {

// A sea and its readers; `sea` is the spectrum's options, `extraNodes` more nodes, and the
// vertex position and fragment colour come from `position` and `color`.
std::string seaGraph(const std::string& sea, const std::string& position, const std::string& color,
                     const std::string& extraNodes = "") {
  return R"({"version": 1, "name": "sea_test", "nodes": [
    {"id": "sea", "type": "ocean_spectrum", "options": )" + sea + R"(},
    {"id": "moved", "type": "ocean_displacement", "inputs": {"ocean": "sea.ocean"}},
    {"id": "detail", "type": "ocean_surface", "inputs": {"ocean": "sea.ocean", "position": "moved.undisplaced"}},
    {"id": "j", "type": "mul", "inputs": {"a": "detail.jacobian", "b": [1, 1, 1]}})" +
         extraNodes + R"(],
    "outputs": {"vertex": {"position": ")" + position + R"("}, "fragment": {"color": ")" + color + R"("}}})";
}

std::string messages(const Diagnostics& diags) {
  std::string out;
  for (const auto& d : diags.sorted()) out += formatText(d) + "\n";
  return out;
}

std::optional<CompileResult> compileSea(const std::string& text, Diagnostics& diags,
                                        std::vector<Target> targets = {Target::Glsl330}) {
  auto graph = parseGraph(text, "sea.json", diags);
  if (!graph) return std::nullopt;
  CompileOptions o;
  o.targets = std::move(targets);
  return compileGraph(*graph, defaultRegistry(), o, diags);
}

std::vector<std::string> textureNames(const Manifest& m) {
  std::vector<std::string> names;
  for (const auto& t : m.textures) names.push_back(t.name);
  return names;
}

TEST(OceanPlan, OpenOceanCompilesForEveryTargetWithItsSimulationPlanned) {
  Diagnostics diags;
  auto graph = loadGraphFile(test::sourcePath("graphs/open_ocean.json"), diags);
  ASSERT_TRUE(graph) << messages(diags);
  CompileOptions o;
  o.targets = {Target::Glsl330, Target::Es300, Target::Vk450};
  o.validate = true;
  auto result = compileGraph(*graph, defaultRegistry(), o, diags);
  ASSERT_TRUE(result) << messages(diags);
  const Manifest& m = result->manifest;
  ASSERT_EQ(m.oceans.size(), 1u);
  EXPECT_EQ(m.oceans[0].nodeId, "sea");
  EXPECT_EQ(m.oceans[0].options.at("tile_lengths"), nlohmann::json::parse("[120, 24, 5]"));
  ASSERT_FALSE(m.passes.empty());
  EXPECT_EQ(m.passes.front(), RenderPass::OceanSimulation);
  // Three cascades, each with both maps (the vertex normal and the fragment normal read the slopes).
  for (int c = 0; c < 3; ++c)
    for (const char* map : {"displacement", "slopes"}) {
      std::string name = "u_ocean0_" + std::string(map) + std::to_string(c);
      auto names = textureNames(m);
      EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
    }
  // The persistent foam of the two longest cascades (foam_cascades 2), none of the third.
  auto names = textureNames(m);
  for (int c = 0; c < 3; ++c)
    EXPECT_EQ(std::find(names.begin(), names.end(), "u_ocean0_foam" + std::to_string(c)) != names.end(), c < 2) << c;
  // The manifest reads back as written.
  Manifest back = Manifest::fromJson(m.toJson());
  EXPECT_EQ(back.fileText(), m.fileText());
}

TEST(OceanPlan, OnlyTheMapsTheReachedReadersSampleAreDeclared) {
  Diagnostics diags;
  // Only the displaced position: no normal, so no slope map; no ocean_surface.
  auto result = compileSea(seaGraph(R"({"tile_lengths": [100, 10]})", "moved.position", "moved.position"), diags);
  ASSERT_TRUE(result) << messages(diags);
  EXPECT_EQ(textureNames(result->manifest),
            (std::vector<std::string>{"u_ocean0_displacement0", "u_ocean0_displacement1"}));
  // A graph whose outputs reach no reader has no ocean, no map and no simulation pass.
  Diagnostics d2;
  auto none = compileSea(seaGraph("{}", "moved.undisplaced", "moved.undisplaced"), d2);
  ASSERT_TRUE(none) << messages(d2);
  EXPECT_TRUE(none->manifest.oceans.empty());
  EXPECT_TRUE(none->manifest.textures.empty());
  EXPECT_FALSE(none->manifest.lists(RenderPass::OceanSimulation));
}

TEST(OceanPlan, EqualSpectraAreOneOceanAndDifferentOnesTwo) {
  const std::string second = R"(,
    {"id": "sea2", "type": "ocean_spectrum", "options": SEA2},
    {"id": "moved2", "type": "ocean_displacement", "inputs": {"ocean": "sea2.ocean", "position": "moved.position"}})";
  auto withSecond = [&](const std::string& options) {
    std::string nodes = second;
    nodes.replace(nodes.find("SEA2"), 4, options);
    return seaGraph(R"({"wind_speed": 8})", "moved2.position", "moved2.position", nodes);
  };
  Diagnostics diags;
  auto same = compileSea(withSecond(R"({"wind_speed": 8})"), diags);
  ASSERT_TRUE(same) << messages(diags);
  EXPECT_EQ(same->manifest.oceans.size(), 1u);
  auto different = compileSea(withSecond(R"({"wind_speed": 9})"), diags);
  ASSERT_TRUE(different) << messages(diags);
  ASSERT_EQ(different->manifest.oceans.size(), 2u);
  EXPECT_EQ(different->manifest.textures.size(), 6u);  // 3 cascades of displacement each
}

struct BadSetting {
  std::string options;  // the spectrum's options
  std::string option;   // the option the error names
  int line, col;        // where: the option's value, or the node's '{' for a default
};

class OceanPlanBadSetting : public ::testing::TestWithParam<BadSetting> {};

TEST_P(OceanPlanBadSetting, IsAnErrorAtItsOption) {
  const BadSetting& b = GetParam();
  Diagnostics diags;
  auto result = compileSea(seaGraph(b.options, "moved.position", "moved.position"), diags);
  EXPECT_FALSE(result);
  ASSERT_TRUE(diags.hasErrors());
  const std::string text = messages(diags);
  EXPECT_NE(text.find("sea.json:" + std::to_string(b.line) + ":" + std::to_string(b.col) + ": error: [WG"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("option '" + b.option + "'"), std::string::npos) << text;
  EXPECT_NE(text.find("sea"), std::string::npos) << text;
}

// The options object starts at line 2, column 56 of seaGraph's text; each value's column
// follows from the text written.
INSTANTIATE_TEST_SUITE_P(
    Settings, OceanPlanBadSetting,
    ::testing::Values(BadSetting{R"({"fetch": 0})", "fetch", 2, 66},
                      BadSetting{R"({"fft_size": 100})", "fft_size", 2, 69},
                      BadSetting{R"({"fft_size": 1024})", "fft_size", 2, 69},
                      BadSetting{R"({"tile_lengths": [10, 100]})", "tile_lengths", 2, 73},
                      BadSetting{R"({"tile_lengths": [1000, 5]})", "tile_lengths", 2, 73},  // 200 times: past N/2 - 1 = 127
                      BadSetting{R"({"tile_lengths": []})", "tile_lengths", 2, 73},
                      BadSetting{R"({"seed": 4294967296})", "seed", 2, 65},
                      BadSetting{R"({"seed": 1.5})", "seed", 2, 65},
                      BadSetting{R"({"wind_speed": 101})", "wind_speed", 2, 71},
                      BadSetting{R"({"depth": 0})", "depth", 2, 66},
                      // At the default resolution 256 the tiles are fine; at 64 they are not.
                      BadSetting{R"({"fft_size": 64, "tile_lengths": [1000, 20]})", "tile_lengths", 2, 89}));

TEST(OceanPlan, AnOceanPortTakesOnlyAnOcean) {
  Diagnostics diags;
  auto result = compileSea(seaGraph("{}", "moved.position", "moved.position",
                                    R"(, {"id": "bad", "type": "ocean_displacement", "inputs": {"ocean": "j.out"}})"),
                           diags);
  EXPECT_FALSE(result);
  EXPECT_NE(messages(diags).find("ocean"), std::string::npos) << messages(diags);
}

}  // namespace
}  // namespace wg
