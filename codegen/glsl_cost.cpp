#include "codegen/glsl_cost.h"

#include <array>
#include <cctype>

namespace wg {
namespace {

bool isIdentStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool isIdentChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Names followed by '(' that are no operation: constructors and statement keywords.
bool isFreeCall(std::string_view name) {
  static constexpr std::array<std::string_view, 16> kFree = {"float", "int",  "uint",  "bool", "vec2",  "vec3",
                                                             "vec4",  "ivec2", "ivec3", "ivec4", "mat3", "mat4",
                                                             "if",    "for",  "while", "return"};
  for (auto f : kFree)
    if (f == name) return true;
  return false;
}

}  // namespace

int GlslCost::ofFunction(const std::string& name) {
  if (auto it = functions_.find(name); it != functions_.end()) return it->second;
  functions_[name] = 0;  // GLSL has no recursion; this only keeps a malformed library finite
  int cost = 0;
  for (const auto& item : library_.items())
    if (item.name == name) {
      // The body only: the signature "float wg_f(float x)" would read as a call of itself.
      size_t open = item.text.find('{');
      if (open != std::string::npos) cost = of(std::string_view(item.text).substr(open));
      break;
    }
  functions_[name] = cost;
  return cost;
}

int GlslCost::of(std::string_view code) {
  int cost = 0;
  // Whether the last significant token ends an operand: then '+'/'-' are binary.
  bool afterOperand = false;
  size_t i = 0;
  const size_t n = code.size();
  while (i < n) {
    char c = code[i];
    if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
      continue;
    }
    if (c == '/' && i + 1 < n && code[i + 1] == '/') {
      while (i < n && code[i] != '\n') ++i;
      continue;
    }
    if (c == '/' && i + 1 < n && code[i + 1] == '*') {
      size_t end = code.find("*/", i + 2);
      i = end == std::string_view::npos ? n : end + 2;
      continue;
    }
    if (isIdentStart(c)) {
      size_t start = i;
      while (i < n && isIdentChar(code[i])) ++i;
      std::string_view name = code.substr(start, i - start);
      size_t j = i;
      while (j < n && std::isspace(static_cast<unsigned char>(code[j]))) ++j;
      bool call = j < n && code[j] == '(';
      if (call && name.starts_with("wg_")) cost += ofFunction(std::string(name));
      else if (call && !isFreeCall(name)) cost += 1;
      afterOperand = !call && name != "return";
      continue;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || (c == '.' && i + 1 < n && std::isdigit(static_cast<unsigned char>(code[i + 1])))) {
      // A number, its exponent's sign included (1e-30 holds no subtraction).
      while (i < n && (isIdentChar(code[i]) || code[i] == '.' ||
                       ((code[i] == '-' || code[i] == '+') && (code[i - 1] == 'e' || code[i - 1] == 'E'))))
        ++i;
      afterOperand = true;
      continue;
    }
    if (c == ')' || c == ']') {
      afterOperand = true;
      ++i;
      continue;
    }
    char next = i + 1 < n ? code[i + 1] : '\0';
    if (c == '+' || c == '-') {
      if (next == c) {  // ++ / --
        cost += 1;
        i += 2;
        continue;
      }
      if (afterOperand || next == '=') cost += 1;  // binary, or a compound assignment
      i += next == '=' ? 2 : 1;
      afterOperand = false;
      continue;
    }
    if (c == '*' || c == '/' || c == '%' || c == '<' || c == '>' || c == '?') {
      cost += 1;
      i += next == '=' ? 2 : 1;  // <=, >=, *=, /=
      afterOperand = false;
      continue;
    }
    if ((c == '=' || c == '!') && next == '=') {  // == and !=
      cost += 1;
      i += 2;
      afterOperand = false;
      continue;
    }
    if ((c == '&' || c == '|') && next == c) {  // && and ||
      cost += 1;
      i += 2;
      afterOperand = false;
      continue;
    }
    // '=', '!', ',', '(', '[', ';', ':', '{', '}', '.': no operation of their own.
    afterOperand = false;
    ++i;
  }
  return cost;
}

}  // namespace wg
