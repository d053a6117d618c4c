#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/graph_io.h"
#include "diagnostic_text.h"

namespace wg {
namespace {

using core_test::dump;

Graph parseOk(const std::string& text) {
  Diagnostics d;
  auto g = parseGraph(text, "g.json", d);
  EXPECT_TRUE(g) << dump(d) << text;
  return g ? *g : Graph{};
}

// A messy but valid file: keys out of order, CRLF-free, numbers in odd spellings.
const char* kMessy = R"({
  "nodes": [
    {"type": "gerstner", "id": "waves", "editor": {"y": -20.5, "x": 10},
      "options": {"model": "ocean", "count": 4, "nested": {"z": [1, {"a": null}], "b": [], "c": {}, "d": 2.50}},
      "inputs": {"position": "vertexIn.position", "height": "$waveHeight", "dir": [1.0, 0]}},
    {"id": "shade", "type": "lambert", "inputs": {"k": 0.5e0, "albedo": "$deepColor"}}
  ],
  "outputs": {"fragment": {"alpha": 1, "color": "shade.color"}, "vertex": {"position": "waves.position"}},
  "version": 1, "name": "ocean", "description": "A \"test\" \\ graph \u00e9 \u0001 \ud83c\udf0a / \t",
  "parameters": {
    "waveHeight": {"static": false, "type": "float", "default": 5E-1, "min": 0, "max": 2},
    "deepColor": {"type": "vec3", "default": [0.1, 0.2, 0.3], "hint": "color", "static": true,
                  "description": "colour far down"}
  },
  "$schema": "https://example.com/watergraph-1.json"
}
)";

// Compact where it fits (100 columns): each parameter, node and container on one line
// unless that line would be longer; the parameter and node tables one entry per line.
const char* kCanonical = R"({
  "$schema": "https://example.com/watergraph-1.json",
  "version": 1,
  "name": "ocean",
  "description": "A \"test\" \\ graph é \u0001 🌊 / \t",
  "parameters": {
    "waveHeight": {"type": "float", "default": 0.5, "min": 0, "max": 2},
    "deepColor": {
      "type": "vec3",
      "default": [0.1, 0.2, 0.3],
      "hint": "color",
      "description": "colour far down",
      "static": true
    }
  },
  "nodes": [
    {
      "id": "waves",
      "type": "gerstner",
      "options": {
        "count": 4,
        "model": "ocean",
        "nested": {"b": [], "c": {}, "d": 2.5, "z": [1, {"a": null}]}
      },
      "inputs": {"dir": [1, 0], "height": "$waveHeight", "position": "vertexIn.position"},
      "editor": {"x": 10, "y": -20.5}
    },
    {"id": "shade", "type": "lambert", "inputs": {"albedo": "$deepColor", "k": 0.5}}
  ],
  "outputs": {
    "vertex": {"position": "waves.position"},
    "fragment": {"color": "shade.color", "alpha": 1}
  }
}
)";

void expectSameSource(const InputSource& a, const InputSource& b, const std::string& what) {
  EXPECT_EQ(a.kind, b.kind) << what;
  EXPECT_EQ(a.name, b.name) << what;
  EXPECT_EQ(a.port, b.port) << what;
  EXPECT_EQ(a.literal, b.literal) << what;
}

