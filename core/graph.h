#pragma once
// The graph as written in a file (format v1, docs/graph-format.md): plain data, every
// element with the file:line:col it came from. Nothing here knows the node registry;
// core/resolve.h turns a Graph into a typed Program.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/interface_tables.h"  // OutputSlot
#include "core/source_ref.h"
#include "core/types.h"
#include "core/view_transform.h"

namespace wg {

inline constexpr int kGraphFormatVersion = 1;

// What feeds an input or an output slot.
struct InputSource {
  enum class Kind { NodeOutput, Parameter, Literal };
  Kind kind = Kind::Literal;
  // NodeOutput: the referenced node id; Parameter: the parameter's name (after '$'). One
  // string for both: a large graph holds tens of thousands of inputs.
  std::string name;
  std::string port;            // NodeOutput: its output port
  std::vector<double> literal; // Literal: 1 number (float) or 2..4 (vecN)
  SourceRef where;             // the JSON value's position
};

struct NodeInput {
  std::string port;
  InputSource source;
  SourceRef keyWhere;  // the key's position, for "unknown input" errors
};

struct NodeOption {
  std::string name;
  nlohmann::json value;  // as written; validated against the node's OptionSpec by resolve
  SourceRef where;       // the value's position
  SourceRef keyWhere;
};

struct Node {
  std::string id;
  std::string type;
  std::vector<NodeOption> options;  // in file order; saved sorted by name
  std::vector<NodeInput> inputs;    // in file order; saved sorted by port
  std::optional<std::array<double, 2>> editorPosition;  // node canvas position
  SourceRef where;      // the node object's '{'
  SourceRef idWhere;    // the id value
  SourceRef typeWhere;  // the type value
};

struct Parameter {
  std::string name;
  Type type = Type::Float;
  std::vector<double> defaultValue;  // componentCount(type) numbers
  std::optional<double> min;
  std::optional<double> max;
  std::string hint;         // "" or "color"
  std::string description;
  bool isStatic = false;    // folded into the shader at compile time, never a uniform
  SourceRef where;          // the parameter's key
};

// A named set of parameter values (weather presets such as calm | moderate | choppy):
// `--preset NAME` makes them the parameters' defaults before compiling, so static
// parameters fold and uniform ones start there.
// One member of a preset: a parameter's value ("depth": 3), or a node option's value
// ("detail.octaves": 2: node id, '.', option name), which resolve checks against the node's
// type like an option written on the node.
struct PresetValue {
  std::string parameter;      // a parameter's value: its name; "" for a node option
  std::vector<double> value;  // componentCount of the parameter's type
  std::string node;           // a node option's value: the node id ("instance/node" inside a subgraph instance),
  std::string option;         // the option's name
  nlohmann::json optionValue; // and the value as written
  SourceRef where;            // the value's position
  SourceRef keyWhere;         // the key's position

