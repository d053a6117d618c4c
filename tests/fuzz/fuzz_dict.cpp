// Prints a libFuzzer dictionary for graph files: the format's keys and JSON tokens, and
// every node type, port, option and option choice in the registry, so the fuzzers reach
// the resolver and the emitters instead of spending their time on unknown names.
// scripts/fuzz.sh writes it to <build>/fuzz/graph.dict on every run (always current).
// With --formula: the words of the expression language instead (the formula target's
// dictionary): its functions, constructors, swizzles and operators.
#include <cstdio>
#include <set>
#include <string>

#include "core/expression_types.h"
#include "nodes/registry.h"

namespace {

std::set<std::string> formulaWords() {
  std::set<std::string> words = {"(", ")", ",", ".", "+", "-", "*", "/", "<", "<=", ">", ">=", "==", "!=", "?", ":",
                                 "vec2(", "vec3(", "vec4(", ".xyz", ".rgba", ".stp", "1.0", "0.5", "1e30", "1e-7",
                                 "a", "b", "c", "d"};
  for (const auto& f : wg::expr::formulaFunctions()) words.insert(std::string(f.name) + "(");
  return words;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "--formula") {
    int i = 0;
    for (const auto& w : formulaWords()) std::printf("f%d=\"%s\"\n", i++, w.c_str());
    return 0;
  }
  std::set<std::string> words = {
      "{", "}", "[", "]", ",", ":", "\"", "true", "false", "null", "-", ".", "e", "1e38", "3.5e38",
      "\"version\"", "\"name\"", "\"description\"", "\"parameters\"", "\"nodes\"", "\"outputs\"",
      "\"$schema\"", "\"id\"", "\"type\"", "\"options\"", "\"inputs\"", "\"editor\"", "\"x\"", "\"y\"",
      "\"default\"", "\"min\"", "\"max\"", "\"hint\"", "\"static\"", "\"color\"", "\"float\"", "\"vec2\"",
      "\"vec3\"", "\"vec4\"", "\"vertex\"", "\"fragment\"", "\"position\"", "\"normal\"", "\"alpha\"",
      "\"direction\"", "\"steepness\"", "\"wavelength\"", "\"amplitude\"", "\"phase\"", "\"builtin:foam\"",
      "\"builtin:dudv\"", "\"builtin:height\"", "\"builtin:water_normal\"", ".out", "$"};
  for (const wg::NodeSpec* s : wg::defaultRegistry().all()) {
    words.insert("\"" + s->type + "\"");
    for (const auto& p : s->inputs) words.insert("\"" + p.name + "\"");
    for (const auto& p : s->outputs) words.insert("." + p.name + "\"");
    for (const auto& o : s->options) {
      words.insert("\"" + o.name + "\"");
      for (const auto& c : o.choices) words.insert("\"" + c + "\"");
    }
  }
  int i = 0;
  for (const auto& w : words) {
    std::string escaped;
    for (char c : w) {
      if (c == '"' || c == '\\') escaped += '\\';
      escaped += c;
    }
    std::printf("w%d=\"%s\"\n", i++, escaped.c_str());
  }
}