// Equal in everything the format defines (positions aside; options and inputs compared
// by name, since the canonical form sorts them).
void expectSameGraph(const Graph& a, const Graph& b) {
  EXPECT_EQ(a.schema, b.schema);
  EXPECT_EQ(a.version, b.version);
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.description, b.description);
  ASSERT_EQ(a.parameters.size(), b.parameters.size());
  for (size_t i = 0; i < a.parameters.size(); ++i) {
    const auto &p = a.parameters[i], &q = b.parameters[i];
    EXPECT_EQ(p.name, q.name);
    EXPECT_EQ(p.type, q.type);
    EXPECT_EQ(p.defaultValue, q.defaultValue);
    EXPECT_EQ(p.min, q.min);
    EXPECT_EQ(p.max, q.max);
    EXPECT_EQ(p.hint, q.hint);
    EXPECT_EQ(p.description, q.description);
    EXPECT_EQ(p.isStatic, q.isStatic);
  }
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  for (size_t i = 0; i < a.nodes.size(); ++i) {
    const auto &n = a.nodes[i], &m = b.nodes[i];
    EXPECT_EQ(n.id, m.id);
    EXPECT_EQ(n.type, m.type);
    EXPECT_EQ(n.editorPosition, m.editorPosition);
    ASSERT_EQ(n.options.size(), m.options.size());
    for (const auto& o : n.options) {
      auto it = std::find_if(m.options.begin(), m.options.end(),
                             [&](const NodeOption& x) { return x.name == o.name; });
      ASSERT_NE(it, m.options.end()) << o.name;
      EXPECT_EQ(o.value, it->value) << o.name;
    }
    ASSERT_EQ(n.inputs.size(), m.inputs.size());
    for (const auto& in : n.inputs) {
      auto it = std::find_if(m.inputs.begin(), m.inputs.end(),
                             [&](const NodeInput& x) { return x.port == in.port; });
      ASSERT_NE(it, m.inputs.end()) << in.port;
      expectSameSource(in.source, it->source, n.id + "." + in.port);
    }
  }
  ASSERT_EQ(a.outputs.size(), b.outputs.size());
  for (size_t i = 0; i < a.outputs.size(); ++i) {
    EXPECT_EQ(a.outputs[i].slot, b.outputs[i].slot);
    expectSameSource(a.outputs[i].source, b.outputs[i].source,
                     std::string(outputSlotName(a.outputs[i].slot)));
  }
}

TEST(GraphSave, CanonicalLayout) {
  Graph g = parseOk(kMessy);
  EXPECT_EQ(saveGraph(g), kCanonical);
}

TEST(GraphSave, FormattingIsIdempotent) {
  std::string once = saveGraph(parseOk(kMessy));
  std::string twice = saveGraph(parseOk(once));
  EXPECT_EQ(once, twice);
  EXPECT_EQ(saveGraph(parseOk(kCanonical)), kCanonical);
}

TEST(GraphSave, RoundTripKeepsEverything) {
  Graph g = parseOk(kMessy);
  Graph back = parseOk(saveGraph(g));
  expectSameGraph(g, back);
  EXPECT_EQ(back.description, "A \"test\" \\ graph \xC3\xA9 \x01 \xF0\x9F\x8C\x8A / \t");
}

