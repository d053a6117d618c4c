#pragma once
// The graph `watergraph-editor --new FILE` starts from: two colour parameters, a Fresnel
// node and a mix, so that it compiles and shows water at once and every part of the editor
// has something to work on.
#include <string>

namespace wg::editor {

// The template's text in the canonical form (watergraph fmt's), named `name`; "" when
// `name` cannot be a graph's name (then "new_graph" is used).
std::string newGraphText(const std::string& name);

}  // namespace wg::editor
