#include "codegen/emit_glsl.h"

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>

#include <filesystem>

#include "codegen/shader_interface.h"
#include "core/texture_check.h"
#include "core/number_format.h"
#include "nodes/glsl_library.h"

namespace wg {
namespace {

// Per-target differences, as data.
struct TargetStyle {
  std::string_view version;
  bool precision;         // ES: default precision statements
  bool uniformBlock;      // Vulkan: non-opaque uniforms in one std140 block
  bool varyingLocations;  // Vulkan: explicit locations on every in/out
};

TargetStyle styleOf(Target t) {
  switch (t) {
    case Target::Glsl330: return {"#version 330 core", false, false, false};
    case Target::Es300: return {"#version 300 es", true, false, false};
    case Target::Vk450: return {"#version 450", false, true, true};
  }
  return {"#version 330 core", false, false, false};
}

std::string literalOf(const Value& v) {
  if (v.size() == 1) return formatGlslFloat(v[0]);
  std::string s(typeName(v.type));
  s += '(';
  bool same = true;
  for (int i = 1; i < v.size(); ++i) same &= v[i] == v[0];
  if (same) return s + formatGlslFloat(v[0]) + ')';
  for (int i = 0; i < v.size(); ++i) s += (i ? ", " : "") + formatGlslFloat(v[i]);
  return s + ')';
}

int resourceRank(const std::string& resource) {
  const char* order[] = {"scene_depth", "scene_color", "planar_reflection", "refraction", "environment"};
  for (int i = 0; i < 5; ++i)
    if (resource == order[i]) return i;
  return 5;
}

bool isPlainName(const std::string& e) {
  if (e.empty() || (e[0] >= '0' && e[0] <= '9')) return false;
  for (char c : e)
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_')) return false;
  return true;
}

// The builtin uniforms, in declaration order.
struct BuiltinUniform {
  const char* name;
  Type type;
  const char* meaning;
};
const BuiltinUniform kModel{iface::kModel, Type::Mat4, "model"};
const BuiltinUniform kViewProjection{iface::kViewProjection, Type::Mat4, "view_projection"};
const BuiltinUniform kCamera{iface::kCameraPosition, Type::Vec3, "camera_position"};
const BuiltinUniform kTime{iface::kTime, Type::Float, "time"};
const BuiltinUniform kViewport{iface::kViewportSize, Type::Vec2, "viewport_size"};
const BuiltinUniform kNearFar{iface::kCameraNearFar, Type::Vec2, "camera_near_far"};
const BuiltinUniform kView{iface::kView, Type::Mat4, "view"};
const BuiltinUniform kProjection{iface::kProjection, Type::Mat4, "projection"};

// One stage's body being written: lines with the op that wrote each, and what it used.
struct StageWriter {
  unsigned stage = 0;
  std::vector<std::string> lines;
  std::vector<int> lineOp;
  std::set<Builtin> builtins;
  std::set<int> parameters;
  std::set<std::string> builtinUniforms;
  // Op outputs whose expression is already a name (a builtin, another temporary): used
  // directly instead of copying into a new local.
  std::map<std::pair<int, int>, std::string> aliases;

  void line(std::string text, int op) {
    lines.push_back("  " + std::move(text));
    lineOp.push_back(op);
  }
};

class Emitter;

class OpEmitContext final : public EmitContext {
 public:
  OpEmitContext(Emitter& e, StageWriter& w, int opIndex) : e_(e), w_(w), opIndex_(opIndex) {}
  std::string input(int port) override;
  Type inputType(int port) const override;
  Type outputType(int port) const override;
  const nlohmann::json& option(std::string_view name) const override;
  void output(int port, std::string expression) override;
  std::string builtin(Builtin b) override;
  std::string temporary(Type type, std::string expression) override;
  unsigned stage() const override { return w_.stage; }
  std::string timePhase(double omega) override;
  std::string texture(std::string_view option) override;
  std::string sceneTexture(std::string_view resource) override;
  const NodeSpec& spec() const override;

  std::vector<std::string> outputs;

