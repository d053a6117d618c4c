// The output transform's double reference (core/view_transform.h): the sRGB curve on both
// sides of its knee, each tone mapper at values worked out here from the published
// formulas, and the hard cases (0, 1, 1e4, +Inf, NaN, negatives) giving finite values in
// [0, 1]. The GPU pass is held to this reference in tests/runtime/output_transform_test.cpp.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "core/color_space.h"
#include "core/graph_io.h"
#include "core/view_transform.h"

namespace wg {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

Rgb grey(double v) { return {v, v, v}; }

TEST(ViewTransform, SrgbCurveOnBothSidesOfTheKnee) {
  // Below the knee the linear segment, above it the power: each value computed by hand.
  EXPECT_DOUBLE_EQ(linearToSrgb(0.0), 0.0);
  EXPECT_DOUBLE_EQ(linearToSrgb(0.001), 0.01292);
  EXPECT_NEAR(linearToSrgb(0.0031308), 0.0031308 * 12.92, 1e-15);  // the knee itself: the linear segment
  EXPECT_NEAR(linearToSrgb(0.0031309), 1.055 * std::pow(0.0031309, 1 / 2.4) - 0.055, 1e-15);
  EXPECT_NEAR(linearToSrgb(0.5), 0.735356983052, 1e-12);
  EXPECT_NEAR(linearToSrgb(1.0), 1.0, 1e-15);
  // The two segments meet at the knee (continuity within the standard's rounding of 12.92).
  EXPECT_NEAR(linearToSrgb(0.0031308), linearToSrgb(std::nextafter(0.0031308, 1.0)), 1e-7);
  // Decoding inverts it, below and above the knee; 128/255 is 0.2158605 linear.
  for (double e : {0.0, 0.02, 0.0405, 128 / 255.0, 1.0}) EXPECT_NEAR(linearToSrgb(srgbToLinear(e)), e, 1e-12) << e;
  // Between the standard's two knees (0.04045 encoded is 0.0031308049 linear, above the
  // encoder's 0.0031308) the round trip leaves by the other segment: off by 3e-8.
  EXPECT_NEAR(linearToSrgb(srgbToLinear(0.04045)), 0.04045, 4e-8);
  EXPECT_NEAR(srgbToLinear(128 / 255.0), 0.21586050011389926, 1e-12);
}

TEST(ViewTransform, PictureValuesOfTheIssue) {
  // A linear 0.5 is the 8-bit 188; the sRGB 128 of a texture comes back as 128.
  const ViewTransform none;
  EXPECT_EQ(std::lround(255 * outputTransform(none, grey(0.5))[0]), 188);
  EXPECT_EQ(std::lround(255 * outputTransform(none, grey(srgbToLinear(128 / 255.0)))[0]), 128);
}

TEST(ViewTransform, NoneClampsAndExposureScales) {
  ViewTransform v;
  EXPECT_DOUBLE_EQ(outputTransform(v, grey(4.0))[1], 1.0);
  v.exposureEv = -2;  // 4 x 2^-2 = 1
  EXPECT_NEAR(outputTransform(v, grey(4.0))[1], 1.0, 1e-15);
  v.exposureEv = -3;  // 0.5
  EXPECT_NEAR(outputTransform(v, grey(4.0))[1], linearToSrgb(0.5), 1e-15);
}

TEST(ViewTransform, AcesFitAtWorkedValues) {
  // Grey stays grey through the input matrix (its rows sum to 1), so the fit alone gives
  // the value: v (v + 0.0245786) - 0.000090537 over v (0.983729 v + 0.4329510) + 0.238081.
  auto fit = [](double v) { return (v * (v + 0.0245786) - 0.000090537) / (v * (0.983729 * v + 0.4329510) + 0.238081); };
  for (double v : {0.18, 1.0, 4.0}) {
    // and the output matrix's rows sum to 1 within 1e-5.
    EXPECT_NEAR(toneMap(ToneMapper::Aces, grey(v))[0], fit(v), 2e-5) << v;
  }
  // A linear 4 is below white (the issue's check), 1e4 is white.
  EXPECT_LT(toneMap(ToneMapper::Aces, grey(4.0))[0], 0.95);
  EXPECT_DOUBLE_EQ(toneMap(ToneMapper::Aces, grey(1e4))[0], 1.0);
  EXPECT_DOUBLE_EQ(toneMap(ToneMapper::Aces, grey(0.0))[0], 0.0);  // the fit's -0.00038 at 0, clamped
}

TEST(ViewTransform, AgxWindowAndPolynomial) {
  // Grey: the inset matrix's rows sum to 1 (no hue shift), so x = (log2 v + 12.47393) / 16.499999.
  auto expected = [](double v) {
    double x = (std::clamp(std::log2(v), -12.47393, 4.026069) + 12.47393) / (4.026069 + 12.47393);
    double x2 = x * x, x4 = x2 * x2;
    double s = 15.5 * x4 * x2 - 40.14 * x4 * x + 31.96 * x4 - 6.868 * x2 * x + 0.4298 * x2 + 0.1191 * x - 0.00232;
    return std::pow(std::clamp(s, 0.0, 1.0), 2.2);
  };
  // The matrices' rows sum to 1 only within 1.8e-4 (inset 1.000137, outset 0.999828 for
  // red), which the 2.2 power turns into at most 4e-4 of the value: grey is not exactly grey.
  for (double v : {0.0001, 0.18, 1.0, 16.0})
    EXPECT_NEAR(toneMap(ToneMapper::Agx, grey(v))[0], expected(v), 4e-4 * expected(v) + 1e-12) << v;
  // Above the window's top (2^4.03 = 16.3) every value is the same: the log clamp is reached.
  EXPECT_DOUBLE_EQ(toneMap(ToneMapper::Agx, grey(100.0))[0], toneMap(ToneMapper::Agx, grey(1e4))[0]);
  EXPECT_GT(toneMap(ToneMapper::Agx, grey(16.0))[0], toneMap(ToneMapper::Agx, grey(8.0))[0]);
}

TEST(ViewTransform, NeutralIsTheIdentityBelowItsKneeAndCompressesAbove) {
  // Below min(rgb) 0.08 the offset is x - 6.25 x^2; with min 0.1 it is 0.04.
  const Rgb c{0.3, 0.2, 0.1};
  Rgb out = toneMap(ToneMapper::Neutral, c);
  EXPECT_NEAR(out[0], 0.26, 1e-15);
  EXPECT_NEAR(out[2], 0.06, 1e-15);
  const Rgb dark{0.05, 0.05, 0.05};
  EXPECT_NEAR(toneMap(ToneMapper::Neutral, dark)[0], 0.05 - (0.05 - 6.25 * 0.0025), 1e-15);
  // Above the knee (peak 0.76 after the offset): grey 4 -> peak 3.96, compressed to
  // 1 - 0.24^2 / (3.96 + 0.24 - 0.76), desaturated towards it (grey stays grey).
  const double newPeak = 1 - 0.24 * 0.24 / (3.96 + 0.24 - 0.76);
  EXPECT_NEAR(toneMap(ToneMapper::Neutral, grey(4.0))[0], newPeak, 1e-12);
  EXPECT_LT(newPeak, 1.0);
}

TEST(ViewTransform, HardCasesGiveFiniteValuesInTheUnitRange) {
  for (ToneMapper t : {ToneMapper::None, ToneMapper::Aces, ToneMapper::Agx, ToneMapper::Neutral})
    for (double ev : {kMinExposureEv, 0.0, kMaxExposureEv})
      for (double v : {0.0, 0.0031308, 1.0, 1e4, kInf, kNaN, -1.0, -kInf, 1e-30}) {
        ViewTransform view{t, ev};
        Rgb out = outputTransform(view, {v, 0.5, v});
        for (double c : out) {
          EXPECT_TRUE(std::isfinite(c)) << toneMapperName(t) << " " << ev << " " << v;
          EXPECT_GE(c, 0.0);
          EXPECT_LE(c, 1.0);
        }
      }
  // NaN and negatives are black, +Inf the largest half float.
  EXPECT_EQ(sanitiseRadiance(kNaN), 0.0);
  EXPECT_EQ(sanitiseRadiance(-3.0), 0.0);
  EXPECT_EQ(sanitiseRadiance(kInf), kLargestHalf);
  EXPECT_NEAR(outputTransform({}, grey(kInf))[0], 1.0, 1e-15);
  EXPECT_EQ(outputTransform({}, grey(kNaN))[0], 0.0);
}

TEST(ViewTransform, NamesRoundTrip) {
  for (std::string_view n : toneMapperNames()) EXPECT_EQ(toneMapperName(*parseToneMapper(n)), n);
  EXPECT_FALSE(parseToneMapper("filmic"));
  EXPECT_EQ(toneMapperList(), "none, aces, agx or neutral");
}

// A graph's "view": read with its members' positions, written back by fmt in canonical
// form, absent when the graph states none (the default then is none, 0 EV).
TEST(GraphView, LoadsSavesAndRoundTrips) {
  const std::string text = R"({"version": 1, "name": "v", "view": {"exposure": -1.5, "tonemap": "neutral"},
    "nodes": [], "outputs": {"fragment": {"color": [1, 0, 0]}}})";
  Diagnostics diags;
  auto g = parseGraph(text, "v.json", diags);
  ASSERT_TRUE(g);
  ASSERT_TRUE(g->view);
  EXPECT_EQ(g->view->toneMapper, ToneMapper::Neutral);
  EXPECT_EQ(g->view->exposureEv, -1.5);
  const std::string saved = saveGraph(*g);
  EXPECT_NE(saved.find("\"view\": {\"tonemap\": \"neutral\", \"exposure\": -1.5}"), std::string::npos) << saved;
  auto again = parseGraph(saved, "v.json", diags);
  ASSERT_TRUE(again && again->view);
  EXPECT_EQ(*again->view, *g->view);
  EXPECT_EQ(saveGraph(*again), saved);
  auto none = parseGraph(R"({"version": 1, "name": "v", "nodes": [], "outputs": {}})", "v.json", diags);
  ASSERT_TRUE(none);
  EXPECT_FALSE(none->view);
  EXPECT_EQ(saveGraph(*none).find("view"), std::string::npos);
}

TEST(GraphView, ErrorsPointAtTheValue) {
  struct Bad {
    const char* view;
    const char* message;
    int column;
  };
  for (const Bad& b : {Bad{R"({"tonemap": "reinhard"})", "unknown tone mapper 'reinhard'", 49},
                       Bad{R"({"exposure": 20.5})", "exposure 20.5 EV in 'view' is outside [-20, 20]", 50},
                       Bad{R"({"exposure": "bright"})", "must be a number", 50},
                       Bad{R"({"gamma": 2.2})", "unknown field 'gamma'", 38}}) {
    Diagnostics diags;
    const std::string text = std::string(R"({"version": 1, "name": "v", "view": )") + b.view +
                             R"(, "nodes": [], "outputs": {"fragment": {"color": [1, 0, 0]}}})";
    EXPECT_FALSE(parseGraph(text, "v.json", diags)) << b.view;
    ASSERT_FALSE(diags.all().empty()) << b.view;
    const std::string line = formatText(diags.all().front());
    EXPECT_NE(line.find(b.message), std::string::npos) << line;
    EXPECT_NE(line.find("v.json:1:" + std::to_string(b.column) + ":"), std::string::npos) << line;
  }
}

}  // namespace
}  // namespace wg
