#pragma once
// Each node type's form in a surface query: its value and its derivatives along x0, z0
// and t (forward differentiation), written as expressions that are valid C and JavaScript
// alike (the JavaScript module defines the <math.h> names and wgd_/wgq_ helpers the C
// header has). The values follow each node's double eval exactly (the component-wise
// formulas of codegen/c_math_formulas.h, and gerstnerReference), so
// the query agrees with the CPU backend to rounding; the derivatives give the surface's
// normal and velocity and the Newton steps of the height inversion.
#include <array>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "codegen/c_parameters.h"
#include "core/ocean_settings.h"
#include "core/program.h"

namespace wg {

// One component of a value: an expression for it and for its derivatives along x0, z0, t;
// "0.0" stands for a derivative known to be zero (constants, parameters).
struct QueryScalar {
  std::string value;
  std::array<std::string, 3> d{"0.0", "0.0", "0.0"};
};
using QueryValue = std::vector<QueryScalar>;

// The statements of the generated function, in order; each bound expression becomes a
// `const` local ("const double" in C, "const" in JavaScript).
class QueryWriter {
 public:
  explicit QueryWriter(HeaderLanguage language) : language_(language) {}
  // `expr` as it is when it is a name or a number; otherwise a new local `name` holding it.
  std::string bind(const std::string& name, const std::string& expr);
  // The statements `roots` (expressions the function's outputs read) need, in order; a
  // local nothing reads (a component a swizzle drops) is left out, so -Wall stays quiet.
  std::string text(const std::vector<std::string>& roots) const;
  HeaderLanguage language() const { return language_; }
  // A statement written as it is (it declares `name`, an array), kept when a kept expression
  // reads `name`: the spectral ocean's map sample (codegen/query_ocean.h).
  void statement(const std::string& name, const std::string& text);

  // The spectral ocean the query reads, if any: the graph's prefix (its state is
  // <prefix>ocean, read through the pointer `o`) and the ocean_spectrum's settings.
  struct Ocean {
    std::string prefix;
    const ocean::OceanSettings* settings = nullptr;
  };
  Ocean ocean;

 private:
  struct Local {
    std::string name, expr;
    bool verbatim = false;
  };
  HeaderLanguage language_;
  std::vector<Local> locals_;
};

// Why an op cannot be part of a query (thrown while writing it; the caller names the node).
struct QueryRefusal : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Whether node type `type` has a query form (its value; its derivative may still be
// missing for some inputs, which queryOp refuses).
bool queryOpKnown(std::string_view type);

// The op's outputs, one QueryValue per output port (empty for a port the query does not
// compute: gerstner_waves' normal, tangent and binormal). `inputs` are the op's input
// sources, each with the source's own component count (a float splats). Locals are named
// from `name` (unique per op). Throws QueryRefusal.
std::vector<QueryValue> queryOp(const Op& op, const std::vector<QueryValue>& inputs, QueryWriter& w,
                                const std::string& name);

}  // namespace wg
