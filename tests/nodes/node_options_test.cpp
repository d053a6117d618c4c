// Typed node options (core/node_options.h) and the checks around them: a node's options
// are parsed once into its struct, mistakes in a parse function or a hard case fail when
// the node is registered, the CPU reference refuses names a node does not have, and the
// registration check finds GLSL calls the library does not define.
#include <gtest/gtest.h>

#include "codegen/cpu_backend.h"
#include "core/diagnostic.h"
#include "core/emit_context.h"
#include "core/graph_io.h"
#include "core/registry.h"
#include "core/resolve.h"
#include "nodes/fresnel_reference.h"
#include "nodes/glsl_call_check.h"
#include "nodes/port_builders.h"
#include "nodes/registry.h"

namespace wg {
namespace {

enum class Shape { Round, Square };
struct ToyOptions {
  Shape shape;
  double size;
  bool on;
};

ToyOptions parseToy(const OptionReader& o) {
  return {o.choice<Shape>("shape", {{"round", Shape::Round}, {"square", Shape::Square}}), o.number("size"), o.flag("on")};
}

// A minimal valid node with three options; each test breaks one thing.
NodeSpec toyNode() {
  NodeSpec s;
  s.type = "toy";
  s.summary = "a test node";
  s.inputs = {ports::fixed("x", Type::Float, Value::scalar(1), "x")};
  s.outputs = {ports::fixed("out", Type::Float, "out")};
  s.options = {ports::choice("shape", {"round", "square"}, "round", "shape"), ports::number("size", 2, 0, 10, "size"),
               ports::flag("on", false, "on")};
  s.parseOptions = optionParser(parseToy);
  s.emit = [](EmitContext& ctx) { ctx.output(0, ctx.input(0)); };
  s.eval = [](EvalContext& ctx) {
    const ToyOptions& o = ctx.options<ToyOptions>();
    ctx.output(0, Value::scalar(ctx.input(0)[0] * o.size + (o.shape == Shape::Square ? 100 : 0) + (o.on ? 1000 : 0)));
  };
  return s;
}

std::string registrationError(NodeSpec s) {
  Registry r;
  try {
    r.add(std::move(s));
  } catch (const std::logic_error& e) {
    return e.what();
  }
  return "";
}

TEST(NodeOptions, ParsedFromTheSpecDefaultsAndTheGivenValues) {
  NodeSpec s = toyNode();
  auto defaults = parseOptions(s, completeOptions(s, nlohmann::json::object()));
  EXPECT_EQ(defaults->as<ToyOptions>().shape, Shape::Round);
  EXPECT_EQ(defaults->as<ToyOptions>().size, 2);
  auto given = parseOptions(s, completeOptions(s, {{"shape", "square"}, {"on", true}}));
  EXPECT_EQ(given->as<ToyOptions>().shape, Shape::Square);
  EXPECT_TRUE(given->as<ToyOptions>().on);
  EXPECT_THROW(given->as<nodes::FresnelSetup>(), std::logic_error);  // not the toy's struct
}

TEST(NodeOptions, AValidToyNodeRegisters) { EXPECT_EQ(registrationError(toyNode()), ""); }

// A texture option defaults to a builtin texture: a path would be relative to no graph, and
// resolve shares one completed default per type between graph files and subgraphs.
TEST(NodeOptions, ATextureOptionThatDefaultsToAPathFailsAtRegistration) {
  NodeSpec s = toyNode();
  s.options.push_back(ports::texture("map", "builtin:foam", "a texture"));
  EXPECT_EQ(registrationError(s), "");
  s.options.back() = ports::texture("map", "foam.png", "a texture");
  EXPECT_EQ(registrationError(s), "node spec 'toy': texture option 'map' must default to a builtin texture");
}

TEST(NodeOptions, ReadingAnUndeclaredOptionFailsAtRegistration) {
  NodeSpec s = toyNode();
  s.parseOptions = optionParser<ToyOptions>([](const OptionReader& o) -> ToyOptions {
    return {Shape::Round, o.number("sise"), o.flag("on")};
  });
  EXPECT_NE(registrationError(std::move(s)).find("does not declare: 'sise'"), std::string::npos);
}

TEST(NodeOptions, AnOptionTheParseNeverReadsFailsAtRegistration) {
  NodeSpec s = toyNode();
  s.parseOptions = optionParser<ToyOptions>([](const OptionReader& o) -> ToyOptions {
    return {o.is("shape", "square") ? Shape::Square : Shape::Round, o.number("size"), false};
  });
  EXPECT_NE(registrationError(std::move(s)).find("does not read option 'on'"), std::string::npos);
}

TEST(NodeOptions, ComparingWithAChoiceTheOptionLacksFailsAtRegistration) {
  NodeSpec s = toyNode();
  s.parseOptions = optionParser<ToyOptions>([](const OptionReader& o) -> ToyOptions {
    return {o.is("shape", "sqaure") ? Shape::Square : Shape::Round, o.number("size"), o.flag("on")};
  });
  EXPECT_NE(registrationError(std::move(s)).find("'sqaure', which is not one of its choices"), std::string::npos);
}

TEST(NodeOptions, AChoiceMappingMissingAChoiceFailsAtRegistration) {
  NodeSpec s = toyNode();
  s.parseOptions = optionParser<ToyOptions>([](const OptionReader& o) -> ToyOptions {
    return {o.choice<Shape>("shape", {{"round", Shape::Round}}), o.number("size"), o.flag("on")};
  });
  EXPECT_NE(registrationError(std::move(s)).find("does not name each of its choices"), std::string::npos);
}

TEST(NodeOptions, ReadingAnOptionAsAnotherKindFailsAtRegistration) {
  NodeSpec s = toyNode();
  s.parseOptions = optionParser<ToyOptions>([](const OptionReader& o) -> ToyOptions {
    return {Shape::Round, static_cast<double>(o.integer("size")), o.flag("on") || o.is("shape", "round")};
  });
  EXPECT_NE(registrationError(std::move(s)).find("read as another kind"), std::string::npos);
}

TEST(NodeOptions, OptionsWithoutAParseFunctionFailAtRegistration) {
  NodeSpec s = toyNode();
  s.parseOptions = nullptr;
  EXPECT_NE(registrationError(std::move(s)).find("without a parseOptions"), std::string::npos);
}

TEST(QualityKnob, LevelsAreValidDistinctValuesAndAtLeastTwo) {
  NodeSpec s = toyNode();
  s.options[1] = ports::knob(s.options[1], {1, 5, 10});
  EXPECT_EQ(registrationError(s), "");
  s.options[1].levels = {5};
  EXPECT_NE(registrationError(s).find("option 'size': a quality knob needs at least two levels"), std::string::npos);
  s.options[1].levels = {1, 11};  // size is in [0, 10]
  EXPECT_NE(registrationError(s).find("option 'size': level 11:"), std::string::npos) << registrationError(s);
  s.options[1].levels = {1, 1};
  EXPECT_NE(registrationError(s).find("level 1 listed twice"), std::string::npos);
  s.options[0] = ports::knob(s.options[0], {"round", "oval"});
  s.options[1].levels.clear();
  EXPECT_NE(registrationError(s).find("option 'shape': level \"oval\":"), std::string::npos) << registrationError(s);
}

TEST(Bypass, RegistrationAddsTheBypassKnob) {
  NodeSpec s = toyNode();
  s.bypass = {{"out", "x", std::nullopt}};
  Registry r;
  r.add(s);
  const NodeSpec* toy = r.find("toy");
  int i = toy->optionIndex(kBypassOption);
  ASSERT_GE(i, 0);
  const OptionSpec& o = toy->options[static_cast<size_t>(i)];
  EXPECT_EQ(o.defaultValue, false);
  EXPECT_EQ(o.levels, (std::vector<nlohmann::json>{true, false}));  // on is the cheaper level
  EXPECT_NE(o.doc.find("out = the input x"), std::string::npos) << o.doc;
  EXPECT_EQ(toyNode().optionIndex(kBypassOption), -1);  // only nodes that declare a bypass
}

TEST(Bypass, EveryOutputOnceByAnInputOrConstantOfItsType) {
  NodeSpec s = toyNode();
  s.outputs.push_back(ports::fixed("glow", Type::Vec3, "glow"));
  s.bypass = {{"out", "x", std::nullopt}};
  EXPECT_NE(registrationError(s).find("output 'glow' needs exactly one bypass value, has 0"), std::string::npos);
  s.bypass.push_back({"glow", "", Value::scalar(0)});
  EXPECT_NE(registrationError(s).find("output 'glow': the constant is not of its type"), std::string::npos);
  s.bypass.back() = {"glow", "x", std::nullopt};
  EXPECT_NE(registrationError(s).find("input 'x' is not of the type of 'glow'"), std::string::npos);
  s.bypass.back() = {"glow", "", Value::vector({0, 0, 0})};
  EXPECT_EQ(registrationError(s), "");
  s.bypass.push_back({"out", "", Value::scalar(0)});
  EXPECT_NE(registrationError(s).find("output 'out' needs exactly one bypass value, has 2"), std::string::npos);
  s.bypass.pop_back();
  s.bypass[0] = {"out", "x", Value::scalar(0)};
  EXPECT_NE(registrationError(s).find("an input or a constant, not both"), std::string::npos);
}

TEST(NodeOptions, AHardCaseNamingAPortOrOptionTheNodeLacksFailsAtRegistration) {
  NodeSpec s = toyNode();
  s.hardCases = {{"misspelt input", {{"xx", Value::scalar(1)}}, {}, "", 0, 1}};
  EXPECT_NE(registrationError(s).find("hard case 'misspelt input': no input 'xx'"), std::string::npos);
  s.hardCases = {{"misspelt option", {}, {{"shap", "square"}}, "", 0, 1}};
  EXPECT_NE(registrationError(s).find("no option 'shap'"), std::string::npos);
  s.hardCases = {{"bad value", {}, {{"shape", "triangle"}}, "", 0, 1}};
  EXPECT_NE(registrationError(s).find("'triangle' is not one of"), std::string::npos);
  s.hardCases = {{"misspelt output", {}, {}, "", 0, 1, "outt"}};
  EXPECT_NE(registrationError(s).find("no output 'outt'"), std::string::npos);
}

TEST(NodeOptions, TheCpuReferenceRefusesNamesTheNodeLacks) {
  NodeSpec s = toyNode();
  EvalEnvironment env;
  EXPECT_EQ(evaluateNode(s, {{"shape", "square"}}, {{"x", Value::scalar(3)}}, env)[0][0], 106);
  try {
    evaluateNode(s, nlohmann::json::object(), {{"xx", Value::scalar(3)}}, env);
    ADD_FAILURE() << "a misspelt input was evaluated";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "toy: no input 'xx'; it has: x");
  }
  try {
    evaluateNode(s, {{"shap", "square"}}, {}, env);
    ADD_FAILURE() << "a misspelt option was evaluated";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "toy: no option 'shap'; it has: shape, size, on");
  }
  EXPECT_THROW(evaluateNode(s, {{"size", 11}}, {}, env), std::invalid_argument);  // above its maximum
}

