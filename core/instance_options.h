#pragma once
// A subgraph instance's options (docs/graph-format.md, "Options of an instance"): what the
// function graph's interface declares (InterfaceOption), what one instance sets, and what
// follows for the nodes inside — the static values `$name` reads and the textures a
// texture option written "$name" samples. The loader checks the declarations; resolve binds
// each instance's values (or, for a function graph compiled on its own, the defaults) with
// bindInstanceOptions and hands the bindings to the subgraph's resolver.
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "core/diagnostic.h"
#include "core/graph.h"
#include "core/sampler_state.h"
#include "core/texture_check.h"

namespace wg {

// "choice", "number", "texture" (the declaration's "type").
std::string_view interfaceOptionKindName(InterfaceOption::Kind kind);
std::optional<InterfaceOption::Kind> parseInterfaceOptionKind(std::string_view name);

// A texture option's value: `"leaves.png"`, or `{"file": "leaves.png", "wrap": "clamp",
// "filter": "nearest", "color_space": "linear"}` where the state members set the sampler
// state of every node that samples it (each optional: unset, the node's own).
struct InterfaceTexture {
  std::string source;  // a .png path or builtin:<name>, as written
  std::optional<TextureWrap> wrap;
  std::optional<TextureFilter> filter;
  std::optional<TextureColorSpace> colorSpace;
};

// "" when `value` is one that `option` accepts, else why not (for WG092): not one of the
// choices, outside the range, not finite, or not of the option's form. A texture's file is
// not looked at here (bindInstanceOptions does that, relative to the file that names it).
std::string interfaceOptionValueProblem(const InterfaceOption& option, const nlohmann::json& value);

// The value of a texture option that interfaceOptionValueProblem accepted.
InterfaceTexture interfaceTexture(const nlohmann::json& value);

// What one instance's options give its subgraph's nodes.
struct BoundTexture {
  InterfaceTexture texture;  // source relative to the top-level graph's folder (or builtin:)
  SourceRef where;           // the value that chose it, for faults found inside
};
struct InstanceBindings {
  std::map<std::string, double, std::less<>> statics;  // `$name`: a number, or a choice's index
  std::map<std::string, BoundTexture, std::less<>> textures;
};

// Where the values come from and how a texture that passed the path checks is accepted.
struct InstanceOptionRequest {
  const GraphInterface& interface;
  const std::string& interfaceFile;  // the function graph's file (its defaults' paths are relative to it)
  // The instance node, or null for a function graph compiled on its own (defaults only).
  const Node* instance = nullptr;
  std::string instanceId;            // as diagnostics name it ("outer/debris")
  std::string instanceFile;          // the graph file that holds the instance
  std::string topDirectory;          // the top-level graph's folder: bound paths end relative to it
  // The graph-wide texture budget and the decode check: "" or why the file is refused.
  std::function<std::string(const TextureFile&)> accept;
};

// The bindings, or nullopt after reporting: an option the instance sets that the interface
// does not declare (WG091), a value it does not accept (WG092), a declared option without
// a default that the instance leaves out, or that a graph compiled on its own has no value
// for (WG090), a texture that cannot be used (WG093, at the value that names it).
std::optional<InstanceBindings> bindInstanceOptions(const InstanceOptionRequest& request, Diagnostics& diags);

// "$name" for an identifier `name`: how a node's texture option names an interface texture.
std::optional<std::string_view> interfaceTextureReference(const nlohmann::json& optionValue);

}  // namespace wg
