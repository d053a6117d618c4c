#include "codegen/derived_c_header.h"

#include <cmath>
#include <set>
#include <stdexcept>

#include "codegen/derived_vocabulary.h"
#include "core/interface_tables.h"
#include "core/number_format.h"

namespace wg {

namespace {

// The per-draw builtins a derived program may read, as the draw struct's members.
struct DrawMember {
  Builtin builtin;
  const char* name;
  int components;
  const char* comment;
};
const DrawMember kDrawMembers[] = {
    {Builtin::Time, "time", 1, "seconds"},
    {Builtin::CameraPosition, "camera_position", 3, "world space"},
    {Builtin::CameraNearFar, "camera_near_far", 2, "near and far planes; each clamped into [1e-6, 1e30] as the runtime does"},
    {Builtin::View, "view", 16, "world -> view, column-major"},
    {Builtin::Projection, "projection", 16, "view -> clip, column-major"},
    {Builtin::SunDirection, "sun_direction", 3, "unit vector towards the sun"},
};

bool isKeyword(const std::string& s) {
  static const std::set<std::string> k = {
      "auto",     "bool",     "break",    "case",     "catch",    "char",      "class",    "const",  "continue",
      "default",  "delete",   "do",       "double",   "else",     "enum",      "explicit", "extern", "false",
      "float",    "for",      "friend",   "goto",     "if",       "inline",    "int",      "long",   "mutable",
      "namespace", "new",     "operator", "private",  "protected", "public",   "register", "restrict", "return",
      "short",    "signed",   "sizeof",   "static",   "struct",   "switch",    "template", "this",   "throw",
      "true",     "try",      "typedef",  "typename", "union",    "unsigned",  "using",    "virtual", "void",
      "volatile", "while",    "and",      "or",       "not",      "xor",       "bitand",   "bitor",  "compl"};
  return k.count(s) > 0;
}

// A name a C preprocessor may hold as an object-like macro: what <math.h> defines
// (INFINITY, NAN, M_PI, FP_NAN, HUGE_VAL, math_errhandling, glibc's DOMAIN ...), and any
// name in capitals, the macro convention of C headers a program includes before this one.
bool mayBeMacro(const std::string& s) {
  if (s == "math_errhandling") return true;
  bool letter = false;
  for (char c : s) {
    if (std::islower(static_cast<unsigned char>(c))) return false;
    letter |= std::isupper(static_cast<unsigned char>(c)) != 0;
  }
  return letter;
}

// A parameter's name as a C member: other characters become '_', a leading digit gets
// '_' before it, and a C/C++ keyword or a possible macro name gets '_' after it (NAN is
// NAN_); a name C reserves (__x, _X) gets 'p' before it.
std::string identifier(const std::string& name) {
  std::string s;
  for (char c : name) s += (std::isalnum(static_cast<unsigned char>(c)) || c == '_') ? c : '_';
  if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) s = "_" + s;
  if (s.size() > 1 && s[0] == '_' && (s[1] == '_' || std::isupper(static_cast<unsigned char>(s[1])))) s = "p" + s;
  return isKeyword(s) || mayBeMacro(s) ? s + "_" : s;
}

// A C double literal: always with '.' or an exponent; infinities and NaN by macro.
std::string cNumber(double x) {
  if (std::isnan(x)) return "NAN";
  if (std::isinf(x)) return x > 0 ? "HUGE_VAL" : "-HUGE_VAL";
  std::string s = formatNumber(x);
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

std::string componentsList(const Value& v) {
  std::string s;
  for (int i = 0; i < v.size(); ++i) s += (i ? ", " : "") + cNumber(v[i]);
  return s;
}

std::string memberDecl(const std::string& name, int n) {
  return n == 1 ? name : name + "[" + std::to_string(n) + "]";
}

// The statements computing one derived value into `out` (a float array).
std::string derivedBody(const DerivedUniform& d, const std::vector<std::string>& parameterArrays) {
  const Program& p = d.value.program;
  std::string c = "  { /* " + d.uniform + " */\n";
  auto arrayOf = [&](const ValueRef& r, size_t opIndex, size_t input) -> std::string {
    switch (r.kind) {
      case ValueRef::Kind::Op: return "o" + std::to_string(r.index) + "_" + std::to_string(r.port);
      case ValueRef::Kind::Param: return parameterArrays.at(static_cast<size_t>(r.index));
      case ValueRef::Kind::Builtin: return "b_" + std::string(builtinName(static_cast<Builtin>(r.index)));
      case ValueRef::Kind::Const: return "k" + std::to_string(opIndex) + "_" + std::to_string(input);
      case ValueRef::Kind::None: break;
    }
    throw std::logic_error("derivedCHeader: unset input");
  };
  for (size_t k = 0; k < p.ops.size(); ++k) {
    const Op& op = p.ops[k];
    if (!isDerivedNodeType(op.spec->type))
      throw std::logic_error("derivedCHeader: node type '" + op.spec->type + "' is not in the derived vocabulary");
    std::vector<std::string> in, out;
    std::vector<Type> sourceTypes;
    for (size_t i = 0; i < op.inputs.size(); ++i) {
      const ValueRef& r = op.inputs[i];
      sourceTypes.push_back(p.typeOf(r));
      if (r.kind == ValueRef::Kind::Const) {  // an op may not read every input (combine's unused ones): -Wall
        std::string name = "k" + std::to_string(k) + "_" + std::to_string(i);
        c += "    const double " + name + "[" + std::to_string(r.constant().size()) + "] = {" + componentsList(r.constant()) +
             "};\n    (void)" + name + ";\n";
      }
      in.push_back(arrayOf(r, k, i));
    }
    for (size_t port = 0; port < op.outputTypes.size(); ++port) {
      std::string name = "o" + std::to_string(k) + "_" + std::to_string(port);
      out.push_back(name);
      if (op.outputTypes[port] != Type::Invalid)
        c += "    double " + name + "[" + std::to_string(componentCount(op.outputTypes[port])) + "];\n";
    }
    c += "    /* " + op.nodeId + ": " + op.spec->type + " */\n";
    std::string s = derivedOpC(op, in, sourceTypes, out);
    for (size_t at = 0; at < s.size();) {  // indent the op's statements into this block
      size_t end = s.find('\n', at);
      c += "  " + s.substr(at, end - at + 1);
      at = end + 1;
    }
    for (size_t port = 0; port < out.size(); ++port)  // split's other components may go unread
      if (op.outputTypes[port] != Type::Invalid) c += "    (void)" + out[port] + ";\n";
  }
  const std::string root = "o" + std::to_string(d.value.value.index) + "_" + std::to_string(d.value.value.port);
  for (int i = 0; i < componentCount(d.value.type); ++i)
    c += "    out->" + d.uniform + "[" + std::to_string(i) + "] = (float)" + root + "[" + std::to_string(i) + "];\n";
  return c + "  }\n";
}

}  // namespace

std::string derivedCPrefix(const std::string& graphName) { return "wg_" + identifier(graphName) + "_"; }

std::string derivedCHeader(const std::string& graphName, const std::vector<ProgramParameter>& parameters,
                           const std::vector<DerivedUniform>& derived) {
  const std::string prefix = derivedCPrefix(graphName);
  std::string guard;
  for (char c : prefix + "derived_h") guard += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  std::string h;
  h += "/* The derived uniforms of graph '" + graphName + "', generated by watergraph (compile --target c-header).\n";
  h += " * Do not edit: recompile the graph. Each derived uniform is a value the shader would compute\n";
  h += " * the same for every pixel; " + prefix + "compute_derived() computes it once per draw, in double,\n";
  h += " * as the watergraph runtime does. Set every uniform it fills (glUniform*, or the uniform block)\n";
  h += " * before each draw, after the parameters or the camera change. */\n";
  h += "#ifndef " + guard + "\n#define " + guard + "\n\n#include <math.h>\n\n";
  h += "#ifdef __cplusplus\nextern \"C\" {\n#endif\n\n";
  h += std::string(derivedCHelpers()) + "\n";

  // Parameters: every one the graph declares, so a struct filled once serves every draw.
  h += "/* The graph's parameters. Values outside a parameter's range are clamped into it (NaN to\n";
  h += " * its lower end), as the runtime clamps the uniforms it uploads. */\n";
  h += "typedef struct " + prefix + "parameters {\n";
  std::vector<std::string> members;
  for (const ProgramParameter& p : parameters) {
    std::string m = identifier(p.name);
    members.push_back(m);
    std::string range = "[" + (p.min ? formatNumber(*p.min) : std::string("-inf")) + ", " +
                        (p.max ? formatNumber(*p.max) : std::string("inf")) + "]";
    h += "  double " + memberDecl(m, componentCount(p.type)) + "; /* " + std::string(typeName(p.type)) + " " + range +
         ", default " + componentsList(p.defaultValue) + " */\n";
  }
  if (parameters.empty()) h += "  double unused; /* the graph has no parameter */\n";
  h += "} " + prefix + "parameters;\n\n";

  h += "/* What changes per draw. */\ntypedef struct " + prefix + "draw {\n";
  for (const DrawMember& m : kDrawMembers)
    h += "  double " + memberDecl(m.name, m.components) + "; /* " + m.comment + " */\n";
  h += "} " + prefix + "draw;\n\n";

  h += "/* The uniforms to set, by the names the shaders declare. */\ntypedef struct " + prefix + "derived {\n";
  for (const DerivedUniform& d : derived)
    h += "  float " + d.uniform + "[" + std::to_string(componentCount(d.value.type)) + "]; /* " +
         std::string(typeName(d.value.type)) + " */\n";
  if (derived.empty()) h += "  float unused; /* no derived uniform: the shaders compute everything */\n";
  h += "} " + prefix + "derived;\n\n";

  h += "/* The parameters' defaults, as the graph declares them. */\n";
  h += "static inline void " + prefix + "default_parameters(" + prefix + "parameters* p) {\n";
  for (size_t i = 0; i < parameters.size(); ++i)
    for (int c = 0; c < parameters[i].defaultValue.size(); ++c)
      h += "  p->" + members[i] + (componentCount(parameters[i].type) == 1 ? "" : "[" + std::to_string(c) + "]") +
           " = " + cNumber(parameters[i].defaultValue[c]) + ";\n";
  if (parameters.empty()) h += "  p->unused = 0.0;\n";
  h += "}\n\n";

  h += "static inline void " + prefix + "compute_derived(const " + prefix + "parameters* p, const " + prefix +
       "draw* d, " + prefix + "derived* out) {\n";
  std::vector<std::string> parameterArrays;
  for (size_t i = 0; i < parameters.size(); ++i) {
    const ProgramParameter& p = parameters[i];
    int n = componentCount(p.type);
    std::string a = "p" + std::to_string(i);
    parameterArrays.push_back(a);
    h += "  double " + a + "[" + std::to_string(n) + "]; /* " + p.name + ", clamped */\n";
    for (int c = 0; c < n; ++c) {
      std::string src = "p->" + members[i] + (n == 1 ? "" : "[" + std::to_string(c) + "]");
      std::string lo = p.min ? cNumber(*p.min) : "", hi = p.max ? cNumber(*p.max) : "";
      std::string v = src;
      if (p.min) v = "(" + v + " >= " + lo + " ? " + v + " : " + lo + ")";
      else if (p.max) v = "(" + v + " == " + v + " ? " + v + " : " + hi + ")";  // NaN to the upper end
      if (p.max) v = "wgd_min(" + v + ", " + hi + ")";
      h += "  " + a + "[" + std::to_string(c) + "] = " + v + ";\n";
    }
  }
  for (const DrawMember& m : kDrawMembers) {
    std::string b = "b_" + std::string(builtinName(m.builtin));
    if (m.builtin == Builtin::CameraNearFar) {
      h += "  double " + b + "[2];\n";
      for (int c = 0; c < 2; ++c)
        h += "  " + b + "[" + std::to_string(c) + "] = d->camera_near_far[" + std::to_string(c) + "] >= 1e-6 ? wgd_min(d->camera_near_far[" +
             std::to_string(c) + "], 1e30) : 1e-6;\n";
    } else if (m.components == 1) {
      h += "  const double* " + b + " = &d->" + m.name + ";\n";
    } else {
      h += "  const double* " + b + " = d->" + m.name + ";\n";
    }
  }
  for (const DerivedUniform& d : derived) h += derivedBody(d, parameterArrays);
  h += "  (void)p; (void)d; (void)out;\n";
  for (const std::string& a : parameterArrays) h += "  (void)" + a + ";\n";
  for (const DrawMember& m : kDrawMembers) h += "  (void)b_" + std::string(builtinName(m.builtin)) + ";\n";
  h += "}\n\n#ifdef __cplusplus\n}\n#endif\n\n#endif\n";
  return h;
}

}  // namespace wg