TEST(NodeOptions, ResolveParsesEachOpsOptionsOnce) {
  Diagnostics diags;
  auto graph = parseGraph(R"({"version": 1, "name": "g", "nodes": [
      {"id": "f", "type": "fresnel", "options": {"model": "exact", "ior": 1.5}}],
    "outputs": {"fragment": {"color": "f.reflectance"}}})",
                          "g.json", diags);
  ASSERT_TRUE(graph) << diags.all().front().message;
  auto program = resolveGraph(*graph, defaultRegistry(), diags);
  ASSERT_TRUE(program) << diags.all().front().message;
  ASSERT_EQ(program->ops.size(), 1u);
  const auto& o = program->ops[0].parsedOptions->as<nodes::FresnelSetup>();
  EXPECT_EQ(o.model, nodes::FresnelModel::Exact);
  EXPECT_EQ(o.ior, 1.5);
  EXPECT_FALSE(o.fromBelow);  // the spec's default direction
}

// A toy whose emit calls `fn` only under `when`, to show the check reaches each variant.
NodeSpec callingToy(std::function<std::string(EmitContext&)> fn) {
  NodeSpec s = toyNode();
  s.emit = [fn](EmitContext& ctx) { ctx.output(0, EmitContext::call(fn(ctx), {ctx.input(0)})); };
  return s;
}