 private:
  Emitter& e_;
  StageWriter& w_;
  int opIndex_;
  int temps_ = 0;
};

class Emitter {
 public:
  Emitter(const Program& p, Target t, std::string sourceName)
      : program_(p), target_(t), style_(styleOf(t)), sourceName_(std::move(sourceName)) {
    for (size_t i = 0; i < p.ops.size(); ++i) opNames_.push_back("n" + std::to_string(i) + "_" + sanitiseIdentifier(p.ops[i].nodeId));
    std::set<std::string> taken;
    for (const auto& param : p.parameters) {
      std::string name = "p_" + sanitiseIdentifier(param.name);
      if (!taken.insert(name).second) name = "p" + std::to_string(paramNames_.size()) + "_" + sanitiseIdentifier(param.name);
      taken.insert(name);
      paramNames_.push_back(name);
    }
    for (size_t k = 0; k < p.varyings.size(); ++k) {
      const ValueRef& v = p.varyings[k];
      const Op& op = p.ops[static_cast<size_t>(v.index)];
      varyingNames_[{v.index, v.port}] = "v" + std::to_string(k) + "_" + sanitiseIdentifier(op.nodeId) +
                                          (op.outputTypes.size() > 1 ? "_" + op.spec->outputs[static_cast<size_t>(v.port)].name : "");
    }
  }

  EmitResult run() {
    StageWriter frag;
    frag.stage = kFragmentStage;
    emitOps(frag);
    std::string color = outputExpr(frag, OutputSlot::FragmentColor, "vec3(0.5)");
    std::string alpha = outputExpr(frag, OutputSlot::FragmentAlpha, "1.0");
    frag.line(std::string(iface::kColorOutput) + " = vec4(" + color + ", " + alpha + ");", -1);

    StageWriter vert;
    vert.stage = kVertexStage;
    emitOps(vert);
    // What the fragment stage reads from the vertex stage.
    bool fragNeedsPosition = frag.builtins.count(Builtin::WorldPosition) || frag.builtins.count(Builtin::ViewDirection);
    bool fragNeedsNormal = frag.builtins.count(Builtin::Normal) > 0;
    bool fragNeedsUv = frag.builtins.count(Builtin::Uv) > 0;
    std::string position = outputExpr(vert, OutputSlot::VertexPosition, builtinExpr(vert, Builtin::WorldPosition));
    vert.line("gl_Position = " + std::string(iface::kViewProjection) + " * vec4(" + position + ", 1.0);", -1);
    vert.builtinUniforms.insert(iface::kViewProjection);
    if (fragNeedsPosition) vert.line("v_world_position = " + position + ";", -1);
    if (fragNeedsNormal) {
      std::string normal = program_.output(OutputSlot::VertexNormal) ? outputExpr(vert, OutputSlot::VertexNormal, "")
                                                                       : builtinExpr(vert, Builtin::Normal);
      vert.line("v_normal = " + normal + ";", -1);
    }
    if (fragNeedsUv) {
      vert.builtins.insert(Builtin::Uv);
      vert.line("v_uv = " + std::string(iface::kUvAttribute) + ";", -1);
    }
    for (const auto& v : program_.varyings)
      vert.line(varyingNames_.at({v.index, v.port}) + " = " + opOutput(vert, v.index, v.port) + ";", -1);

    // Interface.
    EmitResult result;
    result.attributes.push_back({iface::kPositionAttribute, Type::Vec3, iface::kPositionLocation});
    if (vert.builtins.count(Builtin::Normal))
      result.attributes.push_back({iface::kNormalAttribute, Type::Vec3, iface::kNormalLocation});
    if (vert.builtins.count(Builtin::Uv)) result.attributes.push_back({iface::kUvAttribute, Type::Vec2, iface::kUvLocation});
    if (fragNeedsPosition) result.varyings.push_back({"v_world_position", Type::Vec3, "world_position"});
    if (fragNeedsNormal) result.varyings.push_back({"v_normal", Type::Vec3, "normal"});
    if (fragNeedsUv) result.varyings.push_back({"v_uv", Type::Vec2, "uv"});
    for (const auto& v : program_.varyings) {
      const Op& op = program_.ops[static_cast<size_t>(v.index)];
      result.varyings.push_back({varyingNames_.at({v.index, v.port}), op.outputTypes[static_cast<size_t>(v.port)],
                                 "node '" + op.nodeId + "' output '" + op.spec->outputs[static_cast<size_t>(v.port)].name + "'"});
    }
    for (const BuiltinUniform* u : {&kModel, &kViewProjection, &kView, &kProjection, &kCamera, &kNearFar, &kTime, &kViewport}) {
      unsigned stages = (vert.builtinUniforms.count(u->name) ? kVertexStage : 0u) |
                        (frag.builtinUniforms.count(u->name) ? kFragmentStage : 0u);
      if (stages) result.uniforms.push_back({u->name, u->type, -1, u->meaning, stages});
    }
    result.uniforms.insert(result.uniforms.end(), phases_.begin(), phases_.end());
    for (size_t i = 0; i < program_.parameters.size(); ++i) {
      unsigned stages = (vert.parameters.count(static_cast<int>(i)) ? kVertexStage : 0u) |
                        (frag.parameters.count(static_cast<int>(i)) ? kFragmentStage : 0u);
      if (stages) result.uniforms.push_back({paramNames_[i], program_.parameters[i].type, static_cast<int>(i), "", stages});
    }

    // Samplers: node textures by first use, then scene textures in the manifest's
    // resource order; vk450 bindings follow the uniform block's.
    std::stable_sort(sceneTextures_.begin(), sceneTextures_.end(), [](const TextureInfo& a, const TextureInfo& b) {
      return resourceRank(a.resource) < resourceRank(b.resource);
    });
    result.textures = textures_;
    result.textures.insert(result.textures.end(), sceneTextures_.begin(), sceneTextures_.end());
    for (size_t i = 0; i < result.textures.size(); ++i)
      result.textures[i].binding = iface::kUniformBlockBinding + 1 + static_cast<int>(i);

    std::set<std::string> functions;
    result.shaders.push_back(assemble(ShaderStage::Vertex, vert, result, functions));
    result.shaders.push_back(assemble(ShaderStage::Fragment, frag, result, functions));
    for (const auto& item : GlslLibrary::builtin().items())
      if (functions.count(item.name) &&
          std::find(result.functions.begin(), result.functions.end(), item.name) == result.functions.end())
        result.functions.push_back(item.name);
    return result;
  }

