#pragma once
// A node type, declared once: ports, options, stages, the GLSL it emits, its double
// precision reference, its hard cases and its documentation. The registry (nodes/) holds
// one NodeSpec per type; resolve, codegen, the CPU reference, the docs and the editor's
// palette all read it, so nothing lists the nodes a second time.
#include <array>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/interface_tables.h"
#include "core/node_options.h"
#include "core/type_list.h"
#include "core/sampler_state.h"
#include "core/scene_image.h"
#include "core/types.h"
#include "core/value.h"

namespace wg {

namespace ocean {
struct OceanSettings;  // core/ocean_settings.h
}

// What the compiler knows about a value for every input the shader can receive
// (codegen/value_facts.h derives it per program): each component lies in [lo, hi], and
// `normalized` says a vector is the result of a (safe) normalisation: unit length, except
// that a vector shorter than 1e-15 comes out shorter (wg_safe_normalize floors the squared
// length at 1e-30; zero stays zero), so at most 1 long. Variants relying on it must be
// finite for any length in [0, 1]; they differ from the re-normalising forms only on such
// degenerate vectors. Emitters use facts to drop guards the facts make dead; a default
// ValueFact knows nothing, so missing facts always keep the guarded form. Bounds are as the
// shader sees them: rounded to float, denormals widened to what survives a flush to zero.
struct ValueFact {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool normalized = false;
  bool atLeast(double x) const { return lo >= x; }
  bool above(double x) const { return lo > x; }
  bool isConstant(double x) const { return lo == x && hi == x; }
  // A unit vector (or the zero vector): components in [-1, 1], re-normalising changes nothing.
  static ValueFact unitVector() { return {-1, 1, true}; }
};
// What a compiled (non-probe) shader guarantees about a builtin (core/node_spec.cpp says
// where each guarantee comes from).
ValueFact builtinFact(Builtin b);

// How a port's type is decided. Fixed: `type`. Gen: one of float/vec2/vec3/vec4,
// unified over every Gen port of the node (a float splats to the widest); a Gen output
// takes the unified type. Custom ports are typed by NodeSpec::infer.
enum class PortKind { Fixed, Gen, Custom };

struct PortSpec {
  std::string name;
  PortKind kind = PortKind::Fixed;
  Type type = Type::Float;                 // Fixed ports
  std::optional<Value> defaultValue;       // inputs: used when unconnected
  std::optional<Builtin> defaultBuiltin;   // inputs: or fed by a builtin when unconnected
  std::string doc;
  // A per-draw input the node computes for itself: resolve fills it with ops of their own
  // through NodeSpec::derive, so the part of the node that is the same for every pixel is
  // visible to the frequency analysis as ops. A graph file cannot connect it; the docs
  // list it apart.
  bool derived = false;
  // A colour input (a water, light, haze or fallback colour; not a coefficient such as
  // absorption per metre): a literal a graph file gives it, and its default, are authored
  // as the sRGB values a colour picker shows, and resolve hands the node their linear
  // values (core/color_parameters.h). A probe or hard case gives the node linear values
  // directly; docs/nodes.md marks these ports.
  bool color = false;

