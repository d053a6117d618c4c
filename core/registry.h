#pragma once
// The set of node types. nodes/registry.cpp fills the default one; tests may build their
// own. Lookups are by type name; iteration is in name order, so everything generated
// from the registry (docs, schema, palette) is stable.
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/file_node.h"
#include "core/node_spec.h"

namespace wg {

class Registry {
 public:
  void add(NodeSpec spec);  // throws std::logic_error on a duplicate or malformed spec
  const NodeSpec* find(std::string_view type) const;
  std::vector<const NodeSpec*> all() const;  // sorted by type name
  size_t size() const { return specs_.size(); }
  // A type whose nodes take their ports from a file (core/file_node.h). It is not among
  // all(): it has no spec of its own until a node names its file.
  void addFileNodeType(std::string type, FileNodeMaker make);
  const FileNodeMaker* fileNodeType(std::string_view type) const;
  std::vector<std::string> fileNodeTypeNames() const;  // sorted

 private:
  std::map<std::string, std::unique_ptr<NodeSpec>, std::less<>> specs_;
  std::map<std::string, FileNodeMaker, std::less<>> fileNodeTypes_;
};

}  // namespace wg