  bool isOption() const { return !node.empty(); }
};

struct Preset {
  std::string name;
  std::vector<PresetValue> values;  // file order
  SourceRef where;                  // the preset's key
};

struct GraphOutput {
  OutputSlot slot{};
  InputSource source;
  SourceRef keyWhere;
};

struct Graph;

// `"imports": {"foam": "lib/shore_foam.json"}`: the graph at that path (relative to this
// file) becomes the node type `foam` here. core/graph_imports.h loads it.
struct Import {
  std::string name;                    // the node type it becomes
  std::string path;                    // as written
  SourceRef where;                     // the key
  SourceRef pathWhere;                 // the path string
  std::shared_ptr<const Graph> graph;  // set by loadImports; one Graph per file, shared
  std::string file;  // set by loadImports: the path it names, as diagnostics name it (also when it failed)
};

// A function graph's outputs, `"interface": {"outputs": {"foam": {...}}}`: what an instance
// of it offers as `instance.port`. Its inputs are its parameters (docs/graph-format.md).
struct InterfaceOutput {
  std::string name;
  Type type = Type::Float;
  InputSource source;
  std::string description;
  SourceRef where;  // the output's key
};

// A function graph's option, `"interface": {"options": {"pattern": {...}}}`: fixed per
// instance (`"options": {"pattern": "cells"}` on the instance node), never a port. A choice
// or a number is read inside as the static value `$pattern` (a choice as the index of the
// value chosen), a texture by a texture option written `"$debris"` (core/instance_options.h).
struct InterfaceOption {
  enum class Kind { Choice, Number, Texture };
  std::string name;
  Kind kind = Kind::Choice;
  std::vector<std::string> choices;  // Choice: the names an instance may choose, file order
  std::optional<double> min;         // Number: the range an instance's value must lie in
  std::optional<double> max;
  nlohmann::json defaultValue;       // null: every instance must set it
  std::string description;
  SourceRef where;         // the option's key
  SourceRef defaultWhere;  // its "default" value
};

struct GraphInterface {
  std::string description;
  std::vector<InterfaceOption> options;  // file order
  std::vector<InterfaceOutput> outputs;  // file order
  SourceRef where;                       // the "interface" object
};

// An option of a node inside a subgraph instance, set from outside the subgraph's file: a
// preset member "instance/node.option" (nested: "a/b/node.option") once the preset is
// applied, or a configuration `watergraph tune` tries. Resolve gives it to that node when it
// inlines the instance, replacing the value written there; the subgraph's file is shared by
// every instance and stays as written.
struct InstanceOption {
  std::string node;  // the qualified id: "instance/node", as the resolved program names it
  NodeOption option;
};

// A frame on the editor's canvas, `"editor": {"frames": {"shore": {"title": "Shore foam",
// "comment": "...", "nodes": ["foam", "mask"]}}}`: a box with a title and a comment drawn
// around its nodes. Layout only: compiling never reads it. The box is where its nodes are
// (their bounding box and a margin), so moving a node moves its frame's edge, and dragging
// the frame moves its nodes; a node lies in at most one frame.
struct Frame {
  std::string id;      // an identifier, unique among the graph's frames
  std::string title;
  std::string comment;                // may hold line breaks
  std::vector<std::string> nodes;     // ids of the graph's nodes, at least one, each once
  SourceRef where;                    // the frame's key
  SourceRef nodesWhere;               // its "nodes" value
};

struct Graph {
  std::string file;      // path as given, used in diagnostics
  std::string schema;    // optional "$schema", kept for editors
  int version = kGraphFormatVersion;
  std::string name;
  std::string description;
  std::vector<Import> imports;               // file order
  std::optional<GraphInterface> interface;  // set: a function graph, usable as a node type
  std::vector<Parameter> parameters;  // file order
  std::vector<Preset> presets;        // file order
  std::vector<Node> nodes;            // file order
  std::vector<GraphOutput> outputs;   // saved in OutputSlot order; may be empty (resolve refuses it)
  SourceRef outputsWhere;             // the "outputs" object, for "connects no outputs"
  std::vector<InstanceOption> instanceOptions;  // set by applyPreset (never read from or saved to a file)
  // "view": {"tonemap": "agx", "exposure": 0.5}: how the graph's author means its frame to be
  // shown (the output transform); tools use it unless --tonemap / --exposure say otherwise.
  std::optional<ViewTransform> view;
  // "editor": {"frames": {...}}: the canvas's frames, in file order (drawn in that order).
  std::vector<Frame> frames;

  const Node* findNode(std::string_view id) const;
  const Parameter* findParameter(std::string_view name) const;
  const Preset* findPreset(std::string_view name) const;
  const Import* findImport(std::string_view name) const;
  const Frame* findFrame(std::string_view id) const;
};

// True for [A-Za-z_][A-Za-z0-9_]*, at most 64 characters.
bool isIdentifier(std::string_view s);

// A node's options as written, as one JSON object (name -> value).
nlohmann::json writtenOptions(const Node& node);

}  // namespace wg
