// The math vocabulary (nodes/math_rounding.cpp, math_exp_log.cpp, math_trig.cpp,
// math_vector.cpp, math_compare.cpp): each family's double reference against an oracle
// written here from GLSL's definitions and the documented guards, on floats and
// component-wise on vec3 (a float splatting to the vector), and the hard inputs the
// finite-output promise names, each to its documented value.
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

#include <gtest/gtest.h>

#include "node_eval.h"

namespace wg {
namespace {

using test::runNode;

constexpr double kFltMin = std::numeric_limits<float>::min();

// Arguments that reach every branch: signs, zero, halves, integers, tiny, huge, a float
// denormal, and values past the guards' thresholds (88, 127, 1 for asin).
const std::vector<double>& samples() {
  static const std::vector<double> v = {-1e30, -100, -7.5, -2.5, -1.0000001, -1, -0.5, -1e-8, -1e-40, 0,
                                        1e-40, 1e-8, 0.3, 0.5, 1, 1.0000001, 1.5, 2.5, 3.7, 88.5, 130, 1e30};
  return v;
}

// |got - want| within `rel` of max(1, |want|), with equal infinities/NaNs refused.
::testing::AssertionResult agrees(double got, double want, double rel, const std::string& what) {
  if (!std::isfinite(got)) return ::testing::AssertionFailure() << what << ": not finite (" << got << ")";
  if (std::abs(got - want) <= rel * std::max(1.0, std::abs(want))) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << what << ": got " << got << ", the oracle says " << want;
}

// The node on a float, and on vec3 (x, x/3, -x) whose components must each be the oracle.
void unaryAgainst(const std::string& type, const std::function<double(double)>& oracle, double rel = 1e-15) {
  for (double x : samples()) {
    std::string at = type + "(" + std::to_string(x) + ")";
    EXPECT_TRUE(agrees(runNode(type, {{"x", Value::scalar(x)}}).first(), oracle(x), rel, at));
    Value v = Value::vector({x, x / 3, -x});
    Value out = runNode(type, {{"x", v}}).values[0];
    ASSERT_EQ(out.size(), 3) << at;
    for (int i = 0; i < 3; ++i) EXPECT_TRUE(agrees(out[i], oracle(v[i]), rel, at + " component " + std::to_string(i)));
  }
}

// A binary node over every pair of samples, as floats and as vec3 against a float (splat).
void binaryAgainst(const std::string& type, const std::string& a, const std::string& b,
                   const std::function<double(double, double)>& oracle, double rel = 1e-15) {
  for (double x : samples())
    for (double y : samples()) {
      std::string at = type + "(" + a + " = " + std::to_string(x) + ", " + b + " = " + std::to_string(y) + ")";
      EXPECT_TRUE(agrees(runNode(type, {{a, Value::scalar(x)}, {b, Value::scalar(y)}}).first(), oracle(x, y), rel, at));
      Value out = runNode(type, {{a, Value::vector({x, 2 * x, -x})}, {b, Value::scalar(y)}}).values[0];
      ASSERT_EQ(out.size(), 3) << at;
      EXPECT_TRUE(agrees(out[1], oracle(2 * x, y), rel, at + " component 1"));
      EXPECT_TRUE(agrees(out[2], oracle(-x, y), rel, at + " component 2"));
    }
}

// Rounding to nearest with halves to even, from floor alone.
double roundHalfEven(double x) {
  double f = std::floor(x), d = x - f;
  if (d > 0.5) return f + 1;
  if (d < 0.5) return f;
  return std::fmod(f, 2.0) == 0 ? f : f + 1;
}

TEST(MathVocabulary, RoundingFamilyFollowsGlslDefinitions) {
  unaryAgainst("fract", [](double x) { return x - std::floor(x); });
  unaryAgainst("floor", [](double x) { return std::floor(x); });
  unaryAgainst("ceil", [](double x) { return std::ceil(x); });
  unaryAgainst("trunc", [](double x) { return x < 0 ? -std::floor(-x) : std::floor(x); });
  unaryAgainst("round", roundHalfEven);
  unaryAgainst("sign", [](double x) { return x == 0 ? 0.0 : std::copysign(1.0, x); });
  unaryAgainst("negate", [](double x) { return -x; });
  unaryAgainst("one_minus", [](double x) { return 1 - x; });
  // GLSL: step(edge, x) = x < edge ? 0 : 1, so x == edge gives 1.
  binaryAgainst("step", "edge", "x", [](double e, double x) { return x < e ? 0.0 : 1.0; });
  // GLSL: mod(x, y) = x - y floor(x / y); documented: 0 where x / y is beyond 1e38 or NaN.
  binaryAgainst("mod", "x", "y", [](double x, double y) {
    double q = x / y;
    if (std::isnan(q) || std::abs(q) > 1e38) return 0.0;
    return x - y * std::floor(q);
  });
  EXPECT_EQ(runNode("round", {{"x", Value::scalar(0.5)}}).first(), 0.0);
  EXPECT_EQ(runNode("round", {{"x", Value::scalar(-1.5)}}).first(), -2.0);
  EXPECT_EQ(runNode("mod", {{"x", Value::scalar(-0.25)}, {"y", Value::scalar(1)}}).first(), 0.75);  // floored
  EXPECT_EQ(runNode("mod", {{"x", Value::scalar(0.25)}, {"y", Value::scalar(-1)}}).first(), -0.75);  // sign of y
}

TEST(MathVocabulary, ExponentialFamilyFollowsGlslAndItsGuards) {
  unaryAgainst("exp", [](double x) { return x <= 88 ? std::exp(x) : std::exp(88.0); }, 1e-14);
  unaryAgainst("exp2", [](double x) { return std::pow(2.0, std::min(x, 127.0)); }, 1e-14);
  // Below the smallest normal float (0, negatives, a float denormal): the value at it.
  unaryAgainst("log", [](double x) { return std::log(x >= kFltMin ? x : kFltMin); });
  unaryAgainst("log2", [](double x) { return x >= kFltMin ? std::log(x) / std::log(2.0) : -126.0; }, 1e-14);
  unaryAgainst("sqrt", [](double x) { return x >= 0 ? std::sqrt(x) : 0.0; });
  unaryAgainst("inversesqrt", [](double x) { return x >= kFltMin ? 1 / std::sqrt(x) : std::ldexp(1.0, 63); }, 1e-15);
}

TEST(MathVocabulary, TrigonometricFamilyFollowsGlslAndItsGuards) {
  unaryAgainst("tan", [](double x) { return std::sin(x) / std::cos(x); }, 1e-12);
  unaryAgainst("asin", [](double x) { return x > 1 ? std::numbers::pi / 2 : x < -1 ? -std::numbers::pi / 2 : std::asin(x); });
  unaryAgainst("acos", [](double x) { return x > 1 ? 0.0 : x < -1 ? std::numbers::pi : std::acos(x); });
  unaryAgainst("atan", [](double x) { return std::atan(x); });
  auto hyperbolic = [](double x, int kind) {
    double c = std::max(-88.0, std::min(88.0, x));  // documented clamp
    double ep = std::exp(c), em = std::exp(-c);
    return kind == 0 ? (ep - em) / 2 : (ep + em) / 2;
  };
  unaryAgainst("sinh", [&](double x) { return hyperbolic(x, 0); }, 1e-12);
  unaryAgainst("cosh", [&](double x) { return hyperbolic(x, 1); }, 1e-12);
  unaryAgainst("tanh", [](double x) {
    double c = std::max(-10.0, std::min(10.0, x));
    return (std::exp(2 * c) - 1) / (std::exp(2 * c) + 1);
  }, 1e-12);
  // atan(y, x): the angle of (x, y); the origin is 0.
  binaryAgainst("atan2", "y", "x", [](double y, double x) {
    if (x == 0 && y == 0) return 0.0;
    double a = std::atan(std::abs(y) / std::abs(x));  // first quadrant, then unfolded
    if (x == 0) a = std::numbers::pi / 2;
    if (x < 0) a = std::numbers::pi - a;
    return y < 0 ? -a : a;
  }, 1e-15);
}

Value v3(double x, double y, double z) { return Value::vector({x, y, z}); }
double dot3(const Value& a, const Value& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

TEST(MathVocabulary, GeometricFamilyFollowsGlslDefinitions) {
  Value a = v3(1, 2, 3), b = v3(-2, 6, 3);
  EXPECT_DOUBLE_EQ(runNode("distance", {{"a", a}, {"b", b}}).first(), 5.0);  // a 3-4-0 triangle
  EXPECT_DOUBLE_EQ(runNode("distance", {{"a", Value::scalar(-2)}, {"b", Value::scalar(5)}}).first(), 7.0);
  // reflect: mirror the normal component of I, keep the tangential one.
  Value n = v3(0, 1, 0), in = v3(0.6, -0.8, 0);
  Value r = runNode("reflect", {{"incident", in}, {"normal", n}}).values[0];
  EXPECT_TRUE(agrees(r[0], 0.6, 1e-15, "reflect x") && agrees(r[1], 0.8, 1e-15, "reflect y") && agrees(r[2], 0, 0, "z"));
  // refract by Snell's law in angles: sin t = eta sin i, the tangential direction kept.
  for (double degrees : {0.0, 20.0, 45.0, 60.0, 80.0}) {
    for (double eta : {1 / 1.333, 1.333}) {
      double i = degrees * std::numbers::pi / 180, s = eta * std::sin(i);
      Value dir = v3(std::sin(i), -std::cos(i), 0);
      Value t = runNode("refract", {{"incident", dir}, {"normal", n}, {"eta", Value::scalar(eta)}}).values[0];
      std::string at = "refract at " + std::to_string(degrees) + " deg, eta " + std::to_string(eta);
      if (s > 1) {  // total internal reflection: GLSL returns the zero vector
        EXPECT_EQ(dot3(t, t), 0.0) << at;
        continue;
      }
      double angle = std::asin(s);
      EXPECT_TRUE(agrees(t[0], std::sin(angle), 1e-14, at + " x"));
      EXPECT_TRUE(agrees(t[1], -std::cos(angle), 1e-14, at + " y"));
    }
  }
  // faceforward(N, I, Nref): N where Nref faces against I, -N otherwise (0 included).
  Value down = v3(0, -1, 0), side = v3(1, 0, 0);
  EXPECT_EQ(runNode("faceforward", {{"normal", n}, {"incident", down}, {"reference", n}}).values[0][1], 1.0);
  EXPECT_EQ(runNode("faceforward", {{"normal", n}, {"incident", n}, {"reference", n}}).values[0][1], -1.0);
  EXPECT_EQ(runNode("faceforward", {{"normal", n}, {"incident", side}, {"reference", n}}).values[0][1], -1.0);
}

TEST(MathVocabulary, ComparisonFamilyFollowsItsDefinition) {
  struct Op {
    const char* name;
    std::function<bool(double, double)> holds;
  };
  const std::vector<Op> ops = {{"less", std::less<double>()},       {"less_equal", std::less_equal<double>()},
                               {"greater", std::greater<double>()}, {"greater_equal", std::greater_equal<double>()},
                               {"equal", std::equal_to<double>()},  {"not_equal", std::not_equal_to<double>()}};
  for (const auto& op : ops) {
    nlohmann::json o{{"op", op.name}};
    for (double a : {-1.0, 0.5, 2.0})
      for (double b : {-1.0, 0.5, 2.0}) {
        std::string at = std::string(op.name) + "(" + std::to_string(a) + ", " + std::to_string(b) + ")";
        double want = op.holds(a, b) ? 1.0 : 0.0;
        EXPECT_EQ(runNode("compare", {{"a", Value::scalar(a)}, {"b", Value::scalar(b)}}, o).first(), want) << at;
        Value chosen = runNode("select", {{"a", v3(a, b, a)}, {"b", Value::scalar(b)}, {"if_true", v3(7, 7, 7)},
                                          {"if_false", v3(-3, -3, -3)}}, o).values[0];
        EXPECT_EQ(chosen[0], op.holds(a, b) ? 7.0 : -3.0) << at;
        EXPECT_EQ(chosen[1], op.holds(b, b) ? 7.0 : -3.0) << at;
      }
  }
  // inverse_mix undoes mix, and an empty range gives 0.
  for (double a : {-2.0, 0.0, 3.0})
    for (double b : {-1.0, 3.0, 10.0})
      for (double t : {-0.5, 0.0, 0.25, 1.0, 2.0}) {
        double x = a + (b - a) * t;
        double got = runNode("inverse_mix", {{"a", Value::scalar(a)}, {"b", Value::scalar(b)}, {"x", Value::scalar(x)}}).first();
        EXPECT_TRUE(agrees(got, a == b ? 0.0 : t, 1e-15, "inverse_mix"));
      }
}

// The inputs the finite-output promise names, each to the value the node documents.
TEST(MathVocabulary, HardInputsGiveTheirDocumentedFiniteValues) {
  auto at = [](const std::string& type, std::vector<std::pair<std::string, Value>> in) {
    double r = runNode(type, in).first();
    EXPECT_TRUE(std::isfinite(r)) << type;
    return r;
  };
  auto x = [](double v) { return std::vector<std::pair<std::string, Value>>{{"x", Value::scalar(v)}}; };
  float beyondOne = 1.0000001f;  // a unit vector's component as float32 rounds it
  EXPECT_DOUBLE_EQ(at("log", x(0)), std::log(kFltMin));
  EXPECT_DOUBLE_EQ(at("log2", x(0)), -126.0);
  EXPECT_EQ(at("sqrt", x(-1)), 0.0);
  EXPECT_EQ(at("acos", x(beyondOne)), 0.0);
  EXPECT_DOUBLE_EQ(at("asin", x(-beyondOne)), -std::numbers::pi / 2);
  EXPECT_EQ(at("mod", {{"x", Value::scalar(5.3)}, {"y", Value::scalar(0)}}), 0.0);
  EXPECT_EQ(at("atan2", {{"y", Value::scalar(0)}, {"x", Value::scalar(0)}}), 0.0);
  EXPECT_DOUBLE_EQ(at("exp", x(100)), std::exp(88.0));
  EXPECT_EQ(at("inversesqrt", x(0)), std::ldexp(1.0, 63));
  // pi/2 as float32 lies 4.37e-8 past the pole: tan is large and negative, and finite.
  double pole = at("tan", x(static_cast<float>(std::numbers::pi / 2)));
  EXPECT_LT(pole, -2e7);
  EXPECT_GT(pole, -3e7);
  EXPECT_DOUBLE_EQ(at("sinh", x(1000)), std::sinh(88.0));
  EXPECT_EQ(at("tanh", x(1e30)), std::tanh(10.0));
  EXPECT_EQ(at("inverse_mix", {{"a", Value::scalar(1)}, {"b", Value::scalar(1)}, {"x", Value::scalar(4)}}), 0.0);
}

}  // namespace
}  // namespace wg
