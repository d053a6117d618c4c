#pragma once
// The edit model's save-then-load property, shared by the property test
// (tests/core/graph_edit_property_test.cpp) and the fuzz target (fuzz_edit_ops.cpp): bytes
// choose a sequence of GraphEditor operations with hostile arguments (numbers past float32,
// NaN, -0.0, overlong strings, deep JSON, names that are not identifiers, undo and redo);
// whatever the editor accepts, its saved form must load back without an error and save to
// the same text. Header-only: the fuzz targets are single files.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/diagnostic.h"
#include "core/graph_edit.h"
#include "core/graph_io.h"
#include "nodes/registry.h"

namespace wg::fuzz {

// Reads choices from the bytes; past their end every choice is 0.
class ByteReader {
 public:
  explicit ByteReader(std::string_view bytes) : bytes_(bytes) {}
  bool done() const { return at_ >= bytes_.size(); }
  std::size_t pick(std::size_t n) {
    if (n == 0) return 0;
    std::size_t v = done() ? 0 : static_cast<unsigned char>(bytes_[at_++]);
    return v % n;
  }
  template <typename T, std::size_t N>
  const T& pickFrom(const T (&table)[N]) { return table[pick(N)]; }

 private:
  std::string_view bytes_;
  std::size_t at_ = 0;
};

inline double hostileNumber(ByteReader& r) {
  static const double kNumbers[] = {0.0,      -0.0,    1.0,    -1.0,   0.5,   1e-45,  1e-320, 65504.0,
                                    3.4e38,   -3.4e38, 3.4028234663852886e38, 3.4028235677973366e38,
                                    1e39,     -1e39,   1e300,  std::numeric_limits<double>::infinity(),
                                    -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN(),
                                    123.25,   -7.0};
  return r.pickFrom(kNumbers);
}

inline std::string hostileString(ByteReader& r) {
  switch (r.pick(12)) {
    case 0: return "";
    case 1: return "a";
    case 2: return "x";
    case 3: return "out";
    case 4: return "color";
    case 5: return "a b";
    case 6: return "1x";
    case 7: return "line\nbreak";
    case 8: return std::string(64, 'n');
    case 9: return std::string(65, 'n');
    case 10: return std::string(5000, 's');
    default: return "builtin:foam";
  }
}

inline nlohmann::json hostileJson(ByteReader& r) {
  switch (r.pick(7)) {
    case 0: return hostileNumber(r);
    case 1: return hostileString(r);
    case 2: return r.pick(2) == 1;
    case 3: return nullptr;
    case 4: {  // nested arrays, up to past the file's nesting limit
      nlohmann::json v = hostileNumber(r);
      std::size_t depth = r.pick(4) == 0 ? 70 : r.pick(8);
      for (std::size_t i = 0; i < depth; ++i) v = nlohmann::json::array({v});
      return v;
    }
    case 5: return nlohmann::json::object({{hostileString(r), hostileNumber(r)}});
    default: return static_cast<std::int64_t>(r.pick(256)) - 128;
  }
}

inline std::array<double, 2> hostilePosition(ByteReader& r) {
  return {r.pick(2) ? hostileNumber(r) : static_cast<double>(r.pick(256)), hostileNumber(r)};
}

// The property: "" when it holds, else what failed (with the saved text).
inline std::string editSequenceProperty(std::string_view bytes) {
  static const char* kBase =
      R"({"version": 1, "name": "edited",
          "parameters": {"level": {"type": "float", "default": 0.5, "min": 0, "max": 1},
                         "tint": {"type": "vec3", "default": [0.1, 0.2, 0.3]}},
          "presets": {"calm": {"level": 0.25}},
          "nodes": [{"id": "t", "type": "time"}, {"id": "s", "type": "sin", "inputs": {"x": "t.out"}}],
          "outputs": {"fragment": {"alpha": "s.out"}}})";
  Diagnostics baseDiags;
  auto base = parseGraph(kBase, "edited.json", baseDiags);
  if (!base) return "the base graph does not load";
  const Registry& registry = defaultRegistry();
  std::vector<const NodeSpec*> specs = registry.all();
  GraphEditor editor(*base, &registry);
  ByteReader r(bytes);
  for (int step = 0; step < 64 && !r.done(); ++step) {
    const Graph& g = editor.graph();
    auto someNode = [&]() -> std::string {
      if (g.nodes.empty() || r.pick(8) == 0) return hostileString(r);
      return g.nodes[r.pick(g.nodes.size())].id;
    };
    auto inputOf = [&](const std::string& node) -> std::string {
      const Node* n = g.findNode(node);
      const NodeSpec* spec = n ? registry.find(n->type) : nullptr;
      if (!spec || spec->inputs.empty() || r.pick(8) == 0) return hostileString(r);
      return spec->inputs[r.pick(spec->inputs.size())].name;
    };
    auto target = [&]() -> InputTarget {
      if (r.pick(4) == 0) {
        static const char* kSlots[] = {"vertex.position", "vertex.normal", "fragment.color", "fragment.alpha", "x.y"};
        return {"", r.pickFrom(kSlots)};
      }
      std::string node = someNode();
      return {node, inputOf(node)};
    };
    auto numbers = [&] {
      std::vector<double> v(r.pick(6));
      for (double& x : v) x = hostileNumber(r);
      return v;
    };
    switch (r.pick(13)) {
      case 0: {
        std::string type = r.pick(8) == 0 ? hostileString(r) : specs[r.pick(specs.size())]->type;
        editor.addNode(type, r.pick(2) ? "" : hostileString(r), hostilePosition(r));
        break;
      }
      case 1: editor.moveNode(someNode(), hostilePosition(r)); break;
      case 2: editor.deleteNode(someNode()); break;
      case 3: editor.setInputConstant(target(), numbers()); break;
      case 4: editor.setInputParameter(target(), r.pick(3) == 0 ? hostileString(r) : (r.pick(2) ? "level" : "tint")); break;
      case 5: {
        std::string from = someNode();
        const Node* n = g.findNode(from);
        const NodeSpec* spec = n ? registry.find(n->type) : nullptr;
        std::string port = spec && !spec->outputs.empty() && r.pick(8) != 0
                               ? spec->outputs[r.pick(spec->outputs.size())].name
                               : hostileString(r);
        editor.connect(from, port, target());
        break;
      }
      case 6: editor.disconnect(target()); break;
      case 7: {
        std::string node = someNode();
        const Node* n = g.findNode(node);
        const NodeSpec* spec = n ? registry.find(n->type) : nullptr;
        std::string name = spec && !spec->options.empty() && r.pick(8) != 0
                               ? spec->options[r.pick(spec->options.size())].name
                               : hostileString(r);
        editor.setOption(node, name, hostileJson(r));
        break;
      }
      case 8: editor.setParameterDefault(r.pick(2) ? "level" : "tint", numbers()); break;
      case 9: editor.applyPreset(r.pick(4) ? "calm" : hostileString(r)); break;
      case 10: editor.undo(); break;
      case 11: editor.redo(); break;
      default: editor.seal(); break;
    }
  }
  std::string saved = saveGraph(editor.graph());
  Diagnostics diags;
  auto loaded = parseGraph(saved, "edited.json", diags);
  if (!loaded || diags.hasErrors()) {
    std::string why = "the editor's saved graph does not load back:";
    for (const auto& d : diags.sorted()) why += "\n  " + formatText(d).substr(0, 300);
    return why + "\n" + saved.substr(0, 4000);
  }
  if (saveGraph(*loaded) != saved) return "the editor's saved graph loads back different:\n" + saved.substr(0, 4000);
  return "";
}

}  // namespace wg::fuzz
