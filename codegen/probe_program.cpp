#include "codegen/probe_program.h"

#include "codegen/passes.h"
#include "core/resolve.h"
#include "core/suggest.h"

namespace wg {

std::optional<ProbeOutput> parseProbeOutput(const std::string& text) {
  ProbeOutput out;
  size_t dot = text.find('.');
  out.node = text.substr(0, dot);
  if (dot != std::string::npos) out.port = text.substr(dot + 1);
  if (out.node.empty() || (dot != std::string::npos && out.port.empty())) return std::nullopt;
  return out;
}

std::optional<Program> buildProbeProgram(const Graph& graph, const Registry& registry, const ProbeOutput& output,
                                         Diagnostics& diags) {
  NodeOutputValues nodeOutputs;
  auto program = resolveGraph(graph, registry, diags, nodeOutputs);
  if (!program) return std::nullopt;
  if (!output.node.empty()) {
    const Node* node = graph.findNode(output.node);
    auto found = nodeOutputs.find(output.node);
    if (found == nodeOutputs.end()) {
      std::vector<std::string> ids;
      for (const auto& [id, values] : nodeOutputs) ids.push_back(id);
      diags.error(DiagCode::DanglingReference, SourceRef{graph.file, 1, 1},
                  "the probe output names node '" + output.node + "', which the graph does not have" +
                      didYouMean(output.node, ids));
      return std::nullopt;
    }
    const std::vector<NodeOutputValue>& ports = found->second;
    const NodeOutputValue* chosen = ports.empty() ? nullptr : &ports.front();
    if (!output.port.empty()) {
      chosen = nullptr;
      for (const auto& p : ports)
        if (p.port == output.port) chosen = &p;
    }
    std::string type = node ? " (" + node->type + ")" : "";
    if (!chosen) {
      std::vector<std::string> names;
      for (const auto& p : ports) names.push_back(p.port);
      diags.error(DiagCode::UnknownOutputPort, node ? node->where : SourceRef{graph.file, 1, 1},
                  "node '" + output.node + "'" + type + " has no output '" + output.port + "'" + didYouMean(output.port, names),
                  output.node);
      return std::nullopt;
    }
    if (chosen->type == Type::Invalid) {
      diags.error(DiagCode::UnknownOutputPort, node ? node->where : SourceRef{graph.file, 1, 1},
                  "node '" + output.node + "'" + type + " has no output '" + chosen->port + "' for its input types",
                  output.node);
      return std::nullopt;
    }
    ProgramOutput out;
    out.slot = OutputSlot::FragmentColor;
    out.value = chosen->value;
    out.type = chosen->type;
    out.where = node ? node->where : SourceRef{graph.file, 1, 1};
    program->outputs = {out};
  } else {
    const ProgramOutput* color = program->output(OutputSlot::FragmentColor);
    if (!color) {
      diags.error(DiagCode::NoOutputs, SourceRef{graph.file, 1, 1},
                  "the graph has no fragment colour to probe; name a node output with --output NODE.PORT");
      return std::nullopt;
    }
    ProgramOutput keep = *color;
    program->outputs = {keep};
  }
  PassContext ctx{diags};
  specialisePass(*program, ctx);
  prunePass(*program, ctx);
  for (int round = 0; round < 8; ++round) {
    bool changed = foldPass(*program, ctx) == PassResult::Changed;
    changed |= simplifyPass(*program, ctx) == PassResult::Changed;
    changed |= csePass(*program, ctx) == PassResult::Changed;
    if (!changed) break;
  }
  prunePass(*program, ctx);
  for (auto& op : program->ops) op.stage = kFragmentStage;
  program->varyings.clear();
  return program;
}

}  // namespace wg
