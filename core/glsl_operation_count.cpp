#include "core/glsl_operation_count.h"

#include <array>
#include <atomic>
#include <stdexcept>
#include <string>

namespace wg {
namespace {

// Character classes by byte, so counting a piece is one table look-up per character.
enum : uint8_t { kOther = 0, kSpace = 1, kIdentStart = 2, kDigit = 4 };
constexpr std::array<uint8_t, 256> kClass = [] {
  std::array<uint8_t, 256> t{};
  for (int c = 0; c < 256; ++c) {
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f') t[c] = kSpace;
    if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_') t[c] = kIdentStart;
    if (c >= '0' && c <= '9') t[c] = kDigit;
  }
  return t;
}();
inline uint8_t classOf(char c) { return kClass[static_cast<unsigned char>(c)]; }
inline bool isIdentChar(char c) { return (classOf(c) & (kIdentStart | kDigit)) != 0; }

std::atomic<LibraryCallCost> gLibraryCallCost{nullptr};

}  // namespace

bool isFreeGlslCall(std::string_view name) {
  static constexpr std::array<std::string_view, 16> kFree = {"float", "int",  "uint",  "bool",  "vec2",  "vec3",
                                                             "vec4",  "ivec2", "ivec3", "ivec4", "mat3", "mat4",
                                                             "if",    "for",  "while", "return"};
  for (auto f : kFree)
    if (f == name) return true;
  return false;
}

void setLibraryCallCost(LibraryCallCost cost) { gLibraryCallCost.store(cost); }

int glslCallCost(std::string_view name) {
  if (isFreeGlslCall(name)) return 0;
  if (!name.starts_with("wg_")) return 1;
  LibraryCallCost library = gLibraryCallCost.load();
  if (!library)
    throw std::logic_error("the cost of library function '" + std::string(name) +
                           "' is asked before the GLSL library installed its costs (nodes/glsl_library_cost.h)");
  return library(name);
}

int countGlslOperations(std::string_view code, GlslOperationScan& s, GlslCallCost callCost, const void* context) {
  int cost = 0;
  size_t i = 0;
  const size_t n = code.size();
  // The first token of all the text counted so far decides what a join in front sees.
  auto token = [&s](bool sign, bool paren) {
    if (s.started) return;
    s.started = true;
    s.leadingSign = sign;
    s.leadingParen = paren;
  };
  while (i < n) {
    const char c = code[i];
    const uint8_t k = classOf(c);
    if (k == kSpace) {
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
    // An identifier that ended the previous piece is called when this token opens one.
    if (s.pendingCall >= 0) {
      if (c == '(') cost += s.pendingCall;
      s.pendingCall = -1;
    }
    if (k == kIdentStart) {
      const size_t start = i;
      while (i < n && isIdentChar(code[i])) ++i;
      const std::string_view name = code.substr(start, i - start);
      size_t j = i;
      while (j < n && classOf(code[j]) == kSpace) ++j;
      token(false, false);
      if (j == n) {
        // The piece ends here: whether it is a call, the next piece says.
        s.pendingCall = callCost(name, context);
        s.afterOperand = name != "return";
        continue;
      }
      const bool call = code[j] == '(';
      if (call) cost += callCost(name, context);
      s.afterOperand = !call && name != "return";
      continue;
    }
    if (k == kDigit || (c == '.' && i + 1 < n && classOf(code[i + 1]) == kDigit)) {
      // A number, its exponent's sign included (1e-30 holds no subtraction).
      while (i < n && (isIdentChar(code[i]) || code[i] == '.' ||
                       ((code[i] == '-' || code[i] == '+') && (code[i - 1] == 'e' || code[i - 1] == 'E'))))
        ++i;
      token(false, false);
      s.afterOperand = true;
      continue;
    }
    if (c == ')' || c == ']') {
      token(false, false);
      s.afterOperand = true;
      ++i;
      continue;
    }
    const char next = i + 1 < n ? code[i + 1] : '\0';
    if (c == '+' || c == '-') {
      if (next == c) {  // ++ / --
        token(false, false);
        cost += 1;
        i += 2;
        continue;
      }
      const bool counted = s.afterOperand || next == '=';  // binary, or a compound assignment
      token(!counted, false);
      if (counted) cost += 1;
      i += next == '=' ? 2 : 1;
      s.afterOperand = false;
      continue;
    }
    token(false, c == '(');
    if (c == '*' || c == '/' || c == '%' || c == '<' || c == '>' || c == '?') {
      cost += 1;
      i += next == '=' ? 2 : 1;  // <=, >=, *=, /=
      s.afterOperand = false;
      continue;
    }
    if (((c == '=' || c == '!') && next == '=') || ((c == '&' || c == '|') && next == c)) {  // == != && ||
      cost += 1;
      i += 2;
      s.afterOperand = false;
      continue;
    }
    // '=', '!', ',', '(', '[', ';', ':', '{', '}', '.': no operation of their own.
    s.afterOperand = false;
    ++i;
  }
  return cost;
}

int joinGlslOperations(GlslOperationScan& s, const GlslOperationScan& next) {
  if (!next.started) return 0;  // nothing but spaces: the state carries on
  int cost = 0;
  if (s.pendingCall >= 0 && next.leadingParen) cost += s.pendingCall;
  if (s.afterOperand && next.leadingSign) cost += 1;  // its sign is a subtraction here
  if (!s.started) {
    s.started = true;
    s.leadingSign = next.leadingSign;
    s.leadingParen = next.leadingParen;
  }
  s.afterOperand = next.afterOperand;
  s.pendingCall = next.pendingCall;
  return cost;
}

}  // namespace wg
