#include "codegen/depfile.h"

namespace wg {
namespace {

std::string escaped(const std::string& path) {
  std::string out;
  for (char c : path) {
    if (c == '$') {
      out += "$$";
      continue;
    }
    if (c == ' ' || c == '#' || c == '\\') out += '\\';
    out += c;
  }
  return out;
}

}  // namespace

std::string depfileText(const std::vector<DepfileRule>& rules) {
  std::string text;
  for (const auto& rule : rules) {
    for (size_t i = 0; i < rule.outputs.size(); ++i) text += (i ? " " : "") + escaped(rule.outputs[i]);
    text += ":";
    for (const auto& in : rule.inputs) text += " \\\n  " + escaped(in);
    text += "\n";
  }
  return text;
}

}  // namespace wg
