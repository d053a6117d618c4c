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
  auto program = resolveGraph(graph, registry, diags);
  if (!program) return std::nullopt;
  if (!output.node.empty()) {
    // resolve keeps every node as an op (prune runs later), so the chosen one is there.
    int found = -1;
    std::vector<std::string> ids;
    for (size_t i = 0; i < program->ops.size(); ++i) {
      ids.push_back(program->ops[i].nodeId);
      if (program->ops[i].nodeId == output.node) found = static_cast<int>(i);
    }
    const Node* node = graph.findNode(output.node);
    if (found < 0) {
      diags.error(DiagCode::DanglingReference, SourceRef{graph.file, 1, 1},
                  "the probe output names node '" + output.node + "', which the graph does not have" +
                      didYouMean(output.node, ids));
      return std::nullopt;
    }
    const Op& op = program->ops[static_cast<size_t>(found)];
    int port = output.port.empty() ? 0 : op.spec->outputIndex(output.port);
    if (port < 0) {
      std::vector<std::string> ports;
      for (const auto& p : op.spec->outputs) ports.push_back(p.name);
      diags.error(DiagCode::UnknownOutputPort, node ? node->where : SourceRef{graph.file, 1, 1},
                  "node '" + output.node + "' (" + op.spec->type + ") has no output '" + output.port + "'" +
                      didYouMean(output.port, ports),
                  output.node);
      return std::nullopt;
    }
    if (op.outputTypes[static_cast<size_t>(port)] == Type::Invalid) {
      diags.error(DiagCode::UnknownOutputPort, node ? node->where : SourceRef{graph.file, 1, 1},
                  "node '" + output.node + "' (" + op.spec->type + ") has no output '" + op.spec->outputs[static_cast<size_t>(port)].name +
                      "' for its input types",
                  output.node);
      return std::nullopt;
    }
    ProgramOutput out;
    out.slot = OutputSlot::FragmentColor;
    out.value = ValueRef::op(found, port);
    out.type = op.outputTypes[static_cast<size_t>(port)];
    out.where = op.where;
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
