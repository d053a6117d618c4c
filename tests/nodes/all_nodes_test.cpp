// Properties every registered node must have, so a new node is tested the moment it is
// registered: docs present, hard cases finite and in range, and the node compiles alone
// for every target with glslang accepting the result.
#include <cmath>

#include <gtest/gtest.h>

#include "codegen/compile.h"
#include "codegen/cpu_backend.h"
#include "core/graph_io.h"
#include "core/node_options.h"
#include "nodes/registry.h"
#include "nodes/texture_source.h"
#include "test_support.h"

namespace wg {
namespace {

// A literal JSON input that fits a port: floats for float/Gen ports, vectors otherwise.
nlohmann::json literalFor(const PortSpec& p) {
  Type t = p.kind == PortKind::Fixed ? p.type : p.kind == PortKind::Gen ? Type::Float : Type::Vec3;
  if (t == Type::Float) return 0.5;
  nlohmann::json a = nlohmann::json::array();
  for (int i = 0; i < componentCount(t); ++i) a.push_back(0.25 + 0.25 * i);
  return a;
}

// A graph that feeds every required input a literal and shows `output` as the colour.
std::string singleNodeGraph(const NodeSpec& spec, const std::string& output, Type outputType) {
  nlohmann::json node{{"id", "subject"}, {"type", spec.type}};
  nlohmann::json inputs = nlohmann::json::object();
  for (const auto& p : portsOfNode(spec, nlohmann::json::object()).inputs)  // an expression's: its default options
    if (p.required()) inputs[p.name] = literalFor(p);
  if (!inputs.empty()) node["inputs"] = inputs;
  nlohmann::json nodes = nlohmann::json::array({node});
  std::string colour = "subject." + output;
  if (outputType == Type::Vec2 || outputType == Type::Vec4) {
    nodes.push_back({{"id", "show"}, {"type", "swizzle"}, {"options", {{"mask", outputType == Type::Vec2 ? "xyx" : "xyz"}}},
                     {"inputs", {{"x", colour}}}});
    colour = "show.out";
  }
  nlohmann::json g{{"version", 1}, {"name", "single_" + spec.type}, {"nodes", nodes}};
  if (spec.stages & kFragmentStage)
    g["outputs"] = {{"fragment", {{"color", colour}}}};
  else
    g["outputs"] = {{"vertex", {{"position", colour}}}};
  return g.dump(2);
}

TEST(AllNodes, HaveDocumentation) {
  for (const NodeSpec* s : defaultRegistry().all()) {
    SCOPED_TRACE(s->type);
    EXPECT_FALSE(s->summary.empty());
    EXPECT_FALSE(s->formula.empty());
    EXPECT_FALSE(s->cost.empty());
    EXPECT_FALSE(s->family.empty());
    for (const auto& p : s->inputs) EXPECT_FALSE(p.doc.empty()) << "input " << p.name;
    for (const auto& p : s->outputs) EXPECT_FALSE(p.doc.empty()) << "output " << p.name;
    for (const auto& o : s->options) EXPECT_FALSE(o.doc.empty()) << "option " << o.name;
    EXPECT_GT(s->tolerance, 0.0);
  }
}

TEST(AllNodes, HardCasesStayFiniteAndInRange) {
  for (const NodeSpec* s : defaultRegistry().all()) {
    for (const HardCase& hc : s->hardCases) {
      SCOPED_TRACE(s->type + ": " + hc.name);
      TextureCache textures;
      std::vector<Value> outs = evaluateNode(*s, hc.options, hc.inputs, EvalEnvironment{}, &textures, test::sourceDir());
      // The output types resolve gives, to skip outputs that do not exist for these inputs.
      std::vector<Type> outputTypes;
      for (const auto& v : outs) outputTypes.push_back(v.type);
      int ranged = hc.output.empty() ? 0 : s->outputIndex(hc.output);
      ASSERT_GE(ranged, 0) << "hard case names unknown output " << hc.output;
      for (size_t o = 0; o < outs.size(); ++o) {
        if (outputTypes[o] == Type::Invalid) continue;
        for (int c = 0; c < outs[o].size(); ++c) {
          EXPECT_TRUE(std::isfinite(outs[o][c])) << "output " << s->outputs[o].name << "[" << c << "]";
          if (static_cast<int>(o) != ranged) continue;
          EXPECT_GE(outs[o][c], hc.lo - 1e-12) << "output " << s->outputs[o].name << "[" << c << "]";
          EXPECT_LE(outs[o][c], hc.hi + 1e-12) << "output " << s->outputs[o].name << "[" << c << "]";
        }
      }
    }
  }
}

TEST(AllNodes, EachCompilesAloneForEveryTarget) {
  for (const NodeSpec* s : defaultRegistry().all()) {
    for (size_t o = 0; o < s->outputs.size(); ++o) {
      const PortSpec& out = s->outputs[o];
      Type t = out.kind == PortKind::Fixed ? out.type : Type::Vec3;
      if (!isFloatScalarOrVector(t)) continue;
      // Custom outputs of split exist only for some inputs; the vec3 literal gives x, y, z.
      if (s->type == "split" && out.name == "w") continue;
      if (out.kind == PortKind::Custom && s->type == "swizzle") t = Type::Vec3;
      if (out.kind == PortKind::Custom && s->type == "split") t = Type::Float;
      if (out.kind == PortKind::Custom && s->type == "combine") t = Type::Vec3;
      SCOPED_TRACE(s->type + "." + out.name);
      std::string text = singleNodeGraph(*s, out.name, t);
      Diagnostics diags;
      auto graph = parseGraph(text, "single.json", diags);
      ASSERT_TRUE(graph) << text;
      auto result = compileGraph(*graph, defaultRegistry(), CompileOptions{}, diags);
      std::string messages;
      for (const auto& d : diags.all()) messages += formatText(d) + "\n";
      EXPECT_TRUE(result.has_value()) << messages << text;
    }
  }
}

}  // namespace
}  // namespace wg
