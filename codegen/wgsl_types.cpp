#include "codegen/wgsl_types.h"

#include <algorithm>
#include <array>
#include <stdexcept>

namespace wg::wgsl {

ValueType glslType(std::string_view n) {
  if (n == "void") return {'v', 1, 0};
  if (n == "float") return {'f', 1, 0};
  if (n == "int") return {'i', 1, 0};
  if (n == "uint") return {'u', 1, 0};
  if (n == "bool") return {'b', 1, 0};
  if (n == "sampler2D") return {'t', 1, 0};
  if (n == "samplerCube") return {'c', 1, 0};
  if (n.size() == 4 && n.substr(0, 3) == "vec" && n[3] >= '2' && n[3] <= '4') return {'f', n[3] - '0', 0};
  if (n.size() == 5 && n.substr(1, 3) == "vec" && n[4] >= '2' && n[4] <= '4') {
    char b = n[0] == 'i' ? 'i' : n[0] == 'u' ? 'u' : n[0] == 'b' ? 'b' : '?';
    if (b != '?') return {b, n[4] - '0', 0};
  }
  if (n.size() == 4 && n.substr(0, 3) == "mat" && n[3] >= '2' && n[3] <= '4') return {'f', n[3] - '0', n[3] - '0'};
  throw std::logic_error("GLSL subset: type '" + std::string(n) + "' has no WGSL form here");
}

std::string wgslTypeName(const ValueType& t) {
  std::string scalar = t.base == 'f' ? "f32" : t.base == 'i' ? "i32" : t.base == 'u' ? "u32" : "bool";
  if (t.base == 't') return "texture_2d<f32>";
  if (t.base == 'c') return "texture_cube<f32>";
  if (t.base == 'v') return "";
  if (t.isMatrix()) return "mat" + std::to_string(t.cols) + "x" + std::to_string(t.size) + "<" + scalar + ">";
  if (t.size > 1) return "vec" + std::to_string(t.size) + "<" + scalar + ">";
  return scalar;
}

ValueType withBase(ValueType t, char base) {
  t.base = base;
  return t;
}

namespace {

// WGSL keywords and reserved words (WGSL section 15.1-15.2), predeclared type names, and the
// built-in functions the translator writes, sorted for binary search.
constexpr std::array kWgslUnusableNames = std::to_array<std::string_view>({
    "NULL", "Self", "abstract", "active", "alias", "alignas", "alignof", "all", "any", "array", "as", "asm",
    "asm_fragment", "async", "atan2", "atomic", "attribute", "auto", "await", "become", "binding_array", "bitcast",
    "bool", "break", "case", "cast", "catch", "class", "co_await", "co_return", "co_yield", "coherent",
    "column_major", "common", "compile", "compile_fragment", "concept", "const", "const_assert", "const_cast",
    "consteval", "constexpr", "constinit", "continue", "continuing", "crate", "debugger", "decltype", "default",
    "delete", "demote", "demote_to_helper", "diagnostic", "discard", "do", "dpdx", "dpdy", "dynamic_cast", "else",
    "enable", "enum", "explicit", "export", "extends", "extern", "external", "f16", "f32", "fallthrough", "false",
    "filter", "final", "finally", "fn", "for", "friend", "from", "fxgroup", "get", "goto", "groupshared", "highp",
    "i32", "if", "impl", "implements", "import", "inline", "instanceof", "interface", "inverseSqrt", "layout", "let",
    "loop", "lowp", "macro", "macro_rules", "mat2x2", "mat2x3", "mat2x4", "mat3x2", "mat3x3", "mat3x4", "mat4x2",
    "mat4x3", "mat4x4", "match", "mediump", "meta", "mod", "module", "move", "mut", "mutable", "namespace", "new",
    "nil", "noexcept", "noinline", "nointerpolation", "noperspective", "null", "nullptr", "of", "operator",
    "override", "package", "packoffset", "partition", "pass", "patch", "pixelfragment", "precise", "precision",
    "premerge", "priv", "protected", "ptr", "pub", "public", "readonly", "ref", "regardless", "register",
    "reinterpret_cast", "require", "requires", "resource", "restrict", "return", "sampler", "sampler_comparison",
    "select", "self", "set", "shared", "sizeof", "smooth", "snorm", "static", "static_assert", "static_cast", "std",
    "struct", "subroutine", "super", "switch", "target", "template", "textureDimensions", "textureLoad",
    "textureSample", "textureSampleBias", "textureSampleLevel", "texture_2d", "texture_cube", "this",
    "thread_local", "throw", "trait", "true", "try", "type", "typedef", "typeid", "typename", "typeof", "u32",
    "union", "unless", "unorm", "unsafe", "unsized", "use", "using", "var", "varying", "vec2", "vec3", "vec4",
    "virtual", "volatile", "wgsl", "where", "while", "with", "writeonly", "yield",
});

}  // namespace

std::string wgslSafeName(const std::string& name) {
  static const bool sorted = std::is_sorted(kWgslUnusableNames.begin(), kWgslUnusableNames.end());
  if (!sorted) throw std::logic_error("kWgslUnusableNames is not sorted");
  if (std::binary_search(kWgslUnusableNames.begin(), kWgslUnusableNames.end(), std::string_view(name)))
    return name + "_";
  return name;
}

}  // namespace wg::wgsl
