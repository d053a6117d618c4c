// Per-draw splits (PortSpec::derived, NodeSpec::derive): the part of a node that is the same
// for every pixel of a draw (a scroll fract(speed * time), the near/far ratio of a depth
// linearisation, the camera axis) is computed by ops of its own, which the frequency
// analysis classifies per-draw, while the node computes what it did before.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "codegen/compile.h"
#include "codegen/cpu_backend.h"
#include "codegen/frequency.h"
#include "nodes/eval_math.h"
#include "nodes/shading_reference.h"
#include "nodes/texture_source.h"
#include "pass_test_support.h"

namespace wg {
namespace {

using namespace passtest;


// Node `id`'s own op (of its type, among the ops it derived): each derived input named in
// `feeds` (port -> node type) is read from an op of that type that is per-draw.
void expectDerivedPerDraw(const std::string& json, const std::string& id, const std::string& type,
                          const std::vector<std::pair<std::string, std::string>>& feeds) {
  Program p = finalProgram(json);
  auto f = analyseFrequency(p);
  const Op* own = nullptr;
  for (const auto& op : p.ops)
    if (op.nodeId == id && op.spec->type == type) own = &op;
  ASSERT_NE(own, nullptr) << "no " << type << " op for node " << id;
  for (const auto& [port, feeder] : feeds) {
    int pi = own->spec->inputIndex(port);
    ASSERT_GE(pi, 0) << port;
    ASSERT_TRUE(own->spec->inputs[static_cast<size_t>(pi)].derived) << port;
    const ValueRef& in = own->inputs[static_cast<size_t>(pi)];
    ASSERT_EQ(in.kind, ValueRef::Kind::Op) << type << "." << port << " is not read from an op";
    const Op& from = p.ops[static_cast<size_t>(in.index)];
    EXPECT_EQ(from.spec->type, feeder) << type << "." << port;
    EXPECT_EQ(from.nodeId, id) << "the derived op carries the node's id";
    EXPECT_EQ(f[static_cast<size_t>(in.index)], Frequency::PerDraw) << type << "." << port;
  }
  // The node's own op still varies per pixel: only its per-draw part moved out.
  EXPECT_EQ(f[static_cast<size_t>(own - p.ops.data())], Frequency::PerFragment);
}

std::vector<Value> evaluate(const std::string& type, const std::vector<std::pair<std::string, Value>>& inputs,
                            const EvalEnvironment& env = EvalEnvironment{}) {
  static TextureCache textures;
  return evaluateNode(*defaultRegistry().find(type), nlohmann::json::object(), inputs, env, &textures, test::sourceDir());
}

// A node that derives inputs, with a parameter of every type wired into each input it
// takes: the graph compiles, or the node's own type error (WG029) says which input, never an
// internal error. (The graphgen fuzzer found a vec4 into linearize_depth's vec2 near_far
// throwing from the derive; tests/bad/WG029_vec4_into_derived_source.json keeps it.)
TEST(PerDrawSplit, AnyTypeWiredIntoADerivingNodeIsCompiledOrItsTypeError) {
  int deriving = 0, refused = 0;
  for (const NodeSpec* spec : defaultRegistry().all()) {
    if (!spec->derive) continue;
    ++deriving;
    for (const PortSpec& port : spec->inputs) {
      if (port.derived) continue;
      for (const char* type : {"float", "vec2", "vec3", "vec4"}) {
        SCOPED_TRACE(spec->type + "." + port.name + " <- " + type);
        nlohmann::json value = std::string(type) == "float" ? nlohmann::json(0.5) : nlohmann::json::array();
        for (int i = 0; i < componentCount(*parseType(type)) && value.is_array(); ++i) value.push_back(0.5);
        nlohmann::json inputs{{port.name, "$x"}};
        for (const PortSpec& other : spec->inputs) {  // the other required inputs: literals that fit
          if (!other.required() || other.name == port.name) continue;
          Type t = other.kind == PortKind::Fixed ? other.type : Type::Float;
          nlohmann::json literal = t == Type::Float ? nlohmann::json(0.5) : nlohmann::json::array();
          for (int i = 0; i < componentCount(t) && literal.is_array(); ++i) literal.push_back(0.5);
          inputs[other.name] = literal;
        }
        nlohmann::json g{{"version", 1},
                         {"name", "t"},
                         {"parameters", {{"x", {{"type", type}, {"default", value}}}}},
                         {"nodes", {{{"id", "n"}, {"type", spec->type}, {"inputs", inputs}}}}};
        // Show the node's first output as the colour, through a swizzle to vec3.
        g["nodes"].push_back({{"id", "show"}, {"type", "swizzle"}, {"options", {{"mask", "xxx"}}},
                              {"inputs", {{"x", "n." + spec->outputs.front().name}}}});
        g["outputs"] = {{"fragment", {{"color", "show.out"}}}};
        Diagnostics diags;
        auto graph = parseGraph(g.dump(), "t.json", diags);
        ASSERT_TRUE(graph) << allText(diags);
        CompileOptions options;
        options.targets = {Target::Glsl330};
        options.validate = false;
        std::optional<CompileResult> r;
        EXPECT_NO_THROW(r = compileGraph(*graph, defaultRegistry(), options, diags));
        if (r) continue;
        ++refused;
        ASSERT_FALSE(diags.all().empty());
        for (const auto& d : diags.all())
          EXPECT_TRUE(d.code == DiagCode::TypeMismatch || d.code == DiagCode::UnknownOutputPort) << formatText(d);
      }
    }
  }
  EXPECT_GE(deriving, 7);
  EXPECT_GE(refused, 1) << "no wiring was refused: the case of the fuzzer's input is not reached";
}

TEST(PerDrawSplit, DudvScrollIsAPerDrawFract) {
  expectDerivedPerDraw(graphJson(R"({"id": "d", "type": "dudv_distortion"},
                                    {"id": "l", "type": "length", "inputs": {"x": "d.offset"}})",
                                 R"("fragment": {"alpha": "l.out", "color": [1, 0, 0]})"),
                       "d", "dudv_distortion", {{"scroll", "fract"}});
}

TEST(PerDrawSplit, DudvMoveIsTheFractOfTimeTimesSpeed) {
  for (double t : {0.0, 1.5, 13107.0, 524288.0, 1e6})
    for (double speed : {0.03, -0.2}) {
      std::vector<Value> out = evaluate("dudv_distortion", {{"time", Value::scalar(t)}, {"wave_speed", Value::scalar(speed)}});
      EXPECT_EQ(out[2][0], glsl::fract(t * speed)) << "t " << t << " speed " << speed;
    }
}

TEST(PerDrawSplit, NormalMapScrollsArePerDrawFracts) {
  expectDerivedPerDraw(graphJson(R"({"id": "n", "type": "normal_map_scroll"})",
                                 R"("fragment": {"color": "n.normal"})"),
                       "n", "normal_map_scroll", {{"scroll_a", "fract"}, {"scroll_b", "fract"}});
}

TEST(PerDrawSplit, NormalMapScrollShiftsTheLookupByTheFractOfSpeedTimesTime) {
  // Both layers unscaled and scrolling alike: at time t the node reads at uv + fract(speed t)
  // what it reads at time 0 there.
  const Value speed = Value::vector({0.05, -0.03});
  for (double t : {0.7, 1234.5, 524288.0}) {
    Value uv = Value::vector({0.3, 0.6});
    Value shifted = Value::vector({uv[0] + glsl::fract(speed[0] * t), uv[1] + glsl::fract(speed[1] * t)});
    auto at = [&](const Value& where, double time) {
      return evaluate("normal_map_scroll", {{"uv", where}, {"time", Value::scalar(time)}, {"scale_a", Value::scalar(1)},
                                            {"scale_b", Value::scalar(1)}, {"speed_a", speed}, {"speed_b", speed}})[0];
    };
    Value moving = at(uv, t), still = at(shifted, 0.0);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(moving[k], still[k], 1e-12) << "t " << t << " component " << k;
  }
}

TEST(PerDrawSplit, FlowMapPhasesAndWeightsArePerDrawOps) {
  expectDerivedPerDraw(graphJson(R"({"id": "f", "type": "flow_map"},
                                    {"id": "c", "type": "swizzle", "inputs": {"x": "f.sample"}, "options": {"mask": "xyz"}})",
                                 R"("fragment": {"color": "c.out"})"),
                       "f", "flow_map",
                       {{"progress_a", "fract"}, {"progress_b", "fract"}, {"fade_a", "one_minus"}, {"fade_b", "one_minus"}});
}