  // --- used by OpEmitContext ---
  std::string valueExpr(StageWriter& w, const ValueRef& r, Type want) {
    std::string e;
    Type have = program_.typeOf(r);
    switch (r.kind) {
      case ValueRef::Kind::Const: return literalOf(r.constant.convertedTo(want));
      case ValueRef::Kind::Param:
        w.parameters.insert(r.index);
        e = paramNames_[static_cast<size_t>(r.index)];
        break;
      case ValueRef::Kind::Builtin: e = builtinExpr(w, static_cast<Builtin>(r.index)); break;
      case ValueRef::Kind::Op: {
        const Op& op = program_.ops[static_cast<size_t>(r.index)];
        if (w.stage == kFragmentStage && !(op.stage & kFragmentStage))
          e = varyingNames_.at({r.index, r.port});
        else
          e = opOutput(w, r.index, r.port);
        break;
      }
      case ValueRef::Kind::None: throw std::logic_error("emit: unset value");
    }
    if (have != want && have == Type::Float) return std::string(typeName(want)) + "(" + e + ")";
    return e;
  }

  std::string builtinExpr(StageWriter& w, Builtin b) {
    w.builtins.insert(b);
    bool vertex = w.stage == kVertexStage;
    switch (b) {
      case Builtin::Uv: return vertex ? iface::kUvAttribute : "v_uv";
      case Builtin::WorldPosition:
        if (vertex) w.builtinUniforms.insert(iface::kModel);
        return vertex ? "b_world_position" : "v_world_position";
      case Builtin::Normal:
        if (vertex) w.builtinUniforms.insert(iface::kModel);
        return "b_normal";
      case Builtin::ViewDirection:
        w.builtinUniforms.insert(iface::kCameraPosition);
        if (vertex) w.builtinUniforms.insert(iface::kModel);
        return "b_view_direction";
      case Builtin::CameraPosition: w.builtinUniforms.insert(iface::kCameraPosition); return iface::kCameraPosition;
      case Builtin::Time: w.builtinUniforms.insert(iface::kTime); return iface::kTime;
      case Builtin::ScreenUv: w.builtinUniforms.insert(iface::kViewportSize); return "b_screen_uv";
      case Builtin::FragDepth: return "gl_FragCoord.z";
      case Builtin::CameraNearFar: w.builtinUniforms.insert(iface::kCameraNearFar); return iface::kCameraNearFar;
      case Builtin::View: w.builtinUniforms.insert(iface::kView); return iface::kView;
      case Builtin::Projection: w.builtinUniforms.insert(iface::kProjection); return iface::kProjection;
    }
    return "";
  }

