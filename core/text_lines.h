#pragma once
// A text's lines (without their '\n'), as views into it: for what must look at a line of
// a graph file after parsing (SARIF's UTF-16 columns, columns inside a JSON string).
#include <string_view>
#include <vector>

namespace wg {

std::vector<std::string_view> splitLines(std::string_view text);

}  // namespace wg
