#pragma once
// The manifest beside the shaders: what a runtime or engine needs to drive them
// (attributes, uniforms with defaults and ranges, varyings, scene resources, render
// passes) and what the compiler kept and removed, so a user can see what each choice costs.
//
// A plain value. The compiler builds it (codegen/manifest_build.h) and writes it as JSON
// (fileText); the runtime takes it as it is when it runs a graph compiled in the same
// process, and only a manifest read from disk goes through fromJson. Scene resources,
// passes and builtin uniforms are enumerators of core/interface_tables.h, so nothing
// compares names after the JSON is read.
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "codegen/emit_glsl.h"
#include "codegen/target.h"
#include "core/view_transform.h"
#include "core/interface_tables.h"
#include "core/node_spec.h"
#include "core/types.h"

namespace wg {

inline constexpr int kManifestFormat = 1;
// Tessellated targets draw the water as patches of this many vertices.
inline constexpr int kPatchVertices = 3;

// A manifest Manifest::fromJson cannot read; the message names the member at fault.
class ManifestError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ManifestStageFile {
  ShaderStage stage{};
  std::string file;        // "lake.glsl330.vert"
  std::string spirv;       // vk450: "lake.vk450.vert.spv"; "" for the others
  // es300 (codegen/target.h writesStageBodies): "lake.es300.vert.body", the stage after its
  // version line, for a host that writes that line itself (three.js); "" for the others.
  // Written in the manifest's "three" section, not among the target's files.
  std::string body;
  std::string entryPoint;  // targets made by SPIRV-Cross: "main0" (MSL), "main" (HLSL); "" for GLSL
};

struct ManifestTarget {
  std::string name;                      // "glsl330", ..., or a cross target: "msl", "hlsl"
  std::vector<ManifestStageFile> files;  // in pipeline order
  std::string from;                      // cross targets: how the files were made; "" for GLSL
  std::string glslVersion;  // with body files: the version they are written without ("300 es"); else ""
};

// What a parameter uniform holds: the graph parameter, its default and its range.
struct ManifestParameter {
  std::string name;
  std::vector<double> defaultValue;  // one per component
  std::optional<double> min, max;    // every uploaded value is clamped into them
  std::string hint;
  // "srgb" for a colour parameter ("hint": "color" or "hdr_color"): its default, range and
  // every value a host sets are the sRGB values a colour picker shows, and the shader
  // linearises them; "" for data, used as it is.
  std::string colorSpace;
  std::string description;
};

struct ManifestUniform {
  std::string name;  // GLSL name
  Type type = Type::Float;
  unsigned stages = 0;
  std::optional<ManifestParameter> parameter;     // set for a graph parameter
  BuiltinUniform builtin = BuiltinUniform::Time;  // what it holds otherwise
  double angularFrequency = 0;                    // TimePhase: mod(omega * time, 2 pi)
};

struct ManifestTessellation {
  TessellationSettings settings;
  std::vector<std::string> targets;  // the targets that tessellate, in target order
};

// A scene pass whose render targets are smaller than the frame: each is `scale` times the
// frame's width and height (rounded, at least 1 pixel). Passes not listed are the frame's size.
struct ManifestPassScale {
  RenderPass pass = RenderPass::DepthPrepass;
  double scale = 1;
};

struct ManifestKeptNode {
  std::string node;
  std::string type;
  unsigned stages = 0;
  std::vector<std::string> merged;  // ids of the nodes cse merged into this one
};

struct ManifestRemoval {
  std::string what;
  std::string reason;
};

struct Manifest {
  int format = kManifestFormat;
  std::string graph;
  std::string description;  // "" when the graph has none
  // The colour contract: "fragment.color" is linear, scene-referred radiance (Rec. 709
  // primaries, may exceed 1); `view` is the output transform the graph's author meant it to
  // be shown through, written as "color": {"frame": "linear", "primaries": "bt709",
  // "view": {"exposure": EV, "output": "srgb", "tonemap": NAME}}.
  ViewTransform view;
  std::string preset;       // the preset whose values became the defaults; "" for none
  // The graph files the graph imports (its subgraphs), relative to its folder, each once.
  std::vector<std::string> imports;
  std::vector<ManifestTarget> targets;
  // The shader interface, the same for every target (names, order, bindings).
  std::vector<AttributeInfo> attributes;
  std::vector<ManifestUniform> uniforms;    // declaration order
  std::vector<VaryingInfo> varyings;
  std::vector<std::string> functions;       // GLSL library items emitted, in order
  std::vector<TextureInfo> textures;        // node textures by first use, ocean maps, then scene samplers
  // The spectral oceans the ocean maps come from (written as "oceans" only when there are
  // any): each ocean_spectrum node's id and complete options.
  std::vector<OceanInfo> oceans;
  // The web clients' ocean module beside the manifest (codegen/ocean_module_js.h), written
  // as each ocean's "module"; "" when the compile wrote none (no web target).
  std::string oceanModule;
  std::optional<ManifestTessellation> tessellation;
  std::vector<SceneResource> resources;     // table order
  std::vector<RenderPass> passes;           // the passes producing them, then WaterSurface
  // Listed passes rendered below the frame's size (the `resolution` option of the nodes that
  // read them, core/node_spec.h kResolutionOption), in the order of `passes`; none by
  // default, and then the file has no "pass_scales".
  std::vector<ManifestPassScale> passScales;
  int nodesTotal = 0;
  std::vector<ManifestKeptNode> kept;
  std::vector<ManifestRemoval> removed;

  const ManifestTarget* target(std::string_view name) const;  // null when not compiled for it
  bool lists(RenderPass pass) const;
  double scaleOf(RenderPass pass) const;  // 1 unless passScales lists it

  // The manifest file's contents, written straight into one string (no DOM): the bytes
  // nlohmann's dump(2) of the same members gives, and a final newline.
  std::string fileText() const;
  // The same as JSON (parsed from fileText, so the two cannot differ).
  nlohmann::json toJson() const;
  // Reads a manifest file's JSON. Lists other than "passes" may be absent (none); every
  // entry must have the members the compiler writes, and no others, so toJson gives back
  // the JSON that was read. Throws ManifestError.
  static Manifest fromJson(const nlohmann::json& json);
};

}  // namespace wg
