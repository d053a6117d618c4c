#include "codegen/c_math_formulas.h"

#include <map>

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

}  // namespace

const char* componentWiseFormula(std::string_view type) {
  auto f = componentWise().find(type);
  return f == componentWise().end() ? nullptr : f->second.data();
}

std::string_view cMathHelpers() {
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
