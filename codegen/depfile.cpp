#include "codegen/depfile.h"

#include <string_view>

namespace wg {
namespace {

// Characters that end a path for Ninja's depfile lexer (which has no escape for them) or
// that Make takes for syntax even after a backslash (';' starts a recipe, '=' an
// assignment, '|' order-only prerequisites); found by writing each printable ASCII
// character into a depfile and reading it back with both (tests/codegen/depfile_test.cpp).
constexpr std::string_view kUnreadable = "\"&'*;<>?^`|=";

std::string escaped(const std::string& path) {
  std::string out;
  for (std::size_t i = 0; i < path.size(); ++i) {
    char c = path[i];
    if (c == '$') {
      out += "$$";
    } else if (c == ' ' || c == '#' || c == ':') {
      out += '\\';
      out += c;
    } else if (c == '\\') {
      // A run of backslashes before a space is doubled, so that "\\\ " reads back as "\ ".
      std::size_t end = path.find_first_not_of('\\', i);
      bool beforeSpace = end != std::string::npos && path[end] == ' ';
      std::size_t run = (end == std::string::npos ? path.size() : end) - i;
      out.append(beforeSpace ? 2 * run : run, '\\');
      i += run - 1;
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace

std::string depfilePathProblem(const std::string& path) {
  for (std::size_t i = 0; i < path.size(); ++i) {
    auto u = static_cast<unsigned char>(path[i]);
    if (path[i] == '\n' || path[i] == '\r') return "it holds a line break, which ends a rule in a depfile";
    if (u < 0x20 || u == 0x7f) return "it holds a control character, which Make and Ninja read as a separator";
    if (kUnreadable.find(path[i]) != std::string_view::npos)
      return std::string("it holds '") + path[i] + "', which Make or Ninja cannot read back in a depfile";
    if (path[i] == '\\') {
      std::size_t end = path.find_first_not_of('\\', i);
      if (end == std::string::npos) return "it ends in a backslash, which a depfile reads as a line continuation";
      if (path[end] == '#') return "it holds a backslash before '#', which Make and Ninja read differently";
      i = end - 1;
    }
  }
  return "";
}

std::optional<std::string> depfileText(const std::vector<DepfileRule>& rules, const std::string& depfile,
                                       Diagnostics& diags) {
  std::string text;
  bool ok = true;
  auto add = [&](const std::string& path) {
    if (std::string why = depfilePathProblem(path); !why.empty()) {
      diags.error(DiagCode::FileWrite, SourceRef{depfile, 0, 0}, "cannot write '" + path + "' into the depfile: " + why);
      ok = false;
    }
    return escaped(path);
  };
  for (const auto& rule : rules) {
    for (size_t i = 0; i < rule.outputs.size(); ++i) text += (i ? " " : "") + add(rule.outputs[i]);
    text += ":";
    for (const auto& in : rule.inputs) text += " \\\n  " + add(in);
    text += "\n";
  }
  if (!ok) return std::nullopt;
  return text;
}

}  // namespace wg