TEST(GraphSave, ProgrammaticGraphRoundTrips) {
  Graph g;
  g.name = "built";
  Parameter p;
  p.name = "tint";
  p.type = Type::Vec4;
  p.defaultValue = {0.1, 1.0 / 3.0, 1e-7, 1};
  p.min = -0.0;
  p.max = 1e20;
  p.hint = "hdr_color";  // "color" would hold min and max within [0, 1]
  g.parameters.push_back(p);
  Node n;
  n.id = "mix";
  n.type = "mix";
  n.options.push_back({"zeta", nlohmann::json::parse(R"({"k": "q\"\\\u00e9", "a": [true, 1.5]})"),
                       {}, {}});
  n.options.push_back({"alpha", nlohmann::json(-3), {}, {}});
  NodeInput in;
  in.port = "b";
  in.source.kind = InputSource::Kind::Parameter;
  in.source.name = "tint";
  n.inputs.push_back(in);
  in.port = "a";
  in.source = {};
  in.source.kind = InputSource::Kind::Literal;
  in.source.literal = {0.1, 0.2};
  n.inputs.push_back(in);
  n.editorPosition = std::array<double, 2>{0.5, 123456789.25};
  g.nodes.push_back(n);
  GraphOutput o;
  o.slot = OutputSlot::FragmentAlpha;
  o.source.kind = InputSource::Kind::Literal;
  o.source.literal = {0.25};
  g.outputs.push_back(o);
  o.slot = OutputSlot::VertexNormal;
  o.source = {};
  o.source.kind = InputSource::Kind::NodeOutput;
  o.source.name = "mix";
  o.source.port = "out";
  g.outputs.push_back(o);

  std::string text = saveGraph(g);
  Graph back = parseOk(text);
  // The loader keeps outputs in slot order; compare against that.
  std::swap(g.outputs[0], g.outputs[1]);
  expectSameGraph(g, back);
  EXPECT_EQ(back.parameters[0].min, 0.0);
  EXPECT_EQ(saveGraph(back), text);
  EXPECT_NE(text.find("\"default\": [0.1, 0.3333333333333333, 1e-07, 1]"), std::string::npos) << text;
  EXPECT_NE(text.find("\"max\": 1e+20"), std::string::npos) << text;
  EXPECT_NE(text.find("\"min\": -0.0,"), std::string::npos) << text;  // -0 keeps its sign
  EXPECT_TRUE(std::signbit(*back.parameters[0].min));
  // Options and inputs are written sorted by name.
  EXPECT_LT(text.find("\"alpha\": -3"), text.find("\"zeta\""));
  EXPECT_LT(text.find("\"a\": [0.1, 0.2]"), text.find("\"b\": \"$tint\""));
  EXPECT_LT(text.find("\"normal\": \"mix.out\""), text.find("\"alpha\": 0.25"));
}

// A container goes on one line exactly when that line, from where it starts and with a
// comma after it, is at most 100 columns: the node below is 99 columns on its line at an id
// of 37 characters, and is split at 38.
TEST(GraphSave, ALineIsFoldedExactlyUpTo100Columns) {
  auto nodeLine = [](size_t idLength) {
    const std::string text = R"({"version": 1, "name": "g", "nodes": [{"id": ")" + std::string(idLength, 'n') +
                             R"(", "type": "mix", "inputs": {"a": 0.25, "b": 0.5}}], "outputs": {}})";
    const std::string saved = saveGraph(parseOk(text));
    const size_t at = saved.find("\"nodes\": [\n") + 11;  // the first line of the first node
    return saved.substr(at, saved.find('\n', at) - at);
  };
  const std::string fits = nodeLine(37);
  EXPECT_EQ(fits.size() + 1, 100u) << fits;  // + 1: the comma a following node would add
  EXPECT_EQ(fits.back(), '}') << "the whole node on one line: " << fits;
  EXPECT_EQ(nodeLine(38), "    {") << "one column more: one member per line";
  // However long, a number array stays on one line.
  std::string many;
  for (int i = 0; i < 40; ++i) many += (i ? ", " : "") + std::string("0.125");
  const std::string saved = saveGraph(parseOk(R"({"version": 1, "name": "g", "nodes": [{"id": "w", "type": "gerstner",
    "options": {"weights": [)" + many + R"(]}}], "outputs": {}})"));
  EXPECT_NE(saved.find("\"weights\": [" + many + "]\n"), std::string::npos) << saved;
  EXPECT_EQ(saveGraph(parseOk(saved)), saved);
}

// A graph as people write it by hand is already canonical: fmt leaves it as it is.
TEST(GraphSave, AHandWrittenCompactGraphIsLeftAsItIs) {
  const std::string text = R"({
  "version": 1,
  "name": "canal",
  "parameters": {
    "deep": {"type": "vec3", "default": [0.02, 0.1, 0.12], "min": 0, "max": 1, "hint": "color"}
  },
  "nodes": [
    {"id": "uv", "type": "uv"},
    {"id": "from_centre", "type": "sub", "inputs": {"a": "uv.out", "b": [0.5, 0.5]}},
    {"id": "tint", "type": "mix", "inputs": {"a": "$deep", "b": [0.1, 0.3, 0.3], "t": 0.5}},
    {
      "id": "shore",
      "type": "smoothstep",
      "inputs": {"edge0": 0, "edge1": 0.35, "x": "from_centre.out"},
      "editor": {"x": 40, "y": 120}
    }
  ],
  "outputs": {"fragment": {"color": "tint.out", "alpha": 1}}
}
)";
  EXPECT_EQ(saveGraph(parseOk(text)), text);
}