  std::string opOutput(const StageWriter& w, int op, int port) const {
    auto alias = w.aliases.find({op, port});
    if (alias != w.aliases.end()) return alias->second;
    return tempName(op, port);
  }
  std::string tempName(int op, int port) const {
    const Op& o = program_.ops[static_cast<size_t>(op)];
    return o.outputTypes.size() > 1 ? opNames_[static_cast<size_t>(op)] + "_" + o.spec->outputs[static_cast<size_t>(port)].name
                                     : opNames_[static_cast<size_t>(op)];
  }
  const std::string& opName(int op) const { return opNames_[static_cast<size_t>(op)]; }

  std::string phaseUniform(StageWriter& w, double omega) {
    for (auto& p : phases_)
      if (p.omega == omega) {
        p.stages |= w.stage;
        return p.name;
      }
    UniformInfo u{"u_phase" + std::to_string(phases_.size()), Type::Float, -1, "time_phase", w.stage, omega};
    phases_.push_back(u);
    return u.name;
  }

  std::string nodeTexture(StageWriter& w, const std::string& source) {
    for (auto& t : textures_)
      if (t.resource.empty() && t.source == source) {
        t.stages |= w.stage;
        return t.name;
      }
    std::string stem = source.rfind(kBuiltinTexturePrefix, 0) == 0 ? source.substr(kBuiltinTexturePrefix.size())
                                                                     : std::filesystem::path(source).stem().string();
    TextureInfo t;
    t.name = "t" + std::to_string(textures_.size()) + "_" + sanitiseIdentifier(stem);
    t.source = source;
    t.stages = w.stage;
    textures_.push_back(t);
    return t.name;
  }

  std::string sceneSampler(StageWriter& w, std::string_view resource) {
    struct Scene {
      const char* resource;
      const char* name;
      Type type;
    };
    static const Scene kScene[] = {{"scene_depth", iface::kSceneDepthTexture, Type::Sampler2D},
                                   {"scene_color", iface::kSceneColorTexture, Type::Sampler2D},
                                   {"planar_reflection", iface::kReflectionTexture, Type::Sampler2D},
                                   {"refraction", iface::kRefractionTexture, Type::Sampler2D},
                                   {"environment", iface::kEnvironmentTexture, Type::SamplerCube}};
    for (const auto& sc : kScene) {
      if (resource != sc.resource) continue;
      for (auto& t : sceneTextures_)
        if (t.resource == resource) {
          t.stages |= w.stage;
          return t.name;
        }
      TextureInfo t;
      t.name = sc.name;
      t.type = sc.type;
      t.resource = sc.resource;
      t.stages = w.stage;
      sceneTextures_.push_back(t);
      return t.name;
    }
    throw std::logic_error("sceneTexture: no scene texture for resource '" + std::string(resource) + "'");
  }
  const Program& program() const { return program_; }

 private:
  void emitOps(StageWriter& w) {
    // Which outputs of which ops this stage reads.
    std::vector<std::vector<bool>> used(program_.ops.size());
    auto use = [&](const ValueRef& r) {
      if (r.kind != ValueRef::Kind::Op) return;
      auto& u = used[static_cast<size_t>(r.index)];
      if (u.empty()) u.assign(program_.ops[static_cast<size_t>(r.index)].outputTypes.size(), false);
      u[static_cast<size_t>(r.port)] = true;
    };
    for (size_t i = 0; i < program_.ops.size(); ++i)
      if (program_.ops[i].stage & w.stage)
        for (const auto& in : program_.ops[i].inputs) use(in);
    for (const auto& out : program_.outputs) {
      bool vertexSlot = out.slot == OutputSlot::VertexPosition || out.slot == OutputSlot::VertexNormal;
      if (vertexSlot == (w.stage == kVertexStage)) use(out.value);
    }
    if (w.stage == kVertexStage)
      for (const auto& v : program_.varyings) use(v);

    for (size_t i = 0; i < program_.ops.size(); ++i) {
      const Op& op = program_.ops[i];
      if (!(op.stage & w.stage)) continue;
      OpEmitContext ctx(*this, w, static_cast<int>(i));
      ctx.outputs.assign(op.outputTypes.size(), "");
      op.spec->emit(ctx);
      for (size_t p = 0; p < op.outputTypes.size(); ++p) {
        if (used[i].empty() || !used[i][p]) continue;
        if (ctx.outputs[p].empty())
          throw std::logic_error("node '" + op.spec->type + "' emitted no expression for output '" +
                                 op.spec->outputs[p].name + "'");
        if (isPlainName(ctx.outputs[p])) {
          w.aliases[{static_cast<int>(i), static_cast<int>(p)}] = ctx.outputs[p];
          continue;
        }
        w.line(std::string(typeName(op.outputTypes[p])) + " " + tempName(static_cast<int>(i), static_cast<int>(p)) +
                   " = " + ctx.outputs[p] + ";",
               static_cast<int>(i));
      }
    }
  }

