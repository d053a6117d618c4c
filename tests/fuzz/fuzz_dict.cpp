// Prints a libFuzzer dictionary for graph files: the format's keys and JSON tokens, and
// every node type, port, option and option choice in the registry, so the fuzzers reach
// the resolver and the emitters instead of spending their time on unknown names.
// scripts/fuzz.sh writes it to <build>/fuzz/graph.dict on every run (always current).
#include <cstdio>
#include <set>
#include <string>

#include "nodes/registry.h"

int main() {
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
