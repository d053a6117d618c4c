#pragma once
// GLSL-subset expressions printed as WGSL with their types (see codegen/wgsl_translate.h for
// the rules). The names in scope come from the statement printer that derives from this.
#include <optional>
#include <string>
#include <vector>

#include "codegen/glsl_subset.h"
#include "codegen/wgsl_types.h"

namespace wg::wgsl {

struct Symbol {
  ValueType type;
  std::string wgsl;              // how it is read
  std::string texture, sampler;  // a sampler: its two WGSL variables
};

// The suffix of a library function's form that samples level 0 where GLSL's has an implicit LOD.
inline constexpr const char* kLod0Suffix = "_lod0";

struct Callee {
  ValueType result;
  std::vector<ValueType> params;
  std::string wgslName;  // its implicit-LOD form (the same as the other when it does not sample so)
  bool samples = false;  // samples with an implicit LOD: needs uniform control flow
};

struct Printed {
  std::string text;
  ValueType type;
  std::string texture, sampler;  // set for a sampler
};

class ExpressionPrinter {
 public:
  virtual ~ExpressionPrinter() = default;
  Printed expression(const glsl_subset::Expr& e);
  // An initialiser or a returned value of type `want` (the GLSL has no implicit conversions
  // left: es300 compiles it, so the types agree; a mismatch throws).
  std::string converted(const glsl_subset::Expr& e, const ValueType& want);
  // An expression used as a statement: an assignment, ++/--, or a call.
  std::string expressionStatement(const glsl_subset::Expr& e);

 protected:
  virtual std::optional<Symbol> lookup(const std::string& name) const = 0;
  virtual std::optional<Callee> callee(const std::string& name) const = 0;
  virtual bool vertexStage() const = 0;
  virtual void useModHelper(const ValueType& t) = 0;
  virtual void noteImplicitSample() = 0;
  // Set once control flow may have diverged in the function being printed.
  bool tainted_ = false;

 private:
  Printed name(const glsl_subset::Expr& e);
  Printed literal(const glsl_subset::Expr& e);
  Printed unary(const glsl_subset::Expr& e);
  Printed binary(const glsl_subset::Expr& e);
  Printed call(const glsl_subset::Expr& e);
  Printed constructor(const ValueType& type, std::vector<Printed> args);
  Printed builtin(const std::string& name, std::vector<Printed> args);
  Printed texture(const std::string& name, std::vector<Printed> args);
  Printed member(const glsl_subset::Expr& e);
  Printed index(const glsl_subset::Expr& e);
};

// `p` widened to a vector of `size` components when it is a scalar (a no-op otherwise).
std::string splatTo(const Printed& p, int size);

}  // namespace wg::wgsl