  std::string outputExpr(StageWriter& w, OutputSlot slot, std::string fallback) {
    const ProgramOutput* out = program_.output(slot);
    if (!out) return fallback;
    return valueExpr(w, out->value, out->type);
  }

  // Builtin locals at the top of main, in a fixed order, for what the body used.
  std::vector<std::string> builtinLocals(StageWriter& w) {
    std::vector<std::string> lines;
    bool vertex = w.stage == kVertexStage;
    if (vertex) {
      lines.push_back("vec3 b_world_position = (" + std::string(iface::kModel) + " * vec4(" + iface::kPositionAttribute + ", 1.0)).xyz;");
      w.builtinUniforms.insert(iface::kModel);
      if (w.builtins.count(Builtin::Normal))
        lines.push_back("vec3 b_normal = wg_safe_normalize_vec3(mat3(" + std::string(iface::kModel) + ") * " + iface::kNormalAttribute + ");");
      if (w.builtins.count(Builtin::ViewDirection))
        lines.push_back("vec3 b_view_direction = wg_safe_normalize_vec3(" + std::string(iface::kCameraPosition) + " - b_world_position);");
    } else {
      if (w.builtins.count(Builtin::Normal)) lines.push_back("vec3 b_normal = wg_safe_normalize_vec3(v_normal);");
      if (w.builtins.count(Builtin::ViewDirection))
        lines.push_back("vec3 b_view_direction = wg_safe_normalize_vec3(" + std::string(iface::kCameraPosition) + " - v_world_position);");
      if (w.builtins.count(Builtin::ScreenUv))
        lines.push_back("vec2 b_screen_uv = gl_FragCoord.xy / " + std::string(iface::kViewportSize) + ";");
    }
    return lines;
  }

  EmittedShader assemble(ShaderStage stage, StageWriter& w, const EmitResult& io, std::set<std::string>& functions) {
    std::vector<std::string> locals = builtinLocals(w);
    bool vertex = stage == ShaderStage::Vertex;
    unsigned bit = vertex ? kVertexStage : kFragmentStage;
    std::vector<std::pair<std::string, int>> out;  // line, op
    auto add = [&](std::string s, int op = -1) { out.emplace_back(std::move(s), op); };
    add(std::string(style_.version));
    add("// Generated by watergraph from " + sourceName_ + " (graph '" + program_.graphName + "'); do not edit.");
    if (style_.precision) {
      add("precision highp float;");
      add("precision highp int;");
    }
    add("");
    // Inputs.
    if (vertex) {
      for (const auto& a : io.attributes) {
        bool usedHere = a.name == std::string(iface::kPositionAttribute) ||
                        (a.name == std::string(iface::kNormalAttribute) && w.builtins.count(Builtin::Normal)) ||
                        (a.name == std::string(iface::kUvAttribute) && w.builtins.count(Builtin::Uv));
        if (usedHere)
          add("layout(location = " + std::to_string(a.location) + ") in " + std::string(typeName(a.type)) + " " + a.name + ";");
      }
    }
    int location = 0;
    for (const auto& v : io.varyings) {
      std::string qual = style_.varyingLocations ? "layout(location = " + std::to_string(location) + ") " : "";
      add(qual + (vertex ? "out " : "in ") + std::string(typeName(v.type)) + " " + v.name + ";");
      ++location;
    }
    if (!vertex) add("layout(location = " + std::to_string(iface::kColorLocation) + ") out vec4 " + iface::kColorOutput + ";");
    // Uniforms: Vulkan wants one block with the same members in every stage.
    if (style_.uniformBlock) {
      bool any = false;
      for (const auto& u : io.uniforms) any |= !isSampler(u.type);
      if (any) {
        add("layout(std140, set = 0, binding = " + std::to_string(iface::kUniformBlockBinding) + ") uniform " + iface::kUniformBlock + " {");
        for (const auto& u : io.uniforms) add("  " + std::string(typeName(u.type)) + " " + u.name + ";");
        add("};");
      }
    } else {
      for (const auto& u : io.uniforms)
        if (u.stages & bit) add("uniform " + std::string(typeName(u.type)) + " " + u.name + ";");
    }
    for (const auto& t : io.textures) {
      if (!(t.stages & bit)) continue;
      std::string qual = style_.uniformBlock ? "layout(set = 0, binding = " + std::to_string(t.binding) + ") " : "";
      add(qual + "uniform " + std::string(typeName(t.type)) + " " + t.name + ";");
    }
    // Library functions this stage calls, dependencies first.
    std::string code;
    for (const auto& l : locals) code += l + "\n";
    for (const auto& l : w.lines) code += l + "\n";
    auto items = GlslLibrary::builtin().itemsFor(code);
    for (const GlslItem* item : items) {
      add("");
      functions.insert(item->name);
      size_t start = 0;
      while (start <= item->text.size()) {
        size_t eol = item->text.find('\n', start);
        if (eol == std::string::npos) eol = item->text.size();
        add(item->text.substr(start, eol - start));
        start = eol + 1;
      }
    }
    add("");
    add("void main() {");
    for (const auto& l : locals) add("  " + l);
    for (size_t i = 0; i < w.lines.size(); ++i) add(w.lines[i], w.lineOp[i]);
    add("}");

    EmittedShader shader;
    shader.stage = stage;
    for (auto& [text, op] : out) {
      shader.text += text;
      shader.text += '\n';
      shader.lineOp.push_back(op);
    }
    return shader;
  }