TEST(GraphSave, MinimalGraph) {
  Graph g;
  g.name = "g";
  GraphOutput o;
  o.slot = OutputSlot::FragmentColor;
  o.source.kind = InputSource::Kind::Literal;
  o.source.literal = {1, 0, 0, 1};
  g.outputs.push_back(o);
  EXPECT_EQ(saveGraph(g),
            "{\n"
            "  \"version\": 1,\n"
            "  \"name\": \"g\",\n"
            "  \"nodes\": [],\n"
            "  \"outputs\": {\"fragment\": {\"color\": [1, 0, 0, 1]}}\n"
            "}\n");
}

// A literal -0.0 keeps its sign through fmt (1 / -0 is -inf, 1 / 0 is +inf): it is written
// "-0.0", because a JSON reader takes "-0" for the integer 0; +0 stays "0".
TEST(GraphSave, NegativeZeroKeepsItsSign) {
  Graph g = parseOk(R"({"version": 1, "name": "z", "parameters": {"p": {"type": "vec2", "default": [-0.0, 0]}},
      "nodes": [], "outputs": {"fragment": {"alpha": -0.0}}})");
  std::string saved = saveGraph(g);
  EXPECT_NE(saved.find("\"alpha\": -0.0"), std::string::npos) << saved;
  EXPECT_NE(saved.find("\"default\": [-0.0, 0]"), std::string::npos) << saved;
  Graph again = parseOk(saved);
  ASSERT_EQ(again.outputs.size(), 1u);
  ASSERT_EQ(again.outputs[0].source.literal.size(), 1u);
  EXPECT_TRUE(std::signbit(again.outputs[0].source.literal[0]));
  EXPECT_FALSE(std::signbit(again.parameters[0].defaultValue[1]));
  EXPECT_EQ(saveGraph(again), saved);
}

TEST(GraphSave, CrlfInputSavesAsLf) {
  std::string crlf;
  for (const char* p = kMessy; *p; ++p) {
    if (*p == '\n') crlf += '\r';
    crlf += *p;
  }
  std::string text = saveGraph(parseOk(crlf));
  EXPECT_EQ(text.find('\r'), std::string::npos);
  EXPECT_EQ(text, kCanonical);
}

TEST(GraphSave, EscapesInStringsRoundTrip) {
  const std::string tricky = "q\"uote \\back\\slash\\ /sl\x01\x1f\n\t\xC3\xA9\xE6\xB0\xB4\xF0\x9F\x8C\x8A";
  Graph g = parseOk(
      R"({"version": 1, "name": "g", "nodes": [{"id": "n", "type": "t\"\\\u0041",
          "options": {"s": "q\"uote \\back\\slash\\ \/sl\u0001\u001f\n\t\u00e9\u6c34\ud83c\udf0a"}}],
          "outputs": {"fragment": {"alpha": 1}}})");
  ASSERT_EQ(g.nodes.size(), 1u);
  EXPECT_EQ(g.nodes[0].type, "t\"\\A");
  EXPECT_EQ(g.nodes[0].options[0].value, tricky);
  std::string text = saveGraph(g);
  Graph back = parseOk(text);
  EXPECT_EQ(back.nodes[0].type, "t\"\\A");
  EXPECT_EQ(back.nodes[0].options[0].value, tricky);
  EXPECT_EQ(saveGraph(back), text);
}

TEST(GraphSave, EndsWithOneNewline) {
  std::string text = saveGraph(parseOk(kMessy));
  ASSERT_GE(text.size(), 2u);
  EXPECT_EQ(text.back(), '\n');
  EXPECT_NE(text[text.size() - 2], '\n');
}

}  // namespace
}  // namespace wg
