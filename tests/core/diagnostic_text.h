#pragma once
// Text of diagnostics and source positions for the core tests' failure messages.
#include <string>

#include "core/diagnostic.h"
#include "core/source_ref.h"

namespace wg::core_test {

// Every diagnostic as the CLI prints it, one per line.
inline std::string dump(const Diagnostics& d) {
  std::string s;
  for (const auto& e : d.all()) s += formatText(e) + "\n";
  return s;
}

// "line:col".
inline std::string lc(const SourceRef& r) { return std::to_string(r.line) + ":" + std::to_string(r.col); }

}  // namespace wg::core_test
