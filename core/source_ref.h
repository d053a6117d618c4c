#pragma once
#include <string>

namespace wg {

// Where something came from in a graph file: 1-based line and column, 0 when unknown.
struct SourceRef {
  std::string file;
  int line = 0;
  int col = 0;
};

}  // namespace wg