TEST(PerDrawSplit, FlowMapWeightsAreTheTriangleWavesOfTheFractOfTimeTimesSpeed) {
  for (double t : {0.0, 0.3, 13107.0, 524288.0})
    for (double speed : {1.0, 0.15}) {
      std::vector<Value> out = evaluate("flow_map", {{"time", Value::scalar(t)}, {"speed", Value::scalar(speed)}});
      double pa = glsl::fract(t * speed), pb = glsl::fract(t * speed + 0.5);
      EXPECT_EQ(out[1][0], 1.0 - std::abs(1.0 - 2.0 * pa)) << "t " << t << " speed " << speed;
      EXPECT_EQ(out[2][0], 1.0 - std::abs(1.0 - 2.0 * pb)) << "t " << t << " speed " << speed;
    }
}

TEST(PerDrawSplit, SceneDepthRatioIsAPerDrawOp) {
  expectDerivedPerDraw(graphJson(R"({"id": "s", "type": "scene_depth"})",
                                 R"("fragment": {"alpha": "s.linear", "color": [1, 0, 0]})"),
                       "s", "scene_depth", {{"near", "near_far_ratio"}, {"ratio", "near_far_ratio"}});
}

TEST(PerDrawSplit, LinearizeDepthRatioIsAPerDrawOp) {
  expectDerivedPerDraw(graphJson(R"({"id": "u", "type": "uv"}, {"id": "l", "type": "length", "inputs": {"x": "u.out"}},
                                    {"id": "z", "type": "linearize_depth", "inputs": {"depth": "l.out"}})",
                                 R"("fragment": {"alpha": "z.linear", "color": [1, 0, 0]})"),
                       "z", "linearize_depth", {{"near", "near_far_ratio"}, {"ratio", "near_far_ratio"}});
}

