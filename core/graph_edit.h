#pragma once
// Editing a Graph with undo and redo: the model the editor (editor/) is a UI over, and
// what its --script mode drives. Every edit checks its arguments first and either changes
// the graph or returns why not, leaving the graph as it was. Types are not checked here
// (a connection between a vec2 output and a vec3 input is a valid edit); compiling the
// graph reports them, with the node and port, as for a graph file.
#include <array>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/graph.h"
#include "core/registry.h"

namespace wg {

// Where a connection ends: a node input, or (node empty) a graph output slot such as
// "fragment.color".
struct InputTarget {
  std::string node;
  std::string port;
};

class GraphEditor {
 public:
  // With a registry, node types and port names are checked against it and the graph's
  // imports (a loaded subgraph's ports are its interface's, core/graph_node_type.h);
  // without one only what the file format itself requires is. A file node's ports (a
  // glsl_function's, from its .glsl file) are left to compiling, which reads the file.
  explicit GraphEditor(Graph graph, const Registry* registry = nullptr);

  const Graph& graph() const { return graph_; }

  // Each returns "" when the edit was applied, else one line saying why it was refused.
  std::string setParameterDefault(const std::string& name, const std::vector<double>& value);
  // Makes a graph preset's values ("presets": {"calm": {...}}) the parameters' defaults,
  // as one undoable step: what `--preset NAME` compiles, made permanent on save.
  std::string applyPreset(const std::string& name);
  std::string setInputConstant(const InputTarget& target, const std::vector<double>& value);
  std::string setInputParameter(const InputTarget& target, const std::string& parameter);
  // A node option (e.g. fresnel's "model"). With a registry, the name must exist and an
  // enum, bool or number option's value must fit it; texture and JSON options are checked
  // by compiling.
  std::string setOption(const std::string& node, const std::string& name, const nlohmann::json& value);
  // Feeds `target` from output `fromPort` of node `fromNode`; refused if it closes a cycle.
  std::string connect(const std::string& fromNode, const std::string& fromPort, const InputTarget& target);
  // The input goes back to its default (or the output slot is removed).
  std::string disconnect(const InputTarget& target);
  // `id` empty: "<type>_<n>", the first free. The id used is returned in *usedId.
  std::string addNode(const std::string& type, const std::string& id, std::array<double, 2> position,
                      std::string* usedId = nullptr);
  // Removes the node and every input and output slot that reads it.
  std::string deleteNode(const std::string& id);
  std::string moveNode(const std::string& id, std::array<double, 2> position);
  // Several nodes at once (a selection dragged on the canvas, a pasted group), one undo step
  // (merged while the same nodes keep moving, like moveNode). Refused whole if any id is
  // unknown or any position does not fit.
  std::string moveNodes(const std::vector<std::pair<std::string, std::array<double, 2>>>& positions);
  // Several nodes and their links, one undo step.
  std::string deleteNodes(const std::vector<std::string>& ids);
  // Adds `nodes` (a paste) as one undo step. Refused whole, the graph unchanged, when an id
  // is not an identifier, is taken or repeats, a type is unknown (with a registry), a link
  // names a node that is neither in the graph nor among `nodes`, the links among `nodes`
  // close a cycle, a position does not fit, or the graph would pass its node limit.
  std::string insertNodes(std::vector<Node> nodes);
  // The blackboard (core/graph_edit_parameters.cpp): parameters and presets, each one undo
  // step, refused whole with a reason as every edit is.
  // A new parameter: an identifier not taken, `defaultValue` of the type's size, finite in
  // float32, within min and max; hint "", "color" or "hdr_color" (a vec3 or vec4).
  std::string addParameter(Parameter parameter);
  // Renames a parameter; every reference follows: node inputs, output slots, interface
  // outputs and preset values. Refused when `to` is not an identifier or is taken.
  std::string renameParameter(const std::string& from, const std::string& to);
  // Refused, naming every reference, while anything reads the parameter.
  std::string deleteParameter(const std::string& name);
  // Moves a parameter to position `index` (0-based) of the list (the order of the file
  // and of the inspector).
  std::string moveParameter(const std::string& name, size_t index);
  // A new preset holding every parameter's current value.
  std::string createPreset(const std::string& name);
  std::string renamePreset(const std::string& from, const std::string& to);
  std::string deletePreset(const std::string& name);
  // The canvas's frames (core/graph_edit_frames.cpp; Frame in core/graph.h), each one undo
  // step. A new frame around `nodes` (the graph's, at least one): `id` empty means
  // "frame_<n>", the first free, returned in *usedId; nodes another frame held leave it, and
  // a frame left empty goes. Refused for an id that is not an identifier or is taken.
  std::string addFrame(Frame frame, std::string* usedId = nullptr);
  // A frame's title and comment (any text within the loader's string limit).
  std::string setFrameText(const std::string& id, const std::string& title, const std::string& comment);
  // The nodes a frame holds, as addFrame takes them.
  std::string setFrameNodes(const std::string& id, const std::vector<std::string>& nodes);
  // Removes the frame; its nodes stay where they are.
  std::string deleteFrame(const std::string& id);
  // Moves every node of the frame by `by` (so the frame moves), merged like moveNodes while
  // the same frame keeps moving.
  std::string moveFrame(const std::string& id, std::array<double, 2> by);
  // Replaces the whole graph (a reload from disk), undoably.
  void replace(Graph graph, const std::string& label);
  // Takes the imported graphs of `loaded` (the same graph with its imports loaded again)
  // where an import has the same name and path and loaded, in the graph and in every undo
  // and redo state: what a subgraph file holds now is not part of the edit history, so
  // this is no edit and changes no revision.
  void adoptImports(const Graph& loaded);

  // Consecutive parameter or move edits of the same thing (a slider or a drag) become one
  // undo step until sealed; the UI seals when the drag ends.
  void seal() { mergeKey_.clear(); }

  bool canUndo() const { return !undo_.empty(); }
  bool canRedo() const { return !redo_.empty(); }
  bool undo();
  bool redo();
  // What undo and redo would do, e.g. "move node 'tint'" ("" when nothing).
  std::string undoLabel() const { return undo_.empty() ? "" : undo_.back().label; }
  std::string redoLabel() const { return redo_.empty() ? "" : redo_.back().label; }

  // Names the graph's state: every edit makes a new one, undo and redo bring the old one
  // back, so equal revisions mean equal graphs (the editor recompiles when it changes).
  long revision() const { return revision_; }
  bool dirty() const { return revision_ != savedRevision_; }
  void markSaved() { savedRevision_ = revision_; }

 private:
  struct Step {
    Graph graph;  // the state to go back (or forward) to
    long revision = 0;
    std::string label;
  };
  // Snapshots the graph before a change (or merges into the open step) and bumps revision.
  void record(const std::string& label, const std::string& mergeKey);
  Node* findNode(const std::string& id);
  std::string checkTarget(const InputTarget& target) const;
  void setSource(const InputTarget& target, InputSource source);
  // Deleted nodes leave their frames; a frame left empty goes (a saved frame holds a node).
  void dropFromFrames(const std::set<std::string>& gone);
  std::string checkFrameNodes(const std::vector<std::string>& nodes) const;
  void takeIntoFrame(Frame& frame, std::vector<std::string> nodes);

  Graph graph_;
  const Registry* registry_ = nullptr;
  std::vector<Step> undo_, redo_;
  std::string mergeKey_;
  long revision_ = 0;
  long nextRevision_ = 1;  // never reused, so "saved" stays right across undo and redo
  long savedRevision_ = 0;
};

}  // namespace wg