  const Program& program_;
  Target target_;
  TargetStyle style_;
  std::string sourceName_;
  std::vector<std::string> opNames_;
  std::vector<std::string> paramNames_;
  std::map<std::pair<int, int>, std::string> varyingNames_;
  std::vector<UniformInfo> phases_;         // time phases, by first use
  std::vector<TextureInfo> textures_;       // node textures, by first use
  std::vector<TextureInfo> sceneTextures_;  // scene resources, by first use (sorted later)
};

std::string OpEmitContext::input(int port) {
  const Op& op = e_.program().ops[static_cast<size_t>(opIndex_)];
  return e_.valueExpr(w_, op.inputs.at(static_cast<size_t>(port)), op.inputTypes.at(static_cast<size_t>(port)));
}
Type OpEmitContext::inputType(int port) const {
  return e_.program().ops[static_cast<size_t>(opIndex_)].inputTypes.at(static_cast<size_t>(port));
}
Type OpEmitContext::outputType(int port) const {
  return e_.program().ops[static_cast<size_t>(opIndex_)].outputTypes.at(static_cast<size_t>(port));
}
const nlohmann::json& OpEmitContext::option(std::string_view name) const {
  return e_.program().ops[static_cast<size_t>(opIndex_)].options.at(std::string(name));
}
void OpEmitContext::output(int port, std::string expression) { outputs.at(static_cast<size_t>(port)) = std::move(expression); }
std::string OpEmitContext::builtin(Builtin b) { return e_.builtinExpr(w_, b); }
std::string OpEmitContext::timePhase(double omega) { return e_.phaseUniform(w_, omega); }
std::string OpEmitContext::texture(std::string_view option) {
  const nlohmann::json& v = this->option(option);
  if (!v.is_string()) throw std::logic_error("texture(): option '" + std::string(option) + "' is not a texture");
  return e_.nodeTexture(w_, v.get<std::string>());
}
std::string OpEmitContext::sceneTexture(std::string_view resource) {
  const auto& resources = spec().resources;
  if (std::find(resources.begin(), resources.end(), resource) == resources.end())
    throw std::logic_error("node '" + spec().type + "' samples scene resource '" + std::string(resource) +
                           "' without listing it in its resources");
  return e_.sceneSampler(w_, resource);
}
std::string OpEmitContext::temporary(Type type, std::string expression) {
  std::string name = e_.opName(opIndex_) + "_t" + std::to_string(temps_++);
  w_.line(std::string(typeName(type)) + " " + name + " = " + expression + ";", opIndex_);
  return name;
}
const NodeSpec& OpEmitContext::spec() const { return *e_.program().ops[static_cast<size_t>(opIndex_)].spec; }

}  // namespace

std::string sanitiseIdentifier(std::string_view id) {
  std::string out;
  for (char c : id) {
    bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
    char ch = ok ? c : '_';
    if (ch == '_' && (out.empty() || out.back() == '_')) continue;
    out += ch;
    if (out.size() >= 24) break;
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out.empty() ? "x" : out;
}

EmitResult emitProgram(const Program& program, Target target, const std::string& sourceName) {
  return Emitter(program, target, sourceName).run();
}

}  // namespace wg