TEST(PerDrawSplit, LinearizeDepthIsTheReferenceOfNearAndFar) {
  const double inf = std::numeric_limits<double>::infinity();
  for (double d : {-0.5, 0.0, 0.3, 0.999, 1.0, 1.5})
    for (auto [n, f] : std::vector<std::pair<double, double>>{{0.1, 100}, {0.1, 1e38}, {0.1, inf}, {0, 100}, {1, 0.5}, {0.5, 0}}) {
      double got = evaluate("linearize_depth", {{"depth", Value::scalar(d)}, {"near_far", Value::vector({n, f})}})[0][0];
      EXPECT_EQ(got, nodes::linearizeDepthReference(d, n, f)) << "d " << d << " near " << n << " far " << f;
    }
}

TEST(PerDrawSplit, WaterDepthAxisAndRatioArePerDrawOps) {
  expectDerivedPerDraw(graphJson(R"({"id": "w", "type": "water_depth"})",
                                 R"("fragment": {"alpha": "w.thickness", "color": [1, 0, 0]})"),
                       "w", "water_depth",
                       {{"camera_axis", "camera_forward"}, {"near", "near_far_ratio"}, {"ratio", "near_far_ratio"}});
}

TEST(PerDrawSplit, WaterDepthIsTheFormulaOfTheViewMatrix) {
  // What water_depth computed from u_view and u_camera_near_far before the split.
  auto before = [](const EvalEnvironment& env, const Value& v, bool vertical) {
    double n = env.cameraNearFar[0], f = env.cameraNearFar[1];
    double scene = nodes::linearizeDepthReference(env.sceneDepth[0], n, f);
    double surface = nodes::linearizeDepthReference(env.fragDepth[0], n, f);
    double factor = nodes::waterDepthRayFactorReference(env.view, v);
    return nodes::waterDepthThicknessReference(scene, surface, factor, vertical ? std::abs(glsl::safeNormalize(v)[1]) : 1.0);
  };
  Value rigid = Value::ofType(Type::Mat4), scaled = Value::ofType(Type::Mat4), zero = Value::ofType(Type::Mat4);
  // Looking along (0.6, -0.8, 0): row 2 of the view matrix is -forward.
  rigid[2] = -0.6, rigid[6] = 0.8, rigid[10] = 0, rigid[15] = 1;
  scaled[2] = -1.2, scaled[6] = 1.6, scaled[10] = 0, scaled[15] = 1;  // a non-rigid matrix: the axis is normalised
  for (const Value& view : {rigid, scaled, zero})
    for (const Value& v : {Value::vector({-0.6, 0.8, 0}), Value::vector({0, 3, 0}), Value::vector({1, 0, 0}), Value::vector({0, 0, 0})})
      for (auto [nearFar, depths] : std::vector<std::pair<Value, Value>>{{Value::vector({0.1, 50}), Value::vector({0.9, 0.5})},
                                                                         {Value::vector({0.1, 1e38}), Value::vector({1.0, 0.99})},
                                                                         {Value::vector({0, 100}), Value::vector({0.7, 0.2})}}) {
        EvalEnvironment env;
        env.view = view;
        env.cameraNearFar = nearFar;
        env.sceneDepth = Value::scalar(depths[0]);
        env.fragDepth = Value::scalar(depths[1]);
        for (bool vertical : {false, true}) {
          auto& spec = *defaultRegistry().find("water_depth");
          static TextureCache textures;
          double got = evaluateNode(spec, {{"measure", vertical ? "vertical" : "view_ray"}}, {{"view", v}}, env, &textures,
                                    test::sourceDir())[0][0];
          double want = before(env, v, vertical);
          EXPECT_NEAR(got, want, 1e-12 * std::max(1.0, std::abs(want)))
              << "view " << view.toString() << " v " << v.toString() << " near/far " << nearFar.toString();
        }
      }
}

