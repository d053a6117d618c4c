#include "codegen/c_names.h"

#include <algorithm>

namespace wg {

namespace {

bool isLetter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isLower(char c) { return c >= 'a' && c <= 'z'; }

// C99 .. C23 and C++ keywords and alternative tokens. The C11 spellings with an
// underscore and a capital (_Bool) are reserved names and never plain anyway.
bool isKeyword(std::string_view s) {
  static const std::string_view k[] = {
      "alignas",   "alignof",   "and",          "and_eq",      "asm",          "auto",         "bitand",
      "bitor",     "bool",      "break",        "case",        "catch",        "char",         "char16_t",
      "char32_t",  "char8_t",   "class",        "co_await",    "co_return",    "co_yield",     "compl",
      "concept",   "const",     "const_cast",   "consteval",   "constexpr",    "constinit",    "continue",
      "decltype",  "default",   "delete",       "do",          "double",       "dynamic_cast", "else",
      "enum",      "explicit",  "export",       "extern",      "false",        "float",        "for",
      "friend",    "goto",      "if",           "inline",      "int",          "long",         "mutable",
      "namespace", "new",       "noexcept",     "not",         "not_eq",       "nullptr",      "operator",
      "or",        "or_eq",     "private",      "protected",   "public",       "register",     "reinterpret_cast",
      "requires",  "restrict",  "return",       "short",       "signed",       "sizeof",       "static",
      "static_assert", "static_cast", "struct", "switch",      "template",     "this",         "thread_local",
      "throw",     "true",      "try",          "typedef",     "typeid",       "typename",     "typeof",
      "typeof_unqual", "union", "unsigned",     "using",       "virtual",      "void",         "volatile",
      "wchar_t",   "while",     "xor",          "xor_eq"};
  return std::find(std::begin(k), std::end(k), s) != std::end(k);
}

// Object-like macros in lower case that a program including this header may have: what
// GCC and Clang predefine outside strict ISO modes (linux, unix, i386 ...), and what the
// standard C headers and glibc's common POSIX headers define (<errno.h>'s errno,
// <stdio.h>'s stdin, <complex.h>'s complex, <stdbool.h>'s bool, <sys/stat.h>'s st_atime,
// <signal.h>'s sa_handler ...). A function-like macro (isnan, assert) is not replaced in a
// member's name, which no '(' follows, and the function names all start with "wg".
bool isLowerCaseMacro(std::string_view s) {
  static const std::string_view m[] = {
      "alignas",     "alignof",      "bool",       "complex",    "errno",      "false",       "i386",
      "i486",        "i586",         "i686",       "imaginary",  "linux",      "math_errhandling",
      "mips",        "noreturn",     "sa_handler", "sa_sigaction", "si_addr", "si_band",     "si_fd",
      "si_pid",      "si_status",    "si_uid",     "si_value",   "sparc",      "st_atime",   "st_ctime",
      "st_mtime",    "static_assert", "stderr",    "stdin",      "stdout",     "sun",        "thread_local",
      "true",        "unix",         "vax"};
  return std::find(std::begin(m), std::end(m), s) != std::end(m);
}

bool startsWithIgnoringCase(std::string_view s, std::string_view prefix) {
  if (s.size() < prefix.size()) return false;
  for (size_t i = 0; i < prefix.size(); ++i)
    if ((s[i] | 0x20) != prefix[i]) return false;
  return true;
}

}  // namespace

bool isPlainCName(std::string_view s) {
  if (s.empty() || !isLetter(s[0]) || s.back() == '_') return false;
  bool lower = false;
  for (size_t i = 0; i < s.size(); ++i) {
    char c = s[i];
    if (!isLetter(c) && !isDigit(c) && c != '_') return false;
    if (c == '_' && s[i + 1] == '_') return false;  // s.back() != '_', so i + 1 is in range
    lower |= isLower(c);
  }
  if (!lower) return false;  // NAN, M_PI, DOMAIN: the macro convention
  if (startsWithIgnoringCase(s, "zz") || startsWithIgnoringCase(s, "wg")) return false;
  return !isKeyword(s) && !isLowerCaseMacro(s);
}

std::string cIdentifier(std::string_view name) {
  if (isPlainCName(name)) return std::string(name);
  static const char hex[] = "0123456789abcdef";
  std::string s = "zz";
  for (char c : name) {
    if (isLetter(c) || isDigit(c)) {
      s += c;
    } else {
      auto b = static_cast<unsigned char>(c);
      s += '_';
      s += hex[b >> 4];
      s += hex[b & 15];
    }
  }
  return s;
}

std::string cGraphPrefix(std::string_view graphName) { return "wg_" + cIdentifier(graphName) + "_"; }

std::string cIncludeGuard(std::string_view graphName, std::string_view kind) {
  return "WG_" + cIdentifier(graphName) + "_" + std::string(kind) + "_H";
}

const std::vector<std::string_view>& cHeaderSuffixes() {
  static const std::vector<std::string_view> s = {
      // codegen/query_c_header.cpp
      "params", "params_default", "displace", "height", "displace_batch", "height_batch", "surface_at",
      // codegen/query_ocean_c.cpp
      "ocean", "ocean_init", "ocean_update", "ocean_sample"};
  return s;
}

}  // namespace wg

namespace wg {

std::string cCommentText(std::string_view text) {
  std::string s;
  for (char c : text) {
    bool printable = c >= 0x20 && c < 0x7f;
    s += !printable || (c == '/' && !s.empty() && s.back() == '*') ? '?' : c;
  }
  return s;
}

}  // namespace wg
