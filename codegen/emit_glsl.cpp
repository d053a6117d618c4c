#include "codegen/emit_glsl.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>

#include <filesystem>

#include "codegen/shader_interface.h"
#include "codegen/value_facts.h"
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
  for (int i = 1; i < v.size(); ++i) same &= v[i] == v[0] && std::signbit(v[i]) == std::signbit(v[0]);  // -0.0 is not 0.0
  if (same) return s + formatGlslFloat(v[0]) + ')';
  for (int i = 0; i < v.size(); ++i) s += (i ? ", " : "") + formatGlslFloat(v[i]);
  return s + ')';
}

// Scene samplers are declared in the order of their resources' table rows.
int resourceRank(const TextureInfo& t) { return static_cast<int>(sceneSamplerRow(*t.scene).resource); }

std::string uniformName(BuiltinUniform u) { return std::string(builtinUniformRow(u).glslName); }
std::string samplerName(SceneSampler s) { return std::string(sceneSamplerRow(s).glslName); }

bool isPlainName(const std::string& e) {
  if (e.empty() || (e[0] >= '0' && e[0] <= '9')) return false;
  for (char c : e)
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_')) return false;
  return true;
}

// One shader's text being assembled: lines appended into one buffer, each with the op
// that wrote it (-1: none), so a glslang error maps back to its node.
struct ShaderText {
  EmittedShader shader;
  explicit ShaderText(ShaderStage stage) { shader.stage = stage; }
  void add(std::string_view line, int op = -1) {
    shader.text.append(line);
    shader.text += '\n';
    shader.lineOp.push_back(op);
  }
  // Whole lines, each ending in '\n' (a stage body with its ops, or lines from no op).
  void addLines(std::string_view lines, const std::vector<int>* ops = nullptr) {
    shader.text.append(lines);
    if (ops)
      shader.lineOp.insert(shader.lineOp.end(), ops->begin(), ops->end());
    else
      shader.lineOp.insert(shader.lineOp.end(), static_cast<size_t>(std::count(lines.begin(), lines.end(), '\n')), -1);
  }
};

// One stage's body being written into one buffer ("  " + line + '\n' each, no string per
// line), with the op that wrote each line, and what it used.
struct StageWriter {
  unsigned stage = 0;
  std::string body;
  std::vector<int> lineOp;
  std::set<Builtin> builtins;
  std::set<int> parameters;
  std::set<BuiltinUniform> builtinUniforms;
  // Op outputs whose expression is already a name (a builtin, another temporary): used
  // directly instead of copying into a new local. By the Emitter's port index ("" none; a
  // flat vector: a map keyed by (op, port) was a tree walk per input on large graphs).
  std::vector<std::string> aliases;

  // One line of the body, from its parts.
  template <class... Parts>
  void line(int op, const Parts&... parts) {
    body += "  ";
    (body.append(std::string_view(parts)), ...);
    body += '\n';
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
  const ParsedOptions& parsedOptions() const override;
  void output(int port, std::string expression) override;
  std::string builtin(Builtin b) override;
  std::string temporary(Type type, std::string expression) override;
  unsigned stage() const override { return w_.stage; }
  std::string timePhase(double omega) override;
  using EmitContext::texture;
  std::string texture(std::string_view option, const SamplerState& sampler) override;
  std::string sceneTexture(SceneResource resource) override;
  const NodeSpec& spec() const override;
  ValueFact inputFact(int port) const override;
  ValueFact knownBuiltin(Builtin b) const override;
  std::optional<Value> inputConstant(int port) const override;

  std::vector<std::string> outputs;

 private:
  Emitter& e_;
  StageWriter& w_;
  int opIndex_;
  int temps_ = 0;
};

class Emitter {
 public:
  Emitter(const Program& p, Target t, std::string sourceName, EmitMode mode, bool allowTessellation)
      : program_(p), target_(t), style_(styleOf(t)), sourceName_(std::move(sourceName)), probe_(mode == EmitMode::Probe) {
    // Probe shaders take builtins and parameters from arbitrary cases: no facts there.
    if (!probe_) facts_ = ValueFacts(p);
    opNames_.reserve(p.ops.size());
    portBase_.reserve(p.ops.size() + 1);
    portBase_.push_back(0);
    for (size_t i = 0; i < p.ops.size(); ++i) {
      opNames_.push_back("n" + std::to_string(i) + "_" + sanitiseIdentifier(p.ops[i].nodeId));
      portBase_.push_back(portBase_.back() + p.ops[i].outputTypes.size());
    }
    std::set<std::string> taken;
    for (const auto& param : p.parameters) {
      std::string name = "p_" + sanitiseIdentifier(param.name);
      if (!taken.insert(name).second) name = "p" + std::to_string(paramNames_.size()) + "_" + sanitiseIdentifier(param.name);
      taken.insert(name);
      paramNames_.push_back(name);
    }
    if (!probe_) tess_ = tessellationFor(p, t, allowTessellation);
    // Deferred water: an op reads the underwater resource, so the fragment shader runs as
    // a full-screen pass that takes the surface builtins from the water G-buffer.
    deferred_ = !probe_ && p.reads(SceneResource::Underwater);
    for (size_t k = 0; k < p.varyings.size(); ++k) {
      const ValueRef& v = p.varyings[k];
      const Op& op = p.ops[static_cast<size_t>(v.index)];
      varyingNames_[{v.index, v.port}] = "v" + std::to_string(k) + "_" + sanitiseIdentifier(op.nodeId) +
                                          (op.outputTypes.size() > 1 ? "_" + op.spec->outputs[static_cast<size_t>(v.port)].name : "");
    }
  }