TEST(PerDrawSplit, CameraForwardIsTheUnitAxisOrZero) {
  EvalEnvironment env;
  env.view = Value::ofType(Type::Mat4);
  env.view[2] = -1.2, env.view[6] = 1.6, env.view[10] = 0;
  Value axis = evaluate("camera_forward", {}, env)[0];
  EXPECT_NEAR(axis[0], 0.6, 1e-15);
  EXPECT_NEAR(axis[1], -0.8, 1e-15);
  EXPECT_EQ(axis[2], 0.0);
  env.view = Value::ofType(Type::Mat4);  // degenerate: no axis
  EXPECT_EQ(evaluate("camera_forward", {}, env)[0], Value::vector({0, 0, 0}));
}

TEST(PerDrawSplit, NearFarRatioFloorsNearAndRaisesFar) {
  auto at = [](double n, double f) { return evaluate("near_far_ratio", {{"near_far", Value::vector({n, f})}}); };
  EXPECT_EQ(at(0.1, 50)[1][0], 0.1 / 50);
  EXPECT_EQ(at(0, 100)[0][0], 1e-6);
  EXPECT_EQ(at(1, 0.5)[1][0], 1.0);
  EXPECT_EQ(at(0.1, std::numeric_limits<double>::infinity())[1][0], 0.0);
}

TEST(PerDrawSplit, FactsStillChooseTheUnguardedLinearisation) {
  // Scene depth from a depth texture, the surface's from gl_FragCoord.z, near/far from the
  // runtime's clamped uniform: every guard of the linearisation is dead, as before.
  Diagnostics diags;
  auto graph = parseGraph(graphJson(R"({"id": "w", "type": "water_depth"})",
                                    R"("fragment": {"alpha": "w.thickness", "color": [1, 0, 0]})"),
                          "test.json", diags);
  ASSERT_TRUE(graph) << allText(diags);
  CompileOptions options;
  options.targets = {Target::Glsl330};
  auto result = compileGraph(*graph, defaultRegistry(), options, diags);
  ASSERT_TRUE(result && !diags.hasErrors()) << allText(diags);
  std::string frag;
  for (const auto& file : result->files)
    if (file.name.ends_with(".frag")) frag = file.contents;
  ASSERT_FALSE(frag.empty());
  EXPECT_NE(frag.find("wg_linearize_depth_ratio_known("), std::string::npos) << frag;
  EXPECT_EQ(frag.find("wg_linearize_depth_ratio("), std::string::npos) << frag;
  EXPECT_EQ(frag.find("wg_near_far_floor("), std::string::npos) << frag;
}

TEST(PerDrawSplit, ADerivedInputCannotBeConnected) {
  Diagnostics diags;
  auto graph = parseGraph(graphJson(R"({"id": "d", "type": "dudv_distortion", "inputs": {"scroll": 0.5}},
                                       {"id": "l", "type": "length", "inputs": {"x": "d.offset"}})",
                                    R"("fragment": {"alpha": "l.out", "color": [1, 0, 0]})"),
                          "test.json", diags);
  ASSERT_TRUE(graph) << allText(diags);
  auto program = resolveGraph(*graph, defaultRegistry(), diags);
  EXPECT_FALSE(program && !diags.hasErrors());
  EXPECT_NE(allText(diags).find("computed by the node itself"), std::string::npos) << allText(diags);
}

}  // namespace
}  // namespace wg
