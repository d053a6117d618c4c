#include "codegen/derived_vocabulary.h"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "core/interface_tables.h"
#include "nodes/math_builders.h"

namespace wg {

namespace {

// A component-wise node: its formula over the scalars $0, $1, $2 (the inputs' components,
// a float input splatted as GLSL does), as C over the wgd_ helpers.
const std::map<std::string_view, std::string_view>& componentWise() {
  static const std::map<std::string_view, std::string_view> m = {
      {"add", "$0 + $1"},
      {"sub", "$0 - $1"},
      {"mul", "$0 * $1"},
      {"div", "$0 / $1"},
      {"mix", "wgd_mix($0, $1, $2)"},
      {"clamp", "wgd_clamp($0, $1, $2)"},
      {"saturate", "wgd_clamp($0, 0.0, 1.0)"},
      {"smoothstep", "wgd_smoothstep($0, $1, $2)"},
      {"pow", "wgd_safe_pow($0, $1)"},
      {"sin", "sin($0)"},
      {"cos", "cos($0)"},
      {"tan", "wgd_safe_tan($0)"},
      {"asin", "asin(wgd_clamp($0, -1.0, 1.0))"},
      {"acos", "acos(wgd_clamp($0, -1.0, 1.0))"},
      {"atan", "atan($0)"},
      {"atan2", "wgd_safe_atan2($0, $1)"},
      {"sinh", "sinh(wgd_clamp($0, -88.0, 88.0))"},
      {"cosh", "cosh(wgd_clamp($0, -88.0, 88.0))"},
      {"tanh", "tanh(wgd_clamp($0, -10.0, 10.0))"},
      {"abs", "fabs($0)"},
      {"min", "wgd_min($0, $1)"},
      {"max", "wgd_max($0, $1)"},
      {"fract", "$0 - floor($0)"},
      {"floor", "floor($0)"},
      {"ceil", "ceil($0)"},
      {"round", "nearbyint($0)"},
      {"trunc", "trunc($0)"},
      {"mod", "wgd_safe_mod($0, $1)"},
      {"step", "($1 < $0 ? 0.0 : 1.0)"},
      {"sign", "($0 > 0.0 ? 1.0 : $0 < 0.0 ? -1.0 : 0.0)"},
      {"negate", "-$0"},
      {"one_minus", "1.0 - $0"},
      {"exp", "exp(wgd_min($0, 88.0))"},
      {"exp2", "exp2(wgd_min($0, 127.0))"},
      {"log", "log(wgd_max($0, WGD_FLT_MIN))"},
      {"log2", "log2(wgd_max($0, WGD_FLT_MIN))"},
      {"sqrt", "sqrt(wgd_max($0, 0.0))"},
      {"inversesqrt", "1.0 / sqrt(wgd_max($0, WGD_FLT_MIN))"},
      {"inverse_mix", "($1 == $0 ? 0.0 : ($2 - $0) / ($1 - $0))"},
  };
  return m;
}

// compare / select: the option "op" as a C operator.
std::string comparisonOperator(const Op& op) {
  static const std::map<std::string, std::string> ops = {{"less", "<"},          {"less_equal", "<="},
                                                         {"greater", ">"},       {"greater_equal", ">="},
                                                         {"equal", "=="},        {"not_equal", "!="}};
  auto it = ops.find(op.options().value("op", std::string("less")));
  if (it == ops.end()) throw std::logic_error("derivedOpC: unknown comparison in '" + op.nodeId + "'");
  return it->second;
}

const std::vector<std::string_view>& otherTypes() {
  static const std::vector<std::string_view> t = {"camera_forward", "camera_position", "combine",  "compare",
                                                  "cross",          "distance",        "dot",      "length",
                                                  "near_far_ratio", "normalize",       "remap",    "select",
                                                  "split",          "srgb_to_linear",  "sun_direction",
                                                  "swizzle",        "time"};
  return t;
}

std::string at(const std::string& array, Type t, int i) {
  return array + "[" + std::to_string(componentCount(t) == 1 ? 0 : i) + "]";
}

std::string substitute(std::string_view formula, const std::vector<std::string>& args) {
  std::string out;
  for (size_t i = 0; i < formula.size(); ++i) {
    if (formula[i] == '$' && i + 1 < formula.size()) {
      out += "(" + args.at(static_cast<size_t>(formula[i + 1] - '0')) + ")";
      ++i;
    } else {
      out += formula[i];
    }
  }
  return out;
}

std::string assign(const std::string& out, int i, const std::string& value) {
  return "  " + out + "[" + std::to_string(i) + "] = " + value + ";\n";
}

// sum of a[i] * b[i] from 0, in the order glsl::dot adds.
std::string dotC(const std::string& a, Type ta, const std::string& b, Type tb, int n) {
  std::string s = "0.0";
  for (int i = 0; i < n; ++i) s = "(" + s + " + " + at(a, ta, i) + " * " + at(b, tb, i) + ")";
  return s;
}

}  // namespace

const std::vector<std::string_view>& derivedNodeTypes() {
  static const std::vector<std::string_view> all = [] {
    std::vector<std::string_view> v;
    for (const auto& [type, formula] : componentWise()) v.push_back(type);
    v.insert(v.end(), otherTypes().begin(), otherTypes().end());
    std::sort(v.begin(), v.end());
    return v;
  }();
  return all;
}

const char* componentWiseFormula(std::string_view type) {
  auto f = componentWise().find(type);
  return f == componentWise().end() ? nullptr : f->second.data();
}

bool isDerivedNodeType(std::string_view type) {
  const auto& v = derivedNodeTypes();
  return std::binary_search(v.begin(), v.end(), type);
}

std::string derivedOpC(const Op& op, const std::vector<std::string>& in, const std::vector<Type>& ti,
                       const std::vector<std::string>& out) {
  const std::string& type = op.spec->type;
  auto ports = [&](size_t k) { return componentCount(op.inputTypes.at(k)); };
  auto count = [&](int port) { return componentCount(op.outputTypes.at(static_cast<size_t>(port))); };
  std::string c;
  if (auto f = componentWise().find(type); f != componentWise().end()) {
    for (int i = 0; i < count(0); ++i) {
      std::vector<std::string> args;
      for (size_t k = 0; k < in.size(); ++k) args.push_back(at(in[k], ti[k], i));
      c += assign(out[0], i, substitute(f->second, args));
    }
    return c;
  }
  if (type == "time" || type == "camera_position" || type == "sun_direction") {
    for (int i = 0; i < count(0); ++i) c += assign(out[0], i, "b_" + type + "[" + std::to_string(i) + "]");
    return c;
  }
  if (type == "camera_forward") {  // -(row 2) of the view matrix; zero for a degenerate one
    c += "  {\n    const double f[3] = {-b_view[2], -b_view[6], -b_view[10]};\n";
    c += "    const double l2 = " + dotC("f", Type::Vec3, "f", Type::Vec3, 3) + ";\n";
    c += "    const double k = l2 < 0.5 ? 0.0 : 1.0 / sqrt(wgd_max(l2, 1e-30));\n";
    for (int i = 0; i < 3; ++i) c += "  " + assign(out[0], i, "l2 < 0.5 ? 0.0 : f[" + std::to_string(i) + "] * k");
    return c + "  }\n";
  }
  if (type == "near_far_ratio") {  // near floored at 1e-6, near / max(far, near)
    c += assign(out[0], 0, "wgd_max(" + at(in[0], ti[0], 0) + ", 1e-6)");
    return c + assign(out[1], 0, out[0] + "[0] / wgd_max(" + at(in[0], ti[0], 1) + ", " + out[0] + "[0])");
  }
  if (type == "compare" || type == "select") {
    std::string rel = comparisonOperator(op);
    for (int i = 0; i < count(0); ++i) {
      std::string cond = at(in[0], ti[0], i) + " " + rel + " " + at(in[1], ti[1], i);
      c += assign(out[0], i,
                  type == "compare" ? "(" + cond + " ? 1.0 : 0.0)"
                                    : "(" + cond + " ? " + at(in[2], ti[2], i) + " : " + at(in[3], ti[3], i) + ")");
    }
    return c;
  }
  if (type == "dot") return assign(out[0], 0, dotC(in[0], ti[0], in[1], ti[1], ports(0)));
  if (type == "length") return assign(out[0], 0, "sqrt(" + dotC(in[0], ti[0], in[0], ti[0], ports(0)) + ")");
  if (type == "distance") {
    int n = std::max(ports(0), ports(1));
    c += "  {\n    double d[4];\n";
    for (int i = 0; i < n; ++i) c += "  " + assign("d", i, at(in[0], ti[0], i) + " - " + at(in[1], ti[1], i));
    return c + "  " + assign(out[0], 0, "sqrt(" + dotC("d", floatVector(n), "d", floatVector(n), n) + ")") + "  }\n";
  }
  if (type == "normalize") {
    int n = count(0);
    c += "  {\n    const double k = 1.0 / sqrt(wgd_max(" + dotC(in[0], ti[0], in[0], ti[0], n) + ", 1e-30));\n";
    for (int i = 0; i < n; ++i) c += "  " + assign(out[0], i, at(in[0], ti[0], i) + " * k");
    return c + "  }\n";
  }
  if (type == "cross") {
    auto a = [&](int i) { return at(in[0], ti[0], i); };
    auto b = [&](int i) { return at(in[1], ti[1], i); };
    c += assign(out[0], 0, a(1) + " * " + b(2) + " - " + a(2) + " * " + b(1));
    c += assign(out[0], 1, a(2) + " * " + b(0) + " - " + a(0) + " * " + b(2));
    return c + assign(out[0], 2, a(0) + " * " + b(1) + " - " + a(1) + " * " + b(0));
  }
  if (type == "swizzle") {
    std::string mask = op.options().value("mask", std::string("xyz"));
    for (size_t i = 0; i < mask.size(); ++i)
      c += assign(out[0], static_cast<int>(i), at(in[0], ti[0], nodes::math::swizzleIndex(mask[i])));
    return c;
  }
  if (type == "split") {
    for (int i = 0; i < ports(0); ++i) c += assign(out[static_cast<size_t>(i)], 0, at(in[0], ti[0], i));
    return c;
  }
  if (type == "combine") {
    for (int i = 0; i < count(0); ++i) c += assign(out[0], i, in[static_cast<size_t>(i)] + "[0]");
    return c;
  }
  if (type == "srgb_to_linear") {  // the sRGB curve per colour component (core/color_space.h); a vec4's w as it is
    for (int i = 0; i < count(0); ++i)
      c += assign(out[0], i, i == 3 ? at(in[0], ti[0], i) : "wgd_srgb_to_linear(" + at(in[0], ti[0], i) + ")");
    return c;
  }
  if (type == "remap") {
    bool clamped = op.options().value("clamp", false);
    for (int i = 0; i < count(0); ++i) {
      std::string x = at(in[0], ti[0], i), a = at(in[1], ti[1], i), b = at(in[2], ti[2], i);
      std::string t = "(" + b + " == " + a + " ? 0.0 : (" + x + " - " + a + ") / (" + b + " - " + a + "))";
      if (clamped) t = "wgd_clamp(" + t + ", 0.0, 1.0)";
      c += assign(out[0], i, "wgd_mix(" + at(in[3], ti[3], i) + ", " + at(in[4], ti[4], i) + ", " + t + ")");
    }
    return c;
  }
  throw std::logic_error("derivedOpC: node type '" + type + "' is not in the derived vocabulary");
}

std::string_view derivedCHelpers() {
  // std::min / std::max's comparisons, so a NaN goes where the C++ reference sends it.
  return R"(#ifndef WGD_HELPERS
#define WGD_HELPERS
#define WGD_FLT_MIN 1.1754943508222875e-38 /* 2^-126: floor of log's and inversesqrt's argument */
static inline double wgd_min(double a, double b) { return b < a ? b : a; }
static inline double wgd_max(double a, double b) { return a < b ? b : a; }
static inline double wgd_clamp(double x, double lo, double hi) { return wgd_min(wgd_max(x, lo), hi); }
static inline double wgd_mix(double a, double b, double t) { return a * (1.0 - t) + b * t; }
static inline double wgd_smoothstep(double e0, double e1, double x) {
  double t;
  if (e0 == e1) return x < e0 ? 0.0 : 1.0;
  t = wgd_clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}
static inline double wgd_safe_pow(double x, double y) {
  double e;
  if (!(x > 0.0)) return y > 0.0 ? 0.0 : 1.0;
  e = y * log2(x);
  return exp2(127.0 < e ? 127.0 : e);
}
static inline double wgd_srgb_to_linear(double c) {
  double a = fabs(c);
  double v = a <= 0.04045 ? a / 12.92 : pow((a + 0.055) / 1.055, 2.4);
  v = wgd_min(v, a <= 1.0 ? 1.0 : 1.7014118346046923e38); /* 2^127, the GLSL's cap */
  return c < 0.0 ? -v : v;
}
static inline double wgd_safe_mod(double x, double y) {
  double q = x / y;
  return fabs(q) <= 1e38 ? x - y * floor(q) : 0.0;
}
static inline double wgd_safe_tan(double x) {
  double c = cos(x);
  double d = c < 0.0 ? wgd_min(c, -1e-30) : wgd_max(c, 1e-30);
  return sin(x) / d;
}
static inline double wgd_safe_atan2(double y, double x) {
  if (y == 0.0) return x < 0.0 ? 3.14159265358979323846 : 0.0;
  return atan2(y, x);
}
#endif
)";
}

}  // namespace wg
