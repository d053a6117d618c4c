// Colour parameters as the loader reads them (docs/graph-format.md, "Colour"): "color" and
// "hdr_color" are the hints; an sRGB colour's default, min, max and preset values lie
// within [0, 1] (WG011 at the value, naming the parameter); an HDR colour's may exceed 1.
#include <gtest/gtest.h>

#include <string>

#include "core/graph_io.h"
#include "diagnostic_text.h"
#include "test_support.h"

namespace wg {
namespace {

std::string graphWithParameter(const std::string& parameter, const std::string& presets = "") {
  return R"({"version": 1, "name": "g",
"parameters": {"tint": )" + parameter + R"(},
)" + (presets.empty() ? std::string() : R"("presets": )" + presets + ",\n") +
         R"("nodes": [], "outputs": {"fragment": {"color": "$tint"}}})";
}

std::string errors(const std::string& json) {
  Diagnostics diags;
  parseGraph(json, "colors.json", diags);
  std::string s;
  for (const auto& d : diags.sorted()) s += formatText(d) + "\n";
  return s;
}

TEST(ColorHintLoad, AnSrgbColourWithinTheUnitRangeLoads) {
  EXPECT_EQ(errors(graphWithParameter(R"({"type": "vec3", "default": [0, 0.5, 1], "min": 0, "max": 1, "hint": "color"})")), "");
  EXPECT_EQ(errors(graphWithParameter(R"({"type": "vec4", "default": [0, 0.5, 1, 1], "hint": "color"})")), "");
}

TEST(ColorHintLoad, ADefaultAboveOneIsAnErrorAtTheValueNamingTheParameter) {
  std::string e = errors(graphWithParameter(R"({"type": "vec3", "default": [0.5, 1.5, 0], "hint": "color"})"));
  // Line 2, the default's '[' at column 52.
  EXPECT_EQ(e,
            "colors.json:2:52: error: [WG011] the default of parameter 'tint' 1.5 (component 1) lies outside [0, 1], the "
            "range of an sRGB colour (hint \"color\"); a colour brighter than white takes the hint \"hdr_color\"\n");
}

TEST(ColorHintLoad, ANegativeComponentAndARangeBeyondTheUnitAreErrors) {
  EXPECT_NE(errors(graphWithParameter(R"({"type": "vec3", "default": [-0.1, 0, 0], "hint": "color"})")).find("[WG011] the default of parameter 'tint' -0.1"),
            std::string::npos);
  std::string e = errors(graphWithParameter(R"({"type": "vec3", "default": [0, 0, 0], "min": 0, "max": 2, "hint": "color"})"));
  EXPECT_NE(e.find("colors.json:2:80: error: [WG011] 'max' of parameter 'tint' 2 lies outside [0, 1]"), std::string::npos) << e;
  e = errors(graphWithParameter(R"({"type": "vec3", "default": [0, 0, 0], "min": -1, "hint": "color"})"));
  EXPECT_NE(e.find("[WG011] 'min' of parameter 'tint' -1 lies outside [0, 1]"), std::string::npos) << e;
}

TEST(ColorHintLoad, APresetValueBeyondTheUnitIsAnError) {
  std::string e = errors(graphWithParameter(R"({"type": "vec3", "default": [0, 0, 0], "hint": "color"})",
                                            R"({"bright": {"tint": [2, 0, 0]}})"));
  EXPECT_NE(e.find("colors.json:3:32: error: [WG011] the value of 'tint' in preset 'bright' 2 (component 0) lies outside [0, 1]"),
            std::string::npos)
      << e;
}

TEST(ColorHintLoad, AnHdrColourMayExceedOne) {
  EXPECT_EQ(errors(graphWithParameter(R"({"type": "vec3", "default": [4, 4, 4], "hint": "hdr_color"})",
                                      R"({"sunny": {"tint": [10, 9, 8]}})")),
            "");
}

TEST(ColorHintLoad, DataHasNoRangeOfItsOwnAndUnknownHintsNameTheTwo) {
  EXPECT_EQ(errors(graphWithParameter(R"({"type": "vec3", "default": [4, -4, 0]})")), "");
  std::string e = errors(graphWithParameter(R"({"type": "vec3", "default": [0, 0, 0], "hint": "hdr"})"));
  EXPECT_NE(e.find("[WG011] unknown hint 'hdr' on parameter 'tint' (the hints are \"color\" and \"hdr_color\")"), std::string::npos) << e;
  e = errors(graphWithParameter(R"({"type": "vec2", "default": [0, 0], "hint": "hdr_color"})"));
  EXPECT_NE(e.find("the \"hdr_color\" hint on parameter 'tint' needs type vec3 or vec4"), std::string::npos) << e;
}

}  // namespace
}  // namespace wg