  // Tessellation: asked for by a vertex-stage node; GLSL ES 3.00 has no such stages.
  static std::optional<TessellationSettings> tessellationFor(const Program& p, Target t, bool allowTessellation) {
    std::optional<TessellationSettings> tess;
    if (t != Target::Es300 && allowTessellation)
      for (const auto& op : p.ops)
        if ((op.stage & kVertexStage) && op.spec->tessellation && !tess) tess = op.spec->tessellation(*op.parsedOptions);
    return tess;
  }

  EmitResult run() {
    if (probe_) return runProbe();
    prepare();
    return assembleFor();
  }

  // Another target with the same tessellation: the stage bodies and the interface depend
  // on nothing else, so only the assembly (version, qualifiers, layouts) runs again.
  void retarget(Target t) {
    target_ = t;
    style_ = styleOf(t);
  }

  // The stage bodies and the interface (what no target's style changes).
  void prepare() {
    StageWriter& frag = frag_;
    StageWriter& vert = vert_;
    frag.stage = kFragmentStage;
    emitOps(frag);
    std::string color = outputExpr(frag, OutputSlot::FragmentColor, "vec3(0.5)");
    std::string alpha = outputExpr(frag, OutputSlot::FragmentAlpha, "1.0");
    frag.line(-1, iface::kColorOutput, " = vec4(", color, ", ", alpha, ");");
    if (deferred_) prepareDeferredFragment(frag);

    vert.stage = kVertexStage;
    emitOps(vert);
    // What the fragment stage reads from the vertex stage.
    bool fragNeedsPosition = frag.builtins.count(Builtin::WorldPosition) || frag.builtins.count(Builtin::ViewDirection);
    bool fragNeedsNormal = frag.builtins.count(Builtin::Normal) > 0;
    bool fragNeedsUv = frag.builtins.count(Builtin::Uv) > 0;
    // Deferred: the vertex shader feeds the runtime's G-buffer pass, which stores all three.
    if (deferred_) fragNeedsPosition = fragNeedsNormal = fragNeedsUv = true;
    std::string position = outputExpr(vert, OutputSlot::VertexPosition, builtinExpr(vert, Builtin::WorldPosition));
    vert.line(-1, "gl_Position = ", uniformName(BuiltinUniform::ViewProjection), " * vec4(", position, ", 1.0);");
    vert.builtinUniforms.insert(BuiltinUniform::ViewProjection);
    if (fragNeedsPosition) vert.line(-1, "v_world_position = ", position, ";");
    if (fragNeedsNormal) {
      std::string normal = program_.output(OutputSlot::VertexNormal) ? outputExpr(vert, OutputSlot::VertexNormal, "")
                                                                       : builtinExpr(vert, Builtin::Normal);
      vert.line(-1, "v_normal = ", normal, ";");
    }
    if (fragNeedsUv) {
      vert.builtins.insert(Builtin::Uv);
      vert.line(-1, "v_uv = ", tess_ ? "b_uv" : iface::kUvAttribute, ";");
    }
    for (const auto& v : program_.varyings)
      vert.line(-1, varyingNames_.at({v.index, v.port}), " = ", opOutput(vert, v.index, v.port), ";");

    if (tess_) {
      // The vertex shader places the mesh (model), the control stage measures distances.
      vert.builtinUniforms.insert(BuiltinUniform::Model);
      vert.builtinUniforms.insert(BuiltinUniform::CameraPosition);
    }

    // Interface.
    EmitResult& result = io_;
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
    declareBuiltinUniforms(result, &vert, frag);
    for (size_t i = 0; i < program_.parameters.size(); ++i) {
      unsigned stages = (vert.parameters.count(static_cast<int>(i)) ? kVertexStage : 0u) |
                        (frag.parameters.count(static_cast<int>(i)) ? kFragmentStage : 0u);
      if (stages) result.uniforms.push_back({paramNames_[i], program_.parameters[i].type, static_cast<int>(i), {}, stages});
    }

    assignSamplers(result);
  }

