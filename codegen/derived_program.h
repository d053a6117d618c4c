#pragma once
// Derived uniforms, first step (issue #19): a per-draw value of a Program taken out as a
// small program of its own, over the same parameters and the per-draw builtins, in the
// node vocabulary, so a client can compute it once per draw with the double CPU backend
// instead of every pixel computing it in float. This file only extracts, evaluates and
// writes/reads that program (the manifest form); nothing here changes generated shaders.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/program.h"
#include "core/registry.h"

namespace wg {

struct DerivedValue {
  // The ops computing it (inputs: earlier ops, the original program's parameters by index,
  // per-draw builtins, constants), in topological order; no outputs.
  Program program;
  ValueRef value;  // the op output it is
  Type type = Type::Invalid;
};

// Which node types a derived program may hold: codegen/derived_vocabulary.h.

// The per-draw cone below op output (`root`, `port`) of `program`: every op it reads
// through, renumbered. Throws std::logic_error when the cone reads a value that is not
// per-draw (codegen/frequency.h) or an op that is a source other than a uniform input.
DerivedValue extractDerived(const Program& program, int root, int port);

// Its value for one draw: `parameters` by the original program's parameter index (a
// missing one takes its default), the builtins from `env`.
Value evaluateDerived(const DerivedValue& d, const EvalEnvironment& env, const std::vector<Value>& parameters = {});

// The manifest form: {"type", "value": {"op", "port"}, "ops": [{"node", "type", "options",
// "inputs": [{"op", "port"} | {"parameter": name} | {"builtin": name} | {"constant": [..],
// "type"}], "input_types", "output_types"}]}.
nlohmann::json derivedToJson(const DerivedValue& d);
// Back from the manifest form; parameters by name in `parameters`. nullopt with `error` set
// when a node type, parameter or builtin is unknown, an index points forward, or a type
// does not parse.
std::optional<DerivedValue> derivedFromJson(const nlohmann::json& j, const Registry& registry,
                                            const std::vector<ProgramParameter>& parameters, std::string& error);

}  // namespace wg
