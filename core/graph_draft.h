#pragma once
// A graph file's JSON events gathered into drafts the loader checks (core/graph_parse*.cpp):
// the objects the format gives a structure (the graph, its parameters, presets, outputs and
// each node with its options, inputs and editor position, the imports, the interface, and
// the editor layout's frames) keep their members in file order with positions; every other
// value is held as a small nlohmann value, with its position.
// Nodes are handed over one at a time, as each ends, and their draft is reused, so no DOM
// or position tree of the whole file is ever built.
#include <deque>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/json_events.h"

namespace wg {

struct DraftValue;

// A structured value's members, in file order. Clearing keeps the elements, and the next
// emplace_back reuses one with the strings and member lists it holds: the node draft is
// refilled once per node, so the nodes array allocates nothing per node but the Graph's own
// storage (a vector that freed its elements made every node allocate its members again).
class DraftMembers {
 public:
  DraftValue* begin();
  DraftValue* end();
  const DraftValue* begin() const;
  const DraftValue* end() const;
  std::size_t size() const { return used_; }
  bool empty() const { return used_ == 0; }
  DraftValue& back();
  void clear() { used_ = 0; }
  DraftValue& emplace_back();  // a member with no members; its name and value are the caller's to set

 private:
  std::vector<DraftValue> items_;
  std::size_t used_ = 0;
};

struct DraftValue {
  std::string name;  // object members: the key
  JsonPosition key;  // object members: the key's opening quote
  JsonPosition at;   // the value's first character
  nlohmann::json::value_t type = nlohmann::json::value_t::null;
  bool structured = false;           // an object or array the format structures: see `members`
  nlohmann::json value;              // any other value, as written
  DraftMembers members;              // structured objects: members in file order

  // The first of that name, or nullptr. A view: the loader asks with literals, per node.
  const DraftValue* member(std::string_view wanted) const;
  DraftValue* member(std::string_view wanted) { return const_cast<DraftValue*>(std::as_const(*this).member(wanted)); }
};

inline DraftValue* DraftMembers::begin() { return items_.data(); }
inline DraftValue* DraftMembers::end() { return items_.data() + used_; }
inline const DraftValue* DraftMembers::begin() const { return items_.data(); }
inline const DraftValue* DraftMembers::end() const { return items_.data() + used_; }
inline DraftValue& DraftMembers::back() { return items_[used_ - 1]; }

class GraphDraftReader : public JsonEventHandler {
 public:
  const DraftValue& root() const { return root_; }
  std::size_t nodeCount() const { return nodeCount_; }  // elements of the root's "nodes" array

 protected:
  // Each element of the root's "nodes" array, once complete (any JSON type). The element
  // is reused for the next: take what it holds.
  virtual void node(DraftValue& element) = 0;
  // Every scalar and key of the file, as it comes (for checks on every value).
  virtual void seenScalar(const JsonScalar& value, JsonPosition at) = 0;
  virtual void seenKey(const std::string& name, JsonPosition at) = 0;

 private:
  // What the children of an open container are.
  enum class Level {
    Root,       // the graph: "parameters", "presets", "outputs", "interface" objects and "nodes" are
                // structured, "imports" is a Record
    Interface,  // the interface, the graph's "editor" layout: an object member ("outputs", "frames") is a Section
    Section,    // parameters, presets, outputs, the interface's outputs: each member object is a Record
    Record,     // a parameter, a preset, an output stage, an interface output, the imports: members held
    Nodes,     // the nodes array: each element is a node
    Node,      // "options", "inputs" and "editor" objects are Records
  };
  struct Open {
    DraftValue* value;
    Level level;
  };

  void scalar(JsonScalar& v, JsonPosition at) final;
  void startContainer(bool isArray, JsonPosition at) final;
  void endContainer(bool isArray) final;
  void key(std::string& name, JsonPosition at, bool duplicate) final;

  DraftValue& slot(JsonPosition at);  // where the value starting at `at` goes
  void finished();                    // a value of the top open container is complete
  nlohmann::json* hold(nlohmann::json&& v);  // into the held container being built

  DraftValue root_;
  DraftValue node_;  // the node being read, reused
  std::size_t nodeCount_ = 0;
  std::vector<Open> open_;
  // A held container being built: its open arrays and objects, and the key of the member
  // whose value comes next; values of duplicate keys go to scratch (the load fails anyway).
  std::vector<nlohmann::json*> held_;
  std::string heldKey_;
  bool heldDuplicate_ = false;
  std::deque<nlohmann::json> scratch_;
};

}  // namespace wg