  // The shaders for the current target from what prepare() made.
  EmitResult assembleFor() {
    EmitResult result = io_;
    StageWriter& frag = frag_;
    StageWriter& vert = vert_;
    std::set<std::string> functions;
    if (tess_) {
      result.shaders.push_back(tessVertexShader(vert, result, functions));
      result.shaders.push_back(tessControlShader(vert, result, functions));
      result.shaders.push_back(assemble(ShaderStage::TessEvaluation, vert, result, functions));
      result.tessellation = tess_;
    } else {
      result.shaders.push_back(assemble(ShaderStage::Vertex, vert, result, functions));
    }
    result.shaders.push_back(assemble(ShaderStage::Fragment, frag, result, functions));
    for (const auto& item : GlslLibrary::builtin().items())
      if (functions.count(item.name) &&
          std::find(result.functions.begin(), result.functions.end(), item.name) == result.functions.end())
        result.functions.push_back(item.name);
    return result;
  }

  // Probe mode: one fragment shader, every op in it, the first output padded into o_color.
  EmitResult runProbe() {
    StageWriter frag;
    frag.stage = kFragmentStage;
    emitOps(frag);
    if (program_.outputs.empty()) throw std::logic_error("emit: a probe program needs an output");
    const ProgramOutput& out = program_.outputs.front();
    std::string value = valueExpr(frag, out.value, out.type);
    const char* pad[] = {"", ", 0.0, 0.0, 0.0", ", 0.0, 0.0", ", 0.0", ""};
    int n = componentCount(out.type);
    if (n < 1 || n > 4) throw std::logic_error("emit: a probe output must be a float or a vector");
    frag.line(-1, iface::kColorOutput, " = vec4(", value, pad[n], ");");
    EmitResult result;
    declareBuiltinUniforms(result, nullptr, frag);
    for (size_t i = 0; i < program_.parameters.size(); ++i)
      if (frag.parameters.count(static_cast<int>(i)))
        result.uniforms.push_back({paramNames_[i], program_.parameters[i].type, static_cast<int>(i), {}, kFragmentStage});
    assignSamplers(result);
    std::set<std::string> functions;
    result.shaders.push_back(assemble(ShaderStage::Fragment, frag, result, functions));
    for (const auto& item : GlslLibrary::builtin().items())
      if (functions.count(item.name)) result.functions.push_back(item.name);
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

  // The builtin uniforms the stages use, in table order, then the time phases.
  void declareBuiltinUniforms(EmitResult& result, const StageWriter* vert, const StageWriter& frag) const {
    for (const auto& row : builtinUniformTable()) {
      unsigned stages = (vert && vert->builtinUniforms.count(row.id) ? kVertexStage : 0u) |
                        (frag.builtinUniforms.count(row.id) ? kFragmentStage : 0u);
      if (stages) result.uniforms.push_back({std::string(row.glslName), row.type, -1, row.id, stages});
    }
    result.uniforms.insert(result.uniforms.end(), phases_.begin(), phases_.end());
  }

  // Samplers: node textures by first use, then scene textures in the manifest's resource
  // order; vk450 bindings follow the uniform block's.
  void assignSamplers(EmitResult& result) {
    std::stable_sort(sceneTextures_.begin(), sceneTextures_.end(), [](const TextureInfo& a, const TextureInfo& b) {
      return resourceRank(a) < resourceRank(b);
    });
    result.textures = textures_;
    result.textures.insert(result.textures.end(), sceneTextures_.begin(), sceneTextures_.end());
    for (size_t i = 0; i < result.textures.size(); ++i)
      result.textures[i].binding = iface::kUniformBlockBinding + 1 + static_cast<int>(i);
  }

  std::string builtinExpr(StageWriter& w, Builtin b) {
    w.builtins.insert(b);
    if (probe_ && b == Builtin::Uv) {
      // b_uv (builtinLocals): the case's uv, varying across the quad by its gradient.
      useUniform(w, BuiltinUniform::ProbeUvGradient);
      useUniform(w, BuiltinUniform::ProbePixel);
      useUniform(w, builtinRow(b).uniform);
      return "b_uv";
    }
    if (probe_) return useUniform(w, builtinRow(b).uniform);
    bool vertex = w.stage == kVertexStage;
    switch (b) {
      case Builtin::Uv: return vertex ? (tess_ ? "b_uv" : iface::kUvAttribute) : "v_uv";
      case Builtin::WorldPosition:
        if (vertex) w.builtinUniforms.insert(BuiltinUniform::Model);
        return vertex ? "b_world_position" : "v_world_position";
      case Builtin::Normal:
        if (vertex) w.builtinUniforms.insert(BuiltinUniform::Model);
        return "b_normal";
      case Builtin::ViewDirection:
        w.builtinUniforms.insert(BuiltinUniform::CameraPosition);
        if (vertex) w.builtinUniforms.insert(BuiltinUniform::Model);
        return "b_view_direction";
      case Builtin::ScreenUv: w.builtinUniforms.insert(BuiltinUniform::ViewportSize); return "b_screen_uv";
      case Builtin::FragDepth: return deferred_ && !vertex ? "b_water_surface.w" : "gl_FragCoord.z";
      case Builtin::CameraPosition:
      case Builtin::Time:
      case Builtin::CameraNearFar:
      case Builtin::View:
      case Builtin::Projection:
      case Builtin::SunDirection: return useUniform(w, builtinRow(b).uniform);
    }
    return "";
  }

  static std::string useUniform(StageWriter& w, BuiltinUniform u) {
    w.builtinUniforms.insert(u);
    return uniformName(u);
  }

  std::string opOutput(const StageWriter& w, int op, int port) const {
    size_t at = portBase_[static_cast<size_t>(op)] + static_cast<size_t>(port);
    if (at < w.aliases.size() && !w.aliases[at].empty()) return w.aliases[at];
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
    UniformInfo u{uniformName(BuiltinUniform::TimePhase) + std::to_string(phases_.size()), Type::Float, -1,
                  BuiltinUniform::TimePhase, w.stage, omega};
    phases_.push_back(u);
    return u.name;
  }

  // One sampler per distinct (source, sampler state): GL 3.3 keeps wrap and filter in the
  // texture object (the runtime uses no sampler objects) and sRGB is its internal format,
  // so a PNG read two ways is two textures, each with its own unit.
  std::string nodeTexture(StageWriter& w, const std::string& source, const SamplerState& sampler) {
    for (auto& t : textures_)
      if (!t.scene && t.source == source && t.sampler == sampler) {
        t.stages |= w.stage;
        return t.name;
      }
    std::string stem = source.rfind(kBuiltinTexturePrefix, 0) == 0 ? source.substr(kBuiltinTexturePrefix.size())
                                                                     : std::filesystem::path(source).stem().string();
    TextureInfo t;
    t.name = "t" + std::to_string(textures_.size()) + "_" + sanitiseIdentifier(stem);
    t.source = source;
    t.sampler = sampler;
    t.stages = w.stage;
    textures_.push_back(t);
    return t.name;
  }

  std::string sceneSampler(StageWriter& w, SceneSampler sampler) {
    for (auto& t : sceneTextures_)
      if (t.scene == sampler) {
        t.stages |= w.stage;
        return t.name;
      }
    const SceneSamplerRow& row = sceneSamplerRow(sampler);
    TextureInfo t;
    t.name = row.glslName;
    t.type = row.type;
    t.scene = sampler;
    t.stages = w.stage;
    sceneTextures_.push_back(t);
    return t.name;
  }

  // Deferred water: which G-buffer look-ups the fragment's builtins need (declared now, so
  // the samplers are in the interface; builtinLocals writes the reads).
  void prepareDeferredFragment(StageWriter& w) {
    const auto& b = w.builtins;
    bool position = b.count(Builtin::WorldPosition) || b.count(Builtin::ViewDirection) || b.count(Builtin::FragDepth);
    bool normalUv = b.count(Builtin::Normal) || b.count(Builtin::Uv);
    if (!position && !normalUv) return;
    builtinExpr(w, Builtin::ScreenUv);
    if (position) sceneSampler(w, SceneSampler::WaterSurface);
    if (normalUv) sceneSampler(w, SceneSampler::WaterNormalUv);
  }
  const Program& program() const { return program_; }
  const ValueFacts& facts() const { return facts_; }
  bool probe() const { return probe_; }

 private:
  void emitOps(StageWriter& w) {
    // Which outputs of which ops this stage reads.
    std::vector<char> used(portBase_.back(), 0);  // by port index
    auto use = [&](const ValueRef& r) {
      if (r.kind != ValueRef::Kind::Op) return;
      used[portBase_[static_cast<size_t>(r.index)] + static_cast<size_t>(r.port)] = 1;
    };
    for (size_t i = 0; i < program_.ops.size(); ++i)
      if (program_.ops[i].stage & w.stage)
        for (const auto& in : program_.ops[i].inputs) use(in);
    for (const auto& out : program_.outputs) {
      if (outputSlotRow(out.slot).stage == w.stage) use(out.value);
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
        if (!used[portBase_[i] + p]) continue;
        if (ctx.outputs[p].empty())
          throw std::logic_error("node '" + op.spec->type + "' emitted no expression for output '" +
                                 op.spec->outputs[p].name + "'");
        if (isPlainName(ctx.outputs[p])) {
          if (w.aliases.empty()) w.aliases.resize(portBase_.back());
          w.aliases[portBase_[i] + p] = std::move(ctx.outputs[p]);
          continue;
        }
        const int at = static_cast<int>(i);
        if (op.outputTypes.size() > 1)
          w.line(at, typeName(op.outputTypes[p]), " ", opNames_[i], "_", op.spec->outputs[p].name, " = ", ctx.outputs[p], ";");
        else
          w.line(at, typeName(op.outputTypes[p]), " ", opNames_[i], " = ", ctx.outputs[p], ";");
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
    if (probe_) {
      // Every builtin is a uniform; uv also moves by the case's gradient per pixel away from
      // the case's pixel, so dFdx(uv) and dFdy(uv) (the level of detail of a mipmapped
      // texture()) are the gradient, while at the pixel itself the offset is exactly 0 and
      // uv is the case's value bit for bit.
      if (w.builtins.count(Builtin::Uv))
        lines.push_back("vec2 b_uv = " + uniformName(BuiltinUniform::ProbeUv) + " + " +
                        uniformName(BuiltinUniform::ProbeUvGradient) + ".xy * (gl_FragCoord.x - " +
                        uniformName(BuiltinUniform::ProbePixel) + ".x) + " + uniformName(BuiltinUniform::ProbeUvGradient) +
                        ".zw * (gl_FragCoord.y - " + uniformName(BuiltinUniform::ProbePixel) + ".y);");
      return lines;
    }
    bool vertex = w.stage == kVertexStage;
    if (vertex && tess_) {
      // The evaluation stage: the patch's corners, interpolated at gl_TessCoord.
      auto lerp3 = [](const std::string& a) {
        return "gl_TessCoord.x * " + a + "[0] + gl_TessCoord.y * " + a + "[1] + gl_TessCoord.z * " + a + "[2]";
      };
      lines.push_back("vec3 b_world_position = " + lerp3("te_position") + ";");
      if (w.builtins.count(Builtin::Normal)) lines.push_back("vec3 b_normal = wg_safe_normalize_vec3(" + lerp3("te_normal") + ");");
      if (w.builtins.count(Builtin::Uv)) lines.push_back("vec2 b_uv = " + lerp3("te_uv") + ";");
      if (w.builtins.count(Builtin::ViewDirection))
        lines.push_back("vec3 b_view_direction = wg_safe_normalize_vec3(" + uniformName(BuiltinUniform::CameraPosition) + " - b_world_position);");
    } else if (vertex) {
      lines.push_back("vec3 b_world_position = (" + uniformName(BuiltinUniform::Model) + " * vec4(" + iface::kPositionAttribute + ", 1.0)).xyz;");
      w.builtinUniforms.insert(BuiltinUniform::Model);
      if (w.builtins.count(Builtin::Normal))
        lines.push_back("vec3 b_normal = wg_safe_normalize_vec3(mat3(" + uniformName(BuiltinUniform::Model) + ") * " + iface::kNormalAttribute + ");");
      if (w.builtins.count(Builtin::ViewDirection))
        lines.push_back("vec3 b_view_direction = wg_safe_normalize_vec3(" + uniformName(BuiltinUniform::CameraPosition) + " - b_world_position);");
    } else {
      if (deferred_) deferredLocals(w, lines);
      if (w.builtins.count(Builtin::Normal)) lines.push_back("vec3 b_normal = wg_safe_normalize_vec3(v_normal);");
      if (w.builtins.count(Builtin::ViewDirection))
        lines.push_back("vec3 b_view_direction = wg_safe_normalize_vec3(" + uniformName(BuiltinUniform::CameraPosition) + " - v_world_position);");
      if (w.builtins.count(Builtin::ScreenUv) && !deferred_)
        lines.push_back("vec2 b_screen_uv = gl_FragCoord.xy / " + uniformName(BuiltinUniform::ViewportSize) + ";");
    }
    return lines;
  }

  // Deferred water: the surface builtins of this pixel read from the water G-buffer
  // (u_water_surface = world position, depth; u_water_normal_uv = normal.xz, uv; the
  // normal faces up, so its y is sqrt(1 - x^2 - z^2)) under the names the varyings have.
  void deferredLocals(const StageWriter& w, std::vector<std::string>& lines) const {
    const auto& b = w.builtins;
    bool position = b.count(Builtin::WorldPosition) || b.count(Builtin::ViewDirection) || b.count(Builtin::FragDepth);
    bool normalUv = b.count(Builtin::Normal) || b.count(Builtin::Uv);
    if (b.count(Builtin::ScreenUv))
      lines.push_back("vec2 b_screen_uv = gl_FragCoord.xy / " + uniformName(BuiltinUniform::ViewportSize) + ";");
    if (position) {
      lines.push_back("vec4 b_water_surface = texture(" + samplerName(SceneSampler::WaterSurface) + ", b_screen_uv);");
      lines.push_back("vec3 v_world_position = b_water_surface.xyz;");
    }
    if (normalUv) {
      lines.push_back("vec4 b_water_normal_uv = texture(" + samplerName(SceneSampler::WaterNormalUv) + ", b_screen_uv);");
      if (b.count(Builtin::Normal))
        lines.push_back("vec3 v_normal = vec3(b_water_normal_uv.x, sqrt(max(1.0 - dot(b_water_normal_uv.xy, "
                        "b_water_normal_uv.xy), 0.0)), b_water_normal_uv.y);");
      if (b.count(Builtin::Uv)) lines.push_back("vec2 v_uv = b_water_normal_uv.zw;");
    }
  }

  // The version line, the extension tessellation needs in GLSL 330, ES precision.
  void addPreamble(ShaderStage stage, ShaderText& out) const {
    out.add(std::string(style_.version));
    bool tessStage = stage == ShaderStage::TessControl || stage == ShaderStage::TessEvaluation;
    if (tessStage && target_ == Target::Glsl330) out.add("#extension GL_ARB_tessellation_shader : require");
    out.add("// Generated by watergraph from " + sourceName_ + " (graph '" + program_.graphName + "'); do not edit.");
    if (style_.precision) {
      out.add("precision highp float;");
      out.add("precision highp int;");
      // Samplers default to lowp, and a sampler passed to a library function takes the
      // default: llvmpipe then returns half floats (0.6 reads 0.5996) and quantises 8-bit
      // texels to n/256. The hard-case probe found both.
      out.add("precision highp sampler2D;");
      out.add("precision highp samplerCube;");
    }
    out.add("");
  }

  // Declarations of `names` (patch or stage interface) with Vulkan locations from 0.
  void addInterface(ShaderText& out, const std::string& qualifier,
                    const std::vector<std::pair<Type, std::string>>& vars, const std::string& suffix) const {
    int location = 0;
    for (const auto& [type, name] : vars) {
      std::string loc = style_.varyingLocations ? "layout(location = " + std::to_string(location) + ") " : "";
      out.add(loc + qualifier + " " + std::string(typeName(type)) + " " + name + suffix + ";");
      ++location;
    }
  }

  // What travels from the vertex shader through the control stage to the evaluation
  // stage when tessellating: world position, and the normal and uv if used.
  std::vector<std::pair<Type, std::string>> patchVars(const StageWriter& geometry, const std::string& prefix) const {
    std::vector<std::pair<Type, std::string>> vars = {{Type::Vec3, prefix + "position"}};
    if (geometry.builtins.count(Builtin::Normal)) vars.push_back({Type::Vec3, prefix + "normal"});
    if (geometry.builtins.count(Builtin::Uv)) vars.push_back({Type::Vec2, prefix + "uv"});
    return vars;
  }

  // Uniform declarations for a stage: Vulkan's one block (identical everywhere), else the
  // loose uniforms `wanted` selects.
  void addUniforms(ShaderText& out, const EmitResult& io,
                   const std::function<bool(const UniformInfo&)>& wanted) const {
    if (style_.uniformBlock) {
      bool any = false;
      for (const auto& u : io.uniforms) any |= !isSampler(u.type);
      if (!any) return;
      out.add("layout(std140, set = 0, binding = " + std::to_string(iface::kUniformBlockBinding) + ") uniform " + iface::kUniformBlock + " {");
      for (const auto& u : io.uniforms) out.add("  " + std::string(typeName(u.type)) + " " + u.name + ";");
      out.add("};");
      return;
    }
    for (const auto& u : io.uniforms)
      if (wanted(u)) out.add("uniform " + std::string(typeName(u.type)) + " " + u.name + ";");
  }

  void addLibrary(ShaderText& out, const std::string& code, std::set<std::string>& functions) const {
    for (const GlslItem* item : GlslLibrary::builtin().itemsFor(code)) {
      out.add("");
      functions.insert(item->name);
      out.addLines(item->text);
      out.add("");  // ends the item's last line, or adds an empty one after a final '\n'
    }
  }

  // The library items `body` calls, then `void main()` around it (one line per '\n').
  void addMain(ShaderText& out, const std::string& body, std::set<std::string>& functions) const {
    addLibrary(out, body, functions);
    out.add("");
    out.add("void main() {");
    out.addLines(body);
    out.add("}");
  }

  // Tessellating: the vertex shader only moves the mesh into world space.
  EmittedShader tessVertexShader(const StageWriter& geometry, const EmitResult& io, std::set<std::string>& functions) const {
    ShaderText out(ShaderStage::Vertex);
    addPreamble(ShaderStage::Vertex, out);
    for (const auto& a : io.attributes)
      out.add("layout(location = " + std::to_string(a.location) + ") in " + std::string(typeName(a.type)) + " " + a.name + ";");
    addInterface(out, "out", patchVars(geometry, "tc_"), "");
    addUniforms(out, io, [](const UniformInfo& u) { return u.name == uniformName(BuiltinUniform::Model); });
    std::string body = "  tc_position = (" + uniformName(BuiltinUniform::Model) + " * vec4(" + iface::kPositionAttribute + ", 1.0)).xyz;\n";
    if (geometry.builtins.count(Builtin::Normal))
      body += "  tc_normal = wg_safe_normalize_vec3(mat3(" + uniformName(BuiltinUniform::Model) + ") * " + iface::kNormalAttribute + ");\n";
    if (geometry.builtins.count(Builtin::Uv)) body += "  tc_uv = " + std::string(iface::kUvAttribute) + ";\n";
    body += "  gl_Position = vec4(tc_position, 1.0);\n";
    addMain(out, body, functions);
    return std::move(out.shader);
  }

  // Tessellating: levels from the camera distance of each corner (seed 003).
  EmittedShader tessControlShader(const StageWriter& geometry, const EmitResult& io, std::set<std::string>& functions) const {
    ShaderText out(ShaderStage::TessControl);
    addPreamble(ShaderStage::TessControl, out);
    out.add("layout(vertices = 3) out;");
    addInterface(out, "in", patchVars(geometry, "tc_"), "[]");
    addInterface(out, "out", patchVars(geometry, "te_"), "[]");
    addUniforms(out, io, [](const UniformInfo& u) { return u.name == uniformName(BuiltinUniform::CameraPosition); });
    std::string body;
    for (const auto& [type, name] : patchVars(geometry, "")) body += "  te_" + name + "[gl_InvocationID] = tc_" + name + "[gl_InvocationID];\n";
    body += "  if (gl_InvocationID == 0) {\n";
    for (int i = 0; i < 3; ++i)
      body += "    float f" + std::to_string(i) + " = wg_tess_distance_factor(tc_position[" + std::to_string(i) + "], " +
              uniformName(BuiltinUniform::CameraPosition) + ", " + formatGlslFloat(tess_->minDistance) + ", " + formatGlslFloat(tess_->maxDistance) +
              ", " + formatGlslFloat(tess_->factor) + ");\n";
    body += "    gl_TessLevelOuter[0] = 0.5 * (f1 + f2);\n";
    body += "    gl_TessLevelOuter[1] = 0.5 * (f2 + f0);\n";
    body += "    gl_TessLevelOuter[2] = 0.5 * (f0 + f1);\n";
    body += "    gl_TessLevelInner[0] = (f0 + f1 + f2) / 3.0;\n";
    body += "  }\n";
    addMain(out, body, functions);
    return std::move(out.shader);
  }

  EmittedShader assemble(ShaderStage stage, StageWriter& w, const EmitResult& io, std::set<std::string>& functions) {
    std::vector<std::string> locals = builtinLocals(w);
    bool vertex = stage == ShaderStage::Vertex || stage == ShaderStage::TessEvaluation;
    unsigned bit = vertex ? kVertexStage : kFragmentStage;
    ShaderText out(stage);
    addPreamble(stage, out);
    // Inputs.
    if (stage == ShaderStage::TessEvaluation) {
      out.add("layout(triangles, fractional_odd_spacing, ccw) in;");
      addInterface(out, "in", patchVars(w, "te_"), "[]");
    } else if (vertex) {
      for (const auto& a : io.attributes) {
        bool usedHere = a.name == std::string(iface::kPositionAttribute) ||
                        (a.name == std::string(iface::kNormalAttribute) && w.builtins.count(Builtin::Normal)) ||
                        (a.name == std::string(iface::kUvAttribute) && w.builtins.count(Builtin::Uv));
        if (usedHere)
          out.add("layout(location = " + std::to_string(a.location) + ") in " + std::string(typeName(a.type)) + " " + a.name + ";");
      }
    }
    int location = 0;
    // Deferred: the full-screen fragment shader reads the G-buffer instead of varyings.
    for (const auto& v : io.varyings) {
      if (!vertex && deferred_) break;
      std::string qual = style_.varyingLocations ? "layout(location = " + std::to_string(location) + ") " : "";
      out.add(qual + (vertex ? "out " : "in ") + std::string(typeName(v.type)) + " " + v.name + ";");
      ++location;
    }
    if (!vertex) out.add("layout(location = " + std::to_string(iface::kColorLocation) + ") out vec4 " + iface::kColorOutput + ";");
    // Uniforms: Vulkan wants one block with the same members in every stage.
    addUniforms(out, io, [&](const UniformInfo& u) {
      if (!(u.stages & bit)) return false;
      // Tessellating, the model matrix and camera serve the earlier stages only.
      return !(stage == ShaderStage::TessEvaluation && u.name == uniformName(BuiltinUniform::Model));
    });
    for (const auto& t : io.textures) {
      if (!(t.stages & bit)) continue;
      std::string qual = style_.uniformBlock ? "layout(set = 0, binding = " + std::to_string(t.binding) + ") " : "";
      // ES samplers default to lowp, which may return half floats: scene depth and the
      // float G-buffer need highp (node textures are 8-bit and keep the default).
      std::string precision = style_.precision && t.scene ? "highp " : "";
      out.add(qual + "uniform " + precision + std::string(typeName(t.type)) + " " + t.name + ";");
    }
    // Library functions this stage calls, dependencies first.
    // Only lines that name a library item ("wg_"/"WG_" words) can call one: the scan
    // reads those instead of a copy of the whole body.
    auto callsLibrary = [](std::string_view l) {
      return l.find("wg_") != std::string_view::npos || l.find("WG_") != std::string_view::npos;
    };
    std::string code;
    for (const auto& l : locals)
      if (callsLibrary(l)) code.append(l).push_back('\n');
    const std::string_view body = w.body;
    for (size_t start = 0; start < body.size();) {
      size_t end = body.find('\n', start) + 1;  // every body line ends in '\n'
      if (callsLibrary(body.substr(start, end - start))) code.append(body.substr(start, end - start));
      start = end;
    }
    addLibrary(out, code, functions);
    out.add("");
    out.add("void main() {");
    for (const auto& l : locals) out.add("  " + l);
    out.addLines(w.body, &w.lineOp);
    out.add("}");
    return std::move(out.shader);
  }

  const Program& program_;
  Target target_;
  TargetStyle style_;
  std::string sourceName_;
  std::vector<std::string> opNames_;
  std::vector<size_t> portBase_;  // op i's outputs are port indices portBase_[i] ... portBase_[i + 1] - 1
  std::vector<std::string> paramNames_;
  std::map<std::pair<int, int>, std::string> varyingNames_;
  bool probe_ = false;                        // EmitMode::Probe
  ValueFacts facts_;                          // empty in probe mode
  std::optional<TessellationSettings> tess_;  // tessellated geometry stage
  bool deferred_ = false;                     // full-screen fragment stage (underwater)
  std::vector<UniformInfo> phases_;         // time phases, by first use
  std::vector<TextureInfo> textures_;       // node textures, by first use
  std::vector<TextureInfo> sceneTextures_;  // scene resources, by first use (sorted later)
  StageWriter frag_, vert_;  // prepare(): the stage bodies
  EmitResult io_;            // prepare(): the interface, no shaders yet
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
const ParsedOptions& OpEmitContext::parsedOptions() const {
  const Op& op = e_.program().ops[static_cast<size_t>(opIndex_)];
  if (!op.parsedOptions) throw std::logic_error("op '" + op.nodeId + "' has no parsed options");
  return *op.parsedOptions;
}
void OpEmitContext::output(int port, std::string expression) { outputs.at(static_cast<size_t>(port)) = std::move(expression); }
std::string OpEmitContext::builtin(Builtin b) { return e_.builtinExpr(w_, b); }
std::string OpEmitContext::timePhase(double omega) { return e_.phaseUniform(w_, omega); }
std::string OpEmitContext::texture(std::string_view option, const SamplerState& sampler) {
  const nlohmann::json& v = e_.program().ops[static_cast<size_t>(opIndex_)].options.at(option);
  if (!v.is_string()) throw std::logic_error("texture(): option '" + std::string(option) + "' is not a texture");
  return e_.nodeTexture(w_, v.get<std::string>(), sampler);
}
std::string OpEmitContext::sceneTexture(SceneResource resource) {
  const auto& resources = spec().resources;
  const SceneResourceRow& row = sceneResourceRow(resource);
  if (std::find(resources.begin(), resources.end(), resource) == resources.end())
    throw std::logic_error("node '" + spec().type + "' samples scene resource '" + std::string(row.name) +
                           "' without listing it in its resources");
  return e_.sceneSampler(w_, row.sampler);
}
std::string OpEmitContext::temporary(Type type, std::string expression) {
  std::string name = e_.opName(opIndex_) + "_t" + std::to_string(temps_++);
  w_.line(opIndex_, typeName(type), " ", name, " = ", expression, ";");
  return name;
}
ValueFact OpEmitContext::inputFact(int port) const {
  const Op& op = e_.program().ops[static_cast<size_t>(opIndex_)];
  const ValueRef& in = op.inputs.at(static_cast<size_t>(port));
  ValueFact f = e_.facts().of(in, op.inputTypes.at(static_cast<size_t>(port)));
  // Read through a varying: interpolation keeps a range (a convex combination) but not
  // unit length.
  if (in.kind == ValueRef::Kind::Op && w_.stage == kFragmentStage &&
      !(e_.program().ops[static_cast<size_t>(in.index)].stage & kFragmentStage))
    f.normalized = false;
  return f;
}

std::optional<Value> OpEmitContext::inputConstant(int port) const {
  const Op& op = e_.program().ops[static_cast<size_t>(opIndex_)];
  const ValueRef& in = op.inputs.at(static_cast<size_t>(port));
  if (in.kind != ValueRef::Kind::Const) return std::nullopt;
  return in.constant.convertedTo(op.inputTypes.at(static_cast<size_t>(port)));
}

ValueFact OpEmitContext::knownBuiltin(Builtin b) const { return e_.probe() ? ValueFact{} : builtinFact(b); }

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

EmitResult emitProgram(const Program& program, Target target, const std::string& sourceName, EmitMode mode,
                       bool allowTessellation) {
  return Emitter(program, target, sourceName, mode, allowTessellation).run();
}

std::vector<EmitResult> emitPrograms(const Program& program, const std::vector<Target>& targets,
                                     const std::string& sourceName, bool allowTessellation) {
  std::vector<EmitResult> out(targets.size());
  std::vector<bool> done(targets.size(), false);
  for (size_t i = 0; i < targets.size(); ++i) {
    if (done[i]) continue;
    bool tess = Emitter::tessellationFor(program, targets[i], allowTessellation).has_value();
    std::vector<size_t> group;
    for (size_t j = i; j < targets.size(); ++j)
      if (!done[j] && Emitter::tessellationFor(program, targets[j], allowTessellation).has_value() == tess)
        group.push_back(j);
    Emitter e(program, targets[i], sourceName, EmitMode::Shader, allowTessellation);
    e.prepare();
    for (size_t k = 0; k < group.size(); ++k) {
      e.retarget(targets[group[k]]);
      out[group[k]] = e.assembleFor();
      done[group[k]] = true;
    }
  }
  return out;
}

}  // namespace wg
