// Properties every registered node must have, so a new node is tested the moment it is
// registered: docs present, hard cases finite and in range, and the node compiles alone
// for every target with glslang accepting the result.
#include <cctype>
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

bool isOceanPort(const PortSpec& p) { return p.kind == PortKind::Fixed && p.type == Type::Ocean; }

// An `ocean` input takes no literal: an ocean_spectrum node (its defaults) feeds it.
const nlohmann::json kSeaNode = {{"id", "sea"}, {"type", "ocean_spectrum"}};

// A graph that feeds every required input a literal and shows `output` as the colour.
std::string singleNodeGraph(const NodeSpec& spec, const std::string& output, Type outputType) {
  nlohmann::json node{{"id", "subject"}, {"type", spec.type}};
  nlohmann::json inputs = nlohmann::json::object();
  bool sea = false;
  for (const auto& p : portsOfNode(spec, nlohmann::json::object()).inputs) {  // an expression's: its default options
    if (isOceanPort(p)) {
      inputs[p.name] = "sea.ocean";
      sea = true;
    } else if (p.required()) {
      inputs[p.name] = literalFor(p);
    }
  }
  if (!inputs.empty()) node["inputs"] = inputs;
  nlohmann::json nodes = nlohmann::json::array({node});
  if (sea) nodes.push_back(kSeaNode);
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
    // A node whose every output is a handle (an ocean) has no value to hold to a tolerance.
    bool handlesOnly = !s->outputs.empty();
    for (const auto& p : s->outputs) handlesOnly = handlesOnly && p.kind == PortKind::Fixed && isOpaque(p.type);
    if (!handlesOnly) {
      EXPECT_GT(s->tolerance, 0.0);
    }
  }
}

TEST(AllNodes, HardCasesStayFiniteAndInRange) {
  for (const NodeSpec* s : defaultRegistry().all()) {
    for (const HardCase& hc : s->hardCases) {
      SCOPED_TRACE(s->type + ": " + hc.name);
      TextureCache textures;
      auto inputs = hc.inputs;
      for (const auto& p : s->inputs)
        if (isOceanPort(p))
          inputs.emplace_back(p.name, evaluateNode(*defaultRegistry().find("ocean_spectrum"), hc.oceanOptions, {},
                                                   EvalEnvironment{}, &textures, test::sourceDir())[0]);
      std::vector<Value> outs = evaluateNode(*s, hc.options, inputs, EvalEnvironment{}, &textures, test::sourceDir());
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

// Each output read alone, every input a (uniform) parameter so nothing folds: the shader
// declares no local of a node that it never reads. What the outputs do not reach is not
// emitted, also inside a node with several outputs (before, phong_specular wrote its
// environment lobe when only its sun term was read, and blinn_phong, ggx_specular,
// normal_from_height, sine_normals and ssr their unread terms likewise).
TEST(AllNodes, NoOutputReadAloneLeavesAnUnreadTemporary) {
  int checked = 0;
  for (const NodeSpec* s : defaultRegistry().all()) {
    if (s->outputs.size() < 2) continue;
    for (size_t o = 0; o < s->outputs.size(); ++o) {
      const PortSpec& out = s->outputs[o];
      Type t = out.kind == PortKind::Fixed ? out.type : Type::Vec3;
      if (!isFloatScalarOrVector(t) || out.kind == PortKind::Custom) continue;
      SCOPED_TRACE(s->type + "." + out.name);
      nlohmann::json g = nlohmann::json::parse(singleNodeGraph(*s, out.name, t));
      nlohmann::json params = nlohmann::json::object(), inputs = nlohmann::json::object();
      for (const auto& p : portsOfNode(*s, nlohmann::json::object()).inputs) {
        if (p.derived) continue;  // computed by the node itself
        if (isOceanPort(p)) {  // singleNodeGraph added the sea that feeds it
          inputs[p.name] = "sea.ocean";
          continue;
        }
        nlohmann::json literal = literalFor(p);
        std::string type = literal.is_number() ? "float" : "vec" + std::to_string(literal.size());
        params["in_" + p.name] = {{"type", type}, {"default", literal}};
        inputs[p.name] = "$in_" + p.name;
      }
      g["nodes"][0]["inputs"] = inputs;
      g["parameters"] = params;
      Diagnostics diags;
      auto graph = parseGraph(g.dump(), "single.json", diags);
      ASSERT_TRUE(graph) << g.dump();
      CompileOptions options;
      options.targets = {Target::Glsl330};
      options.validate = false;
      auto result = compileGraph(*graph, defaultRegistry(), options, diags);
      std::string messages;
      for (const auto& d : diags.all()) messages += formatText(d) + "\n";
      EXPECT_TRUE(result) << messages << g.dump();
      if (!result) continue;
      for (const auto& f : result->files) {
        size_t main = f.contents.find("void main");
        if (main == std::string::npos) continue;
        const std::string body = f.contents.substr(main);
        // Each local the body declares ("  float n0_subject_t1 = ...") must be read after it.
        for (size_t at = body.find("\n  "); at != std::string::npos; at = body.find("\n  ", at + 1)) {
          size_t space = body.find(' ', at + 3), eq = body.find(" = ", at + 3), eol = body.find('\n', at + 1);
          if (space == std::string::npos || eq == std::string::npos || eq > eol || space > eq) continue;
          std::string name = body.substr(space + 1, eq - space - 1);
          // A node's locals: "<op>_t<k>" (an op's own output lines are pruned by op).
          size_t t = name.rfind("_t");
          if (name.rfind('n', 0) != 0 || t == std::string::npos || t + 2 == name.size() ||
              name.find_first_not_of("0123456789", t + 2) != std::string::npos)
            continue;
          ++checked;
          bool read = false;
          for (size_t k = body.find(name, eq); k != std::string::npos && !read; k = body.find(name, k + 1)) {
            char after = k + name.size() < body.size() ? body[k + name.size()] : ' ';
            char before = body[k - 1];
            read = !(std::isalnum(static_cast<unsigned char>(after)) || after == '_') &&
                   !(std::isalnum(static_cast<unsigned char>(before)) || before == '_');
          }
          EXPECT_TRUE(read) << f.name << " declares " << name << " and never reads it";
        }
      }
    }
  }
  EXPECT_GT(checked, 20) << "the scan found the nodes' locals";
}

}  // namespace
}  // namespace wg