  bool required() const { return !defaultValue && !defaultBuiltin && !derived; }
};

struct OptionSpec {
  // Texture: a string, "builtin:<name>" or a .png path relative to the graph file.
  // Text: a string (`validate` may check it); an expression's formula.
  enum class Kind { Enum, Number, Integer, Bool, Json, Texture, Text };
  std::string name;
  Kind kind = Kind::Enum;
  nlohmann::json defaultValue;
  std::vector<std::string> choices;  // Enum
  std::optional<double> min, max;    // Number, Integer
  std::string doc;
  // Json options (e.g. a list of waves) check themselves: "" when valid, else why not.
  std::function<std::string(const nlohmann::json&)> validate;
  // A quality knob: the values that trade speed for accuracy, from the cheapest to the
  // most exact (`watergraph bench GRAPH` measures each; the last is the reference). Empty:
  // not a knob. Every level is a valid value of the option.
  std::vector<nlohmann::json> levels;
  // A knob whose levels depend on the node's other options (ocean_spectrum's cascade_sizes:
  // one size per cascade): the levels, cheapest to most exact, for a node whose options
  // are `written` (as the graph writes them, defaults not filled in); fewer than two where
  // the option is no knob for that node. `levels` stays empty for such an option.
  std::function<std::vector<nlohmann::json>(const nlohmann::json& written)> levelsFor;
};

// The levels of knob `o` on a node whose options are `written`: its fixed levels, or those
// levelsFor gives.
inline std::vector<nlohmann::json> knobLevels(const OptionSpec& o, const nlohmann::json& written) {
  if (!o.levels.empty() || !o.levelsFor) return o.levels;
  return o.levelsFor(written.is_object() ? written : nlohmann::json::object());
}

// A named input set with the behaviour it must keep: every output finite, and the
// components of `output` (the first output when empty) within [lo, hi].
struct HardCase {
  std::string name;
  std::vector<std::pair<std::string, Value>> inputs;  // port name -> value
  nlohmann::json options = nlohmann::json::object();
  std::string expectation;  // what "safe" means here, for the docs
  double lo = -1e30, hi = 1e30;
  std::string output;
  // Set only where float32 cannot determine the result at all (a phase of 1e30 rad): the
  // case then checks finiteness and [lo, hi] with this tolerance instead of the node's
  // error bound. Every other case is held to the bound.
  std::optional<double> tolerance;
  // A node with an `ocean` input: the options of the ocean_spectrum the case's sea comes
  // from (its defaults when empty).
  nlohmann::json oceanOptions = nlohmann::json::object();
};

struct NodeSpec;
struct ExpandContext;  // core/expand.h
struct DeriveContext;  // core/derive.h

// The ports of a node whose ports follow from its options (NodeSpec::portsFor).
// The index of the port named `name` in `ports`, or -1.
int portIndex(const std::vector<PortSpec>& ports, std::string_view name);

struct NodePorts {
  std::vector<PortSpec> inputs;
  std::vector<PortSpec> outputs;
  int inputIndex(std::string_view name) const { return portIndex(inputs, name); }
  int outputIndex(std::string_view name) const { return portIndex(outputs, name); }
};

// What infer sees and decides: input types (Invalid when unconnected without default)
// and the node's options; it sets output types and any Custom input types.
struct InferContext {
  const NodeSpec& spec;
  const ParsedOptions& options;   // the node's options struct: options.as<T>()
  TypeList inputTypes;   // per input port: the type connected or defaulted
  TypeList outputTypes;  // to fill
  std::string error;              // set to refuse: "input 'x' must be a vector"
  int errorInput = -1;            // the port the error is about, if any
};

// The codegen side of a node (core/emit_context.h): what emit() writes GLSL through.
class EmitContext;

// Builtin values for the CPU reference: what a case says the stage provides.
struct EvalEnvironment {
  Value uv = Value::vector({0.5, 0.5});
  Value worldPosition = Value::vector({0, 0, 0});
  Value normal = Value::vector({0, 1, 0});
  Value viewDirection = Value::vector({0, 1, 0});
  Value cameraPosition = Value::vector({0, 10, 0});
  Value time = Value::scalar(0);
  Value screenUv = Value::vector({0.5, 0.5});
  Value fragDepth = Value::scalar(0.5);
  Value cameraNearFar = Value::vector({0.1, 100});
  Value view = Value::ofType(Type::Mat4);        // column-major, as GLSL
  Value projection = Value::ofType(Type::Mat4);  // column-major, as GLSL
  Value sunDirection = Value::vector({0.6666666666666666, 0.6666666666666666, -0.3333333333333333});
  // The angle a pixel subtends at the image centre, 2 / (projection[1][1] viewport height):
  // what a footprint on the water grows from (1e-3: a 1000-pixel-high view of 53 degrees).
  Value pixelAngle = Value::scalar(1e-3);
  // Scene resources as the case sees them at this pixel (what a texture fetch returns).
  Value sceneDepth = Value::scalar(1.0);  // depth-buffer value behind the water (1 = sky)
  Value sceneColor = Value::vector({0, 0, 0});
  Value reflectionColor = Value::vector({0, 0, 0});
  Value refractionColor = Value::vector({0, 0, 0});
  Value environmentColor = Value::vector({0, 0, 0});
  // The screen-space derivatives of the uv builtin, (du/dx, dv/dx) and (du/dy, dv/dy):
  // what a mipmapped texture look-up at uv chooses its level from. Zero (level 0) unless
  // a probe case gives "uv_dx"/"uv_dy"; the probe's GPU path draws uv varying by them
  // across the pixel's quad, so the shader's implicit derivatives are these.
  Value uvDx = Value::vector({0, 0});
  Value uvDy = Value::vector({0, 0});
  // Scene textures whose whole image the reference has (per SceneSampler; null: the one
  // value of the field above). `check` sets them for deferred water, whose shader samples
  // scene depth and colour at positions it computes (core/scene_image.h).
  std::array<const SceneImage*, kSceneSamplerCount> sceneImages{};
  const Value& builtin(Builtin b) const;
  // What a look-up of the 2D scene texture `s` at screen position (u, v) returns: the
  // image sampled as the GPU does where there is one, else this pixel's field value.
  Value sceneAt(SceneSampler s, double u, double v) const;
  Value sceneAt(SceneSampler s, const Value& uv) const { return sceneAt(s, uv[0], uv[1]); }
};

class EvalContext {
 public:
  virtual ~EvalContext() = default;
  virtual const Value& input(int port) const = 0;
  virtual Type inputType(int port) const = 0;
  virtual Type outputType(int port) const = 0;
  // The op's options, parsed once into the node's struct (core/node_options.h).
  virtual const ParsedOptions& parsedOptions() const = 0;
  template <class T>
  const T& options() const { return parsedOptions().as<T>(); }
  virtual void output(int port, Value v) = 0;
  virtual const EvalEnvironment& environment() const = 0;
  virtual const NodeSpec& spec() const = 0;
  // The texture of a Texture option sampled as GL would with `sampler`, the level of
  // detail of a mipmapped look-up taken from `gradient` (nodes/texture_sampling.h): vec4.
  virtual Value sampleTexture(std::string_view option, double u, double v, const SamplerState& sampler,
                              const UvGradient& gradient) const = 0;
  // With the default state (GL_LINEAR + GL_REPEAT, linear data), which needs no gradient.
  Value sampleTexture(std::string_view option, double u, double v) const {
    return sampleTexture(option, u, v, SamplerState{}, UvGradient{});
  }

