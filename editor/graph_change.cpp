#include "editor/graph_change.h"

#include "core/graph_io.h"

namespace wg::editor {

GraphChange compareGraphs(const Graph& before, const Graph& after) {
  GraphChange change;
  Graph a = before, b = after;
  for (auto& n : a.nodes) n.editorPosition.reset();
  for (auto& n : b.nodes) n.editorPosition.reset();
  a.frames.clear(), b.frames.clear();  // layout, as positions: never compiled
  if (a.parameters.size() == b.parameters.size()) {
    for (size_t i = 0; i < a.parameters.size(); ++i) {
      Parameter& pa = a.parameters[i];
      Parameter& pb = b.parameters[i];
      // A static parameter is folded into the shader: its value is code, not a uniform.
      if (pa.name != pb.name || pa.isStatic || pb.isStatic || pa.defaultValue == pb.defaultValue) continue;
      change.parameters.push_back(pb.name);
      pa.defaultValue = pb.defaultValue;
    }
  }
  // saveGraph is the canonical text: equal texts are equal graphs for the compiler.
  change.structural = saveGraph(a) != saveGraph(b);
  if (change.structural) change.parameters.clear();
  return change;
}

}  // namespace wg::editor
