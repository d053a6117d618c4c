#include "codegen/query_ops.h"

#include <map>
#include <set>

#include "codegen/c_math_formulas.h"
#include "core/interface_tables.h"
#include "core/number_format.h"
#include "nodes/gerstner_waves.h"
#include "nodes/math_builders.h"

namespace wg {

namespace {

const std::string kZero = "0.0";

bool isZero(const std::string& e) { return e == kZero; }

// Products and sums that drop known zeros and ones, so the common case (a wave over the
// world position, whose derivatives are 1 and 0) is written without dead arithmetic.
std::string mulS(const std::string& a, const std::string& b) {
  if (isZero(a) || isZero(b)) return kZero;
  if (a == "1.0") return b;
  if (b == "1.0") return a;
  return "(" + a + ") * (" + b + ")";
}
std::string addS(const std::string& a, const std::string& b) {
  if (isZero(a)) return b;
  if (isZero(b)) return a;
  return "(" + a + ") + (" + b + ")";
}

// A double literal valid in both languages (no NaN or infinity reach here: option values
// are finite).
std::string lit(double x) {
  std::string s = formatNumber(x);
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

// The derivative of a component-wise formula, over the values $0..$2 and their
// derivatives $a..$c (one direction at a time). A type missing here has no derivative
// form: queryOp refuses it where an input varies with x0, z0 or t.
const std::map<std::string_view, std::string_view>& derivativeFormulas() {
  static const std::map<std::string_view, std::string_view> m = {
      {"add", "$a + $b"},
      {"sub", "$a - $b"},
      {"mul", "$a * $1 + $0 * $b"},
      {"div", "($a * $1 - $0 * $b) / ($1 * $1)"},
      {"negate", "-$a"},
      {"one_minus", "-$a"},
      {"mix", "$a * (1.0 - $2) + $b * $2 + ($1 - $0) * $c"},
      // wgd_clamp(x, lo, hi) = wgd_min(wgd_max(x, lo), hi): the branch each comparison takes.
      {"clamp", "($2 < wgd_max($0, $1) ? $c : $0 < $1 ? $b : $a)"},
      {"saturate", "(1.0 < wgd_max($0, 0.0) ? 0.0 : $0 < 0.0 ? 0.0 : $a)"},
      {"min", "($1 < $0 ? $b : $a)"},
      {"max", "($0 < $1 ? $b : $a)"},
      {"abs", "($0 < 0.0 ? -$a : $a)"},
      {"sin", "cos($0) * $a"},
      {"cos", "-sin($0) * $a"},
      {"fract", "$a"},
      {"floor", "0.0"},
      {"ceil", "0.0"},
      {"round", "0.0"},
      {"trunc", "0.0"},
      {"sign", "0.0"},
      {"step", "0.0"},
      {"mod", "(fabs($0 / $1) <= 1e38 ? $a - $b * floor($0 / $1) : 0.0)"},
      {"exp", "(88.0 < $0 ? 0.0 : exp($0) * $a)"},
      {"exp2", "(127.0 < $0 ? 0.0 : exp2($0) * 0.69314718055994531 * $a)"},
      {"log", "($0 < WGD_FLT_MIN ? 0.0 : $a / $0)"},
      {"log2", "($0 < WGD_FLT_MIN ? 0.0 : $a / ($0 * 0.69314718055994531))"},
      {"sqrt", "($0 > 0.0 ? 0.5 / sqrt($0) * $a : 0.0)"},
      {"inversesqrt", "($0 < WGD_FLT_MIN ? 0.0 : -0.5 * $a / ($0 * sqrt($0)))"},
      {"tanh", "(fabs($0) <= 10.0 ? (1.0 - tanh($0) * tanh($0)) * $a : 0.0)"},
      {"sinh", "(fabs($0) <= 88.0 ? cosh($0) * $a : 0.0)"},
      {"cosh", "(fabs($0) <= 88.0 ? sinh($0) * $a : 0.0)"},
      {"atan", "$a / (1.0 + $0 * $0)"},
      {"atan2", "($0 == 0.0 ? 0.0 : ($1 * $a - $0 * $b) / ($0 * $0 + $1 * $1))"},
      {"pow", "wgq_dpow($0, $1, $a, $b)"},
      {"smoothstep", "wgq_dsmoothstep($0, $1, $2, $a, $b, $c)"},
  };
  return m;
}

// The other types with a query form (beside the component-wise ones).
const std::vector<std::string_view>& structuralTypes() {
  static const std::vector<std::string_view> t = {
      "combine", "compare",   "cross",  "dot",   "gerstner_waves", "length",        "normal",        "normalize",
      "select",  "split",     "swizzle", "time", "vertex_output",  "world_position", "ocean_spectrum", "ocean_displacement"};
  return t;
}

std::string substitute(std::string_view formula, const std::vector<std::string>& values,
                       const std::vector<std::string>& derivatives) {
  std::string out;
  for (size_t i = 0; i < formula.size(); ++i) {
    char c = i + 1 < formula.size() ? formula[i + 1] : '\0';
    if (formula[i] == '$' && c >= '0' && c <= '2') {
      out += "(" + values.at(static_cast<size_t>(c - '0')) + ")";
      ++i;
    } else if (formula[i] == '$' && c >= 'a' && c <= 'c') {
      out += "(" + derivatives.at(static_cast<size_t>(c - 'a')) + ")";
      ++i;
    } else {
      out += formula[i];
    }
  }
  return out;
}

// Component i of a source value (a single component splats, as GLSL converts).
const QueryScalar& comp(const QueryValue& v, int i) { return v.at(v.size() == 1 ? 0 : static_cast<size_t>(i)); }

bool varies(const QueryScalar& s) { return !isZero(s.d[0]) || !isZero(s.d[1]) || !isZero(s.d[2]); }

class OpWriter {
 public:
  OpWriter(const Op& op, QueryWriter& w, const std::string& name) : op_(op), w_(w), name_(name) {}

  // Binds a whole scalar: "v<name>_<port>_<i>" and "d<name>_<port>_<i><x|z|t>".
  QueryScalar bindScalar(int port, int i, const std::string& value, const std::array<std::string, 3>& d) {
    QueryScalar s;
    std::string base = name_ + "_" + std::to_string(port) + "_" + std::to_string(i);
    s.value = w_.bind("v" + base, value);
    static const char axis[] = {'x', 'z', 't'};
    for (int j = 0; j < 3; ++j) s.d[static_cast<size_t>(j)] = isZero(d[static_cast<size_t>(j)]) ? kZero : w_.bind("d" + base + axis[j], d[static_cast<size_t>(j)]);
    return s;
  }
  std::string temp(const std::string& what, const std::string& expr) { return w_.bind("t" + name_ + "_" + what, expr); }
  int count(int port) const { return componentCount(op_.outputTypes.at(static_cast<size_t>(port))); }
  [[noreturn]] void refuse(const std::string& why) const { throw QueryRefusal(why); }

 private:
  const Op& op_;
  QueryWriter& w_;
  std::string name_;
};

// sum of a_i * b_i from 0, in the order glsl::dot adds.
std::string dotValue(const QueryValue& a, const QueryValue& b, int n) {
  std::string s = "0.0";
  for (int i = 0; i < n; ++i) s = "(" + s + " + " + comp(a, i).value + " * " + comp(b, i).value + ")";
  return s;
}
std::string dotDerivative(const QueryValue& a, const QueryValue& b, int n, size_t j) {
  std::string s = kZero;
  for (int i = 0; i < n; ++i)
    s = addS(s, addS(mulS(comp(a, i).d[j], comp(b, i).value), mulS(comp(a, i).value, comp(b, i).d[j])));
  return s;
}

std::vector<QueryValue> componentWiseOp(const Op& op, const char* formula, const std::vector<QueryValue>& in,
                                        OpWriter& o) {
  QueryValue out;
  auto df = derivativeFormulas().find(op.spec->type);
  for (int i = 0; i < o.count(0); ++i) {
    std::vector<std::string> values;
    bool anyVaries = false;
    for (const QueryValue& v : in) {
      values.push_back(comp(v, i).value);
      anyVaries = anyVaries || varies(comp(v, i));
    }
    std::array<std::string, 3> d{kZero, kZero, kZero};
    if (anyVaries) {
      if (df == derivativeFormulas().end())
        o.refuse("its type '" + op.spec->type + "' has no derivative form, and its input varies with the position or time");
      for (size_t j = 0; j < 3; ++j) {
        std::vector<std::string> ds;
        bool all0 = true;
        for (const QueryValue& v : in) {
          ds.push_back(comp(v, i).d[j]);
          all0 = all0 && isZero(ds.back());
        }
        d[j] = all0 || df->second == "0.0" ? kZero : substitute(df->second, values, ds);
      }
    }
    out.push_back(o.bindScalar(0, i, substitute(formula, values, {}), d));
  }
  return {out};
}

// gerstnerReference's sums, term by term in its order, with each product's constant factor
// computed here in double as the reference computes it (qa * dirX, then times cos).
std::vector<QueryValue> gerstnerOp(const Op& op, const std::vector<QueryValue>& in, OpWriter& o) {
  const auto& waves = op.parsedOptions->as<std::vector<nodes::GerstnerWave>>();
  const QueryValue& p = in.at(0);
  const QueryScalar &px = comp(p, 0), &pz = comp(p, 2);
  std::array<std::string, 3> sum{"0.0", "0.0", "0.0"};
  std::array<std::array<std::string, 3>, 3> dsum;  // [component][direction]
  for (auto& a : dsum) a = {kZero, kZero, kZero};
  for (size_t i = 0; i < waves.size(); ++i) {
    const nodes::GerstnerWave& w = waves[i];
    std::string k = std::to_string(i);
    std::string theta = o.temp("th" + k, lit(w.k) + " * wgq_mod(" + lit(w.dirX) + " * " + px.value + " + " + lit(w.dirZ) +
                                             " * " + pz.value + ", " + lit(w.wavelength) + ") + (" + lit(w.phase) +
                                             " - wgq_mod(" + lit(w.omega) + " * t, 6.283185307179586))");
    std::string s = o.temp("s" + k, "sin(" + theta + ")"), c = o.temp("c" + k, "cos(" + theta + ")");
    const double qa = w.steepness * w.amplitude;
    sum[0] += " + " + lit(qa * w.dirX) + " * " + c;
    sum[1] += " + " + lit(w.amplitude) + " * " + s;
    sum[2] += " + " + lit(qa * w.dirZ) + " * " + c;
    for (size_t j = 0; j < 3; ++j) {
      // d theta = k (dirX dpx + dirZ dpz) - omega dt: mod's floor is piecewise constant.
      std::string dtheta = addS(mulS(lit(w.k * w.dirX), px.d[j]), mulS(lit(w.k * w.dirZ), pz.d[j]));
      if (j == 2) dtheta = addS(dtheta, lit(-w.omega));
      if (isZero(dtheta)) continue;
      dtheta = o.temp("dth" + k + "xzt"[j], dtheta);
      dsum[0][j] = addS(dsum[0][j], mulS(lit(-qa * w.dirX), mulS(s, dtheta)));
      dsum[1][j] = addS(dsum[1][j], mulS(lit(w.amplitude), mulS(c, dtheta)));
      dsum[2][j] = addS(dsum[2][j], mulS(lit(-qa * w.dirZ), mulS(s, dtheta)));
    }
  }
  QueryValue position;
  for (int i = 0; i < 3; ++i) {
    std::string disp = o.temp("D" + std::to_string(i), sum[static_cast<size_t>(i)]);
    std::array<std::string, 3> d;
    for (size_t j = 0; j < 3; ++j) d[j] = addS(comp(p, i).d[j], dsum[static_cast<size_t>(i)][j]);
    position.push_back(o.bindScalar(0, i, comp(p, i).value + " + " + disp, d));
  }
  return {position, {}, {}, {}};
}

// ocean_displacement: the point p plus the cascades' maps at p.xz, each cascade weighted by the
// readers' fade at p's distance from the state's camera (wg_ocean_fade, 1 when the state has
// no camera), as the vertex shader sums them. Its derivatives along x0, z0 are the maps'
// own (the slope channels, which the shader's normal reads too, by the chain rule through
// p.xz), along t the velocity channels; the fade weights' own slope is left out, as the
// shader's normal leaves it out.
std::vector<QueryValue> oceanDisplacementOp(const Op& op, const std::vector<QueryValue>& in, QueryWriter& w,
                                            OpWriter& o, const std::string& name) {
  const ocean::OceanSettings* sea = w.ocean.settings;
  if (!sea) o.refuse("its ocean is not the query's ocean_spectrum");
  const bool c = w.language() == HeaderLanguage::C;
  const QueryValue &p = in.at(1), &camera = in.at(2);
  const double fade = op.parsedOptions->as<double>();
  std::string weights;
  if (fade > 0) {
    std::string d2 = "0.0";
    for (int i = 0; i < 3; ++i) {
      std::string diff = "(" + comp(p, i).value + " - " + comp(camera, i).value + ")";
      d2 = i == 0 ? diff + " * " + diff : d2 + " + " + diff + " * " + diff;
    }
    std::string distance = o.temp("dist", "sqrt(" + d2 + ")");
    for (size_t k = 0; k < sea->cascades.tileLengths.size(); ++k) {
      const double start = static_cast<float>(fade * sea->cascades.tileLengths[k]);  // the shader's literal
      weights += std::string(k ? ", " : "") + "(" + (c ? "o->fade" : "o.fade") + " ? 1.0 - wgd_smoothstep(" + lit(start) +
                 ", " + lit(2.0 * start) + ", " + distance + ") : 1.0)";
    }
  } else {
    for (size_t k = 0; k < sea->cascades.tileLengths.size(); ++k) weights += std::string(k ? ", " : "") + "1.0";
  }
  const std::string wName = "oc" + name + "_w", sName = "oc" + name + "_s";
  const std::string call = "  " + w.ocean.prefix + "ocean_sample(o, " + comp(p, 0).value + ", " + comp(p, 2).value + ", " +
                           wName + ", " + sName + ");\n";
  if (c)
    w.statement(sName, "  double " + wName + "[" + std::to_string(sea->cascades.tileLengths.size()) + "] = {" + weights +
                           "};\n  double " + sName + "[11];\n" + call);
  else
    w.statement(sName, "  const " + wName + " = [" + weights + "], " + sName + " = new Float64Array(11);\n" + call);
  auto ch = [&](int k) { return sName + "[" + std::to_string(k) + "]"; };
  // Per component of the displacement (lDx, h, lDz): its channel and its derivatives' along x, z, t.
  const int value[3] = {0, 1, 2}, alongX[3] = {6, 4, 3}, alongZ[3] = {3, 5, 7}, alongT[3] = {8, 9, 10};
  QueryValue position;
  for (int i = 0; i < 3; ++i) {
    std::array<std::string, 3> d;
    for (size_t j = 0; j < 3; ++j) {
      d[j] = addS(comp(p, i).d[j], addS(mulS(ch(alongX[i]), comp(p, 0).d[j]), mulS(ch(alongZ[i]), comp(p, 2).d[j])));
      if (j == 2) d[j] = addS(d[j], ch(alongT[i]));
    }
    position.push_back(o.bindScalar(0, i, comp(p, i).value + " + " + ch(value[i]), d));
  }
  return {position, {}, p};
}

}  // namespace

std::string QueryWriter::bind(const std::string& name, const std::string& expr) {
  bool simple = !expr.empty();
  for (char c : expr) simple = simple && (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.');
  if (simple) return expr;
  locals_.push_back({name, expr, false});
  return name;
}

void QueryWriter::statement(const std::string& name, const std::string& text) { locals_.push_back({name, text, true}); }

namespace {

// The identifiers in `expr` ("t0_s1", "sin", "1e38" too: numbers are harmless).
void addNames(const std::string& expr, std::set<std::string>& names) {
  for (size_t i = 0; i < expr.size();) {
    if (std::isalnum(static_cast<unsigned char>(expr[i])) || expr[i] == '_') {
      size_t j = i;
      while (j < expr.size() && (std::isalnum(static_cast<unsigned char>(expr[j])) || expr[j] == '_')) ++j;
      names.insert(expr.substr(i, j - i));
      i = j;
    } else {
      ++i;
    }
  }
}

}  // namespace

std::string QueryWriter::text(const std::vector<std::string>& roots) const {
  std::set<std::string> read;
  for (const std::string& r : roots) addNames(r, read);
  std::vector<bool> keep(locals_.size(), false);
  for (size_t k = locals_.size(); k-- > 0;)  // a local reads only earlier ones
    if (read.count(locals_[k].name)) {
      keep[k] = true;
      addNames(locals_[k].expr, read);
    }
  std::string text;
  for (size_t k = 0; k < locals_.size(); ++k)
    if (keep[k] && locals_[k].verbatim)
      text += locals_[k].expr;
    else if (keep[k])
      text += std::string(language_ == HeaderLanguage::C ? "  const double " : "  const ") + locals_[k].name + " = " +
              locals_[k].expr + ";\n";
  return text;
}

bool queryOpKnown(std::string_view type) {
  if (componentWiseFormula(type)) return true;
  for (std::string_view t : structuralTypes())
    if (t == type) return true;
  return type == "srgb_to_linear";
}

std::vector<QueryValue> queryOp(const Op& op, const std::vector<QueryValue>& in, QueryWriter& w, const std::string& name) {
  OpWriter o(op, w, name);
  const std::string& type = op.spec->type;
  if (const char* f = componentWiseFormula(type)) return componentWiseOp(op, f, in, o);
  if (type == "gerstner_waves") return gerstnerOp(op, in, o);
  if (type == "ocean_spectrum") return {QueryValue{{"0.0"}}};  // a marker: the state is `o`
  if (type == "ocean_displacement") return oceanDisplacementOp(op, in, w, o, name);
  if (type == "world_position") {
    QueryValue v{{"x0", {"1.0", kZero, kZero}}, {"0.0", {kZero, kZero, kZero}}, {"z0", {kZero, "1.0", kZero}}};
    return {v};
  }
  if (type == "time") return {QueryValue{{"t", {kZero, kZero, "1.0"}}}};
  if (type == "normal") return {QueryValue{{"0.0"}, {"1.0"}, {"0.0"}}};  // the flat mesh's normal
  auto each = [&](int port, auto value, auto derivative) {
    QueryValue out;
    for (int i = 0; i < o.count(port); ++i) {
      std::array<std::string, 3> d;
      for (size_t j = 0; j < 3; ++j) d[j] = derivative(i, j);
      out.push_back(o.bindScalar(port, i, value(i), d));
    }
    return out;
  };
  if (type == "vertex_output") {
    QueryValue position = each(
        0, [&](int i) { return comp(in[0], i).value + " + " + comp(in[1], i).value; },
        [&](int i, size_t j) { return addS(comp(in[0], i).d[j], comp(in[1], i).d[j]); });
    return {position, {}};
  }
  if (type == "swizzle") {
    std::string mask = op.options().value("mask", std::string("xyz"));
    QueryValue out;
    for (char c : mask) out.push_back(comp(in[0], nodes::math::swizzleIndex(c)));
    return {out};
  }
  if (type == "split") {
    std::vector<QueryValue> out;
    for (size_t i = 0; i < op.outputTypes.size(); ++i) out.push_back({comp(in[0], static_cast<int>(i))});
    return out;
  }
  if (type == "combine") {
    QueryValue out;
    for (int i = 0; i < o.count(0); ++i) out.push_back(comp(in[static_cast<size_t>(i)], 0));
    return {out};
  }
  if (type == "dot") {
    int n = componentCount(op.inputTypes.at(0));
    return {each(
        0, [&](int) { return dotValue(in[0], in[1], n); },
        [&](int, size_t j) { return dotDerivative(in[0], in[1], n, j); })};
  }
  if (type == "length") {
    int n = componentCount(op.inputTypes.at(0));
    std::string len = o.temp("len", "sqrt(" + dotValue(in[0], in[0], n) + ")");
    return {each(
        0, [&](int) { return len; },
        [&](int, size_t j) {
          std::string half = dotDerivative(in[0], in[0], n, j);  // d(a.a) = 2 a.da: halved below
          return isZero(half) ? kZero : "(" + len + " > 0.0 ? 0.5 * (" + half + ") / " + len + " : 0.0)";
        })};
  }
  if (type == "normalize") {
    int n = o.count(0);
    std::string l2 = o.temp("l2", dotValue(in[0], in[0], n));
    std::string k = o.temp("k", "1.0 / sqrt(wgd_max(" + l2 + ", 1e-30))");
    std::array<std::string, 3> adA;  // a . da per direction
    for (size_t j = 0; j < 3; ++j) {
      std::string s = kZero;
      for (int i = 0; i < n; ++i) s = addS(s, mulS(comp(in[0], i).value, comp(in[0], i).d[j]));
      adA[j] = isZero(s) ? kZero : o.temp(std::string("ad") + "xzt"[j], s);
    }
    return {each(
        0, [&](int i) { return comp(in[0], i).value + " * " + k; },
        [&](int i, size_t j) {
          const std::string& da = comp(in[0], i).d[j];
          if (isZero(da) && isZero(adA[j])) return kZero;
          // d(a k) = da k - a k^3 (a . da) where the floor does not hold k constant.
          return "(" + l2 + " > 1e-30 ? " + mulS(da, k) + " - " + comp(in[0], i).value + " * " + k + " * " + k + " * " + k +
                 " * (" + adA[j] + ") : " + mulS(da, k) + ")";
        })};
  }
  if (type == "cross") {
    auto c = [&](int k, int i) -> const QueryScalar& { return comp(in[static_cast<size_t>(k)], i); };
    auto term = [&](int i1, int i2) {  // a[i1] b[i2] - a[i2] b[i1]
      return std::pair{c(0, i1).value + " * " + c(1, i2).value + " - " + c(0, i2).value + " * " + c(1, i1).value,
                       [&, i1, i2](size_t j) {
                         std::string plus = addS(mulS(c(0, i1).d[j], c(1, i2).value), mulS(c(0, i1).value, c(1, i2).d[j]));
                         std::string minus = addS(mulS(c(0, i2).d[j], c(1, i1).value), mulS(c(0, i2).value, c(1, i1).d[j]));
                         return isZero(minus) ? plus : addS(plus, "-(" + minus + ")");
                       }};
    };
    const std::pair<int, int> axes[3] = {{1, 2}, {2, 0}, {0, 1}};
    return {each(
        0, [&](int i) { return term(axes[i].first, axes[i].second).first; },
        [&](int i, size_t j) { return term(axes[i].first, axes[i].second).second(j); })};
  }
  if (type == "compare" || type == "select") {
    static const std::map<std::string, std::string> ops = {{"less", "<"},  {"less_equal", "<="},   {"greater", ">"},
                                                           {"greater_equal", ">="}, {"equal", "=="}, {"not_equal", "!="}};
    auto rel = ops.find(op.options().value("op", std::string("less")));
    if (rel == ops.end()) o.refuse("unknown comparison");
    auto cond = [&](int i) { return comp(in[0], i).value + " " + rel->second + " " + comp(in[1], i).value; };
    if (type == "compare")
      return {each(0, [&](int i) { return "(" + cond(i) + " ? 1.0 : 0.0)"; }, [&](int, size_t) { return kZero; })};
    return {each(
        0, [&](int i) { return "(" + cond(i) + " ? " + comp(in[2], i).value + " : " + comp(in[3], i).value + ")"; },
        [&](int i, size_t j) {
          const std::string &a = comp(in[2], i).d[j], &b = comp(in[3], i).d[j];
          return isZero(a) && isZero(b) ? kZero : "(" + cond(i) + " ? " + a + " : " + b + ")";
        })};
  }
  if (type == "srgb_to_linear") {  // a colour parameter's linearisation: constant in x0, z0, t
    for (int i = 0; i < o.count(0); ++i)
      if (varies(comp(in[0], i))) o.refuse("its input varies with the position or time, and srgb_to_linear has no derivative form");
    return {each(
        0, [&](int i) { return i == 3 ? comp(in[0], i).value : "wgd_srgb_to_linear(" + comp(in[0], i).value + ")"; },
        [&](int, size_t) { return kZero; })};
  }
  o.refuse("node type '" + type + "' has no form for surface queries");
}

}  // namespace wg