  const Value& input(std::string_view port) const;
  double scalar(std::string_view port) const { return input(port)[0]; }
};

// Distance-based tessellation of the surface mesh (the stylized water shader, docs/sources.md): per vertex
// f = clamp(1 - (d - minDistance) / (maxDistance - minDistance), 0.01, 1) * factor.
struct TessellationSettings {
  double minDistance = 5;
  double maxDistance = 50;
  double factor = 16;
};

// The option Registry::add gives every node that declares NodeSpec::bypass.
inline constexpr const char* kBypassOption = "bypass";

// The option Registry::add gives every node that reads a frame-sized scene resource (all
// but the environment cube map): the size of the render targets of the passes producing
// what it reads, as a fraction of the frame's width and height (1: the frame's size). A
// quality knob (levels in registry.cpp); it changes no shader text, only the manifest's
// "pass_scales" (a pass read by several nodes takes the smallest of their values: one
// reader lowered lowers the pass, so `tune` can try it one knob at a time).
inline constexpr const char* kResolutionOption = "resolution";
inline constexpr double kMinResolution = 0.25;

struct NodeSpec {
  std::string type;     // "fresnel"
  std::string family;   // "optics", "math", "inputs", ...
  std::string summary;  // one line
  std::string formula;  // the maths, for docs/nodes.md
  std::string source;   // the technique sources it follows (docs/sources.md names them), "" for general nodes
  std::string cost;     // cost notes for docs/nodes.md
  std::vector<PortSpec> inputs;
  std::vector<PortSpec> outputs;
  std::vector<OptionSpec> options;
  // Reads `options` into the node's struct, once per op (null: the node reads none).
  OptionParser parseOptions;
  unsigned stages = kAnyStage;
  // Reads builtins, textures or time (ctx.timePhase): never constant-folded.
  bool isSource = false;
  // Input nodes: reading the attribute or uniform again in the fragment stage is cheaper
  // than a varying, so the stage pass recomputes them there.
  bool recomputeInFragment = false;
  // A source that reads only uniforms (time, camera): the same for every vertex, so the
  // fragment stage recomputes it instead of interpolating it.
  bool isUniformSource = false;
  std::function<void(InferContext&)> infer;  // null: Fixed and Gen rules only
  // Options meaningless together, or a value the per-option checks cannot judge alone
  // (cascade tiles that overlap at the chosen resolution): the option to blame and why, or
  // nothing. resolve reports it as an invalid option at that option (at the node when the
  // file does not write it).
  struct OptionProblem {
    std::string option, why;
  };
  std::function<std::optional<OptionProblem>(const ParsedOptions& options)> checkOptions;
  // Algebraic identity: given the op's constant inputs (nullopt where not constant), the
  // index of the input its single output equals (x * 1, x + 0, mix(a, b, 0)), or -1. The
  // simplify pass uses it only when that input already has the output's type.
  std::function<int(const std::vector<std::optional<Value>>& constants)> identity;
  // A node that shapes the mesh itself may ask for tessellation, given its options.
  std::function<std::optional<TessellationSettings>(const ParsedOptions& options)> tessellation;
  // Facts of the outputs given the facts of the inputs and the options (one per output).
  // Null: nothing known. Must hold for every input the facts admit (value_facts_test).
  std::function<std::vector<ValueFact>(const std::vector<ValueFact>& inputs, const ParsedOptions& options)> facts;
  std::function<void(EmitContext&)> emit;
  std::function<void(EvalContext&)> eval;
  // A node that is not one op but a piece of program built from its options (an
  // expression's formula): resolve calls `expand` in place of making an op, so the ops it
  // appends go through every pass, the emitter and the CPU backend as if wired by hand.
  // Such a node has neither emit nor eval. `portsFor` gives its ports from its parsed
  // options (an expression declares its inputs); `inputs` and `outputs` then hold only
  // what every instance has, for the docs.
  std::function<void(ExpandContext&)> expand;
  std::function<NodePorts(const ParsedOptions& options)> portsFor;
  // A node with `derived` input ports (PortSpec::derived): given the values of its other
  // inputs, it appends the ops that compute the derived ones (from math nodes and small
  // per-draw nodes) and names their values. resolve calls it before typing the op; the op
  // itself then reads them as inputs, so emit and eval see them like any other input.
  std::function<void(DeriveContext&)> derive;
  std::vector<HardCase> hardCases;
  // The error bound of float32 GPU against the double reference, per output component:
  //   |gpu - ref| <= tolerance * max(1, |ref|) + conditioning
  // `tolerance` bounds the rounding of the evaluation itself. `conditioning` is what the
  // formula makes of the rounding of its inputs: the sum, over every float32 input
  // component x the shader computes with, of how far the exact result moves when x moves
  // by conditionRoundings * 2^-24 * |x| (either way). It is small where the formula is
  // well-conditioned and grows where it is not (the critical angle, a phase k x at 1e5 m),
  // without a hand-set window; a wrong constant still fails. 0: `tolerance` alone.
  // The probe and the hard-case suite apply it (accuracy/error_bound.h).
  double tolerance = 1e-5;
  double conditionRoundings = 0;
  std::string conditionWhy;  // for the docs: which inputs make it grow, and where
  // Scene resources the node reads; each makes the runtime run the pass that produces it
  // (core/interface_tables.h says which).
  std::vector<SceneResource> resources;
  // A node that adds detail (caustics, foam, scattering, ripples) says what each output is
  // when it is switched off: one of its inputs passed through, or a constant. Registry::add
  // then gives it the Bool option `bypass` (kBypassOption), a quality knob whose cheaper
  // level is on; the bypass pass (codegen/pass_bypass.cpp) replaces a bypassed op by these
  // values before any other pass, so what only it needed (the ops feeding it, the scene
  // resources it reads) is pruned with it.
  struct BypassValue {
    std::string output;
    std::string input;              // this input passes through, or
    std::optional<Value> constant;  // this constant stands in
  };
  std::vector<BypassValue> bypass;
  // GLSL definitions of the node's own, beyond the library's: a function node's file,
  // renamed into its namespace and accepted by glslang for every target (core/file_node.h).
  // The planner emits it once before main in each stage that runs the node.
  std::shared_ptr<const std::string> ownGlsl;

  int inputIndex(std::string_view name) const;
  int outputIndex(std::string_view name) const;
  int optionIndex(std::string_view name) const;
};


}  // namespace wg