TEST(GlslCallCheck, FindsAFunctionTheLibraryLacks) {
  const GlslLibrary& lib = GlslLibrary::builtin();
  EXPECT_NO_THROW(checkGlslCalls(callingToy([](EmitContext&) { return "wg_safe_normalize_vec3"; }), lib));
  try {
    checkGlslCalls(callingToy([](EmitContext&) { return "wg_safe_normalize_vec"; }), lib);
    ADD_FAILURE() << "a missing function passed";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("emit calls 'wg_safe_normalize_vec'"), std::string::npos) << e.what();
  }
}

TEST(GlslCallCheck, ReachesNonDefaultChoicesAndFactVariants) {
  const GlslLibrary& lib = GlslLibrary::builtin();
  EXPECT_THROW(checkGlslCalls(callingToy([](EmitContext& ctx) {
                                return ctx.options<ToyOptions>().shape == Shape::Square ? "wg_missing" : "wg_safe_normalize_vec3";
                              }),
                              lib),
               std::logic_error);
  EXPECT_THROW(checkGlslCalls(callingToy([](EmitContext& ctx) {
                                return ctx.options<ToyOptions>().on ? "wg_missing" : "wg_safe_normalize_vec3";
                              }),
                              lib),
               std::logic_error);
  EXPECT_THROW(checkGlslCalls(callingToy([](EmitContext& ctx) {
                                return ctx.inputFact(0).atLeast(1) ? "wg_missing" : "wg_safe_normalize_vec3";
                              }),
                              lib),
               std::logic_error);
}

}  // namespace
}  // namespace wg
