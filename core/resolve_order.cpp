// Resolving, step 3: the nodes in data-flow order (Kahn's algorithm over flat arrays of
// node indices), every reference checked, every cycle named.
#include <algorithm>
#include <string>

#include "core/resolver.h"
#include "core/suggest.h"

namespace wg::resolving {

// Kahn's algorithm over node references: iterative, so a 100,000-node chain needs no
// deep recursion. Nodes left over lie on or behind a cycle; each cycle is named.
// The edges live in flat arrays (inputNode_ for dependencies, userBase/users for the
// reverse), not a vector per node: two allocations per node on a large graph otherwise.
std::vector<int> Resolver::topologicalOrder() {
  size_t n = graph_.nodes.size();
  std::vector<int> pending(n, 0);
  // inputBase_: laid out by lookUpSpecs.
  inputNode_.assign(inputBase_[n], -1);
  inputSourcePort_.assign(inputBase_[n], -1);
  for (size_t i = 0; i < n; ++i) {
    const Node& node = graph_.nodes[i];
    for (size_t k = 0; k < node.inputs.size(); ++k) {
      const NodeInput& in = node.inputs[k];
      if (in.source.kind == InputSource::Kind::Parameter) {
        if (!paramValue_.count(in.source.name)) {
          if (!parameterNames_) {
            std::vector<std::string> names;
            for (const auto& p : graph_.parameters) names.push_back(p.name);
            parameterNames_.emplace(std::move(names));
          }
          diags_.error(DiagCode::UnknownParameter, in.source.where,
                       "no parameter named '" + in.source.name + "'" +
                           parameterNames_->didYouMean(in.source.name),
                       node.id, inputLabel(in.port));
        }
        continue;
      }
      if (in.source.kind != InputSource::Kind::NodeOutput) continue;
      int dep = referencedNode(in.source, node.id, [&] { return inputLabel(in.port); }, &inputSourcePort_[inputBase_[i] + k]);
      if (dep < 0) continue;
      inputNode_[inputBase_[i] + k] = dep;
      if (static_cast<size_t>(dep) == i) {
        diags_.error(DiagCode::Cycle, in.source.where, "node '" + node.id + "' refers to itself", node.id,
                     inputLabel(in.port));
        continue;
      }
      ++pending[i];
    }
  }
  // Each node's users, in the order of (user, input): counted, then placed.
  std::vector<size_t> userBase(n + 1, 0);
  for (size_t i = 0; i < n; ++i)
    for (size_t e = inputBase_[i]; e < inputBase_[i + 1]; ++e)
      if (int d = inputNode_[e]; d >= 0 && static_cast<size_t>(d) != i) ++userBase[static_cast<size_t>(d) + 1];
  for (size_t i = 0; i < n; ++i) userBase[i + 1] += userBase[i];
  std::vector<int> users(userBase[n]);
  std::vector<size_t> fill(userBase.begin(), userBase.end() - 1);
  for (size_t i = 0; i < n; ++i)
    for (size_t e = inputBase_[i]; e < inputBase_[i + 1]; ++e)
      if (int d = inputNode_[e]; d >= 0 && static_cast<size_t>(d) != i) users[fill[static_cast<size_t>(d)]++] = static_cast<int>(i);
  std::vector<int> order;
  order.reserve(n);
  std::vector<int> ready;
  for (size_t i = n; i-- > 0;)
    if (pending[i] == 0) ready.push_back(static_cast<int>(i));
  // Pop the lowest index first so the order follows the file where it can.
  std::vector<bool> done(n, false);
  while (!ready.empty()) {
    int i = ready.back();
    ready.pop_back();
    order.push_back(i);
    done[static_cast<size_t>(i)] = true;
    for (size_t e = userBase[static_cast<size_t>(i)]; e < userBase[static_cast<size_t>(i) + 1]; ++e)
      if (--pending[static_cast<size_t>(users[e])] == 0) ready.push_back(users[e]);
  }
  if (order.size() < n) reportCycles(done);
  return order;
}

// Every node left unfinished lies on a cycle or behind one. Walks dependencies among
// them from each node not yet walked: a walk that comes back to a node of its own closes
// a new cycle (reported); one that reaches a node of an earlier walk leads into a cycle
// already reported. Each node is walked once, so disjoint cycles are each named in
// linear time.
// A node's dependencies are its inputs' nodes (inputNode_), a reference to itself aside.
void Resolver::reportCycles(const std::vector<bool>& done) {
  std::vector<size_t> walkOf(done.size(), 0);  // 0: not walked; else the walk's number
  std::vector<size_t> placeInWalk(done.size(), 0);
  size_t walkNumber = 0;
  for (size_t start = 0; start < done.size(); ++start) {
    if (done[start] || walkOf[start] != 0) continue;
    ++walkNumber;
    std::vector<int> walk;
    int cur = static_cast<int>(start);
    bool stuck = false;
    while (walkOf[static_cast<size_t>(cur)] == 0) {
      walkOf[static_cast<size_t>(cur)] = walkNumber;
      placeInWalk[static_cast<size_t>(cur)] = walk.size();
      walk.push_back(cur);
      int next = -1;
      for (size_t e = inputBase_[static_cast<size_t>(cur)]; e < inputBase_[static_cast<size_t>(cur) + 1]; ++e)
        if (int d = inputNode_[e]; d >= 0 && d != cur && !done[static_cast<size_t>(d)]) {
          next = d;
          break;
        }
      if (next < 0) {  // cannot happen: an unfinished node has an unfinished dependency
        stuck = true;
        break;
      }
      cur = next;
    }
    if (stuck || walkOf[static_cast<size_t>(cur)] != walkNumber) continue;  // into a known cycle
    reportCycle(std::vector<int>(walk.begin() + static_cast<long>(placeInWalk[static_cast<size_t>(cur)]), walk.end()));
  }
}

void Resolver::reportCycle(std::vector<int> cycle) {
  // Name the cycle in data-flow order, starting at its first node in the file.
  std::reverse(cycle.begin(), cycle.end());
  auto first = std::min_element(cycle.begin(), cycle.end());
  std::rotate(cycle.begin(), first, cycle.end());
  // A long cycle is named by its first and last steps (one line, not a megabyte of ids).
  constexpr size_t kShown = 8;
  std::string path;
  for (size_t k = 0; k < cycle.size(); ++k) {
    if (cycle.size() > 2 * kShown && k == kShown) {
      path += "... (" + std::to_string(cycle.size() - 2 * kShown) + " more nodes) -> ";
      k = cycle.size() - kShown;
    }
    path += "'" + graph_.nodes[static_cast<size_t>(cycle[k])].id + "' -> ";
  }
  path += "'" + graph_.nodes[static_cast<size_t>(cycle.front())].id + "'";
  const Node& at = graph_.nodes[static_cast<size_t>(cycle.front())];
  diags_.error(DiagCode::Cycle, at.where, "the nodes form a cycle: " + path, at.id);
}

}  // namespace wg::resolving
