#pragma once
// How many operations the GLSL a node or the planner writes asks the GPU for, counted as a
// GlslExpr is built (core/emit_context.h), never by reading a shader back. A node combines
// values by appending its own literal pieces ("(", " * ", ", 0.0)") to them: each piece is
// counted once, as it is appended, by the rules below; a value appended brings its own count
// (it was counted as it was built); a call through EmitContext::call costs what the callee
// costs plus its arguments. A name the planner hands out (a temporary, a parameter, a
// uniform) is never read, so renaming one changes no count.
//
// The rules: binary and comparison operators, selects (?:), ++/-- and compound assignments
// count 1 each; a call of a GLSL built-in function (texture look-ups included) counts 1; a
// call of a library function (wg_*) counts what its body counts (nodes/glsl_library_cost.h
// computes that once per item from the library's own hand-written source); constructors,
// swizzles, unary signs, plain assignments and comments count 0. Vector width and the
// relative price of operations are ignored: a figure for ranking and for "is it more than
// a uniform read", not a measurement.
#include <cstdint>
#include <string_view>

namespace wg {

// Where a count stands after the text counted so far, so that the next piece continues it
// (a '-' after an operand is a subtraction, after '(' a sign; an identifier that ends one
// piece is a call when the next opens a parenthesis).
struct GlslOperationScan {
  int32_t pendingCall = -1;   // the text ends in an identifier: what calling it costs; -1 none
  bool afterOperand = false;  // the last token ends an operand (a name, a number, ')' or ']')
  bool started = false;       // a token has been seen
  bool leadingSign = false;   // the first token is a '+' or '-' counted as a sign (0)
  bool leadingParen = false;  // the first token is '('
};

// What a call of function `name` costs to a count (`context` is the caller's).
using GlslCallCost = int (*)(std::string_view name, const void* context);

// The operations of `text` read on from `scan` (which it updates); calls are priced by
// `callCost`.
int countGlslOperations(std::string_view text, GlslOperationScan& scan, GlslCallCost callCost, const void* context);

// Appends an already counted text whose count ended in `next` after the text of `scan`: the
// operations the seam adds (a leading sign that is a subtraction here, a pending identifier
// whose call `next` opens), with `scan` updated to the state after both.
int joinGlslOperations(GlslOperationScan& scan, const GlslOperationScan& next);

// Names followed by '(' that are no operation: constructors and statement keywords.
bool isFreeGlslCall(std::string_view name);

// A call of `name` in GLSL a node or the planner writes: 0 for a constructor or keyword,
// what the library declares for a library function (wg_*), 1 for a GLSL built-in.
int glslCallCost(std::string_view name);

// The library's costs, by function name: installed by the GLSL library
// (nodes/glsl_library_cost.cpp) before any node emits; core cannot see the library.
using LibraryCallCost = int (*)(std::string_view name);
void setLibraryCallCost(LibraryCallCost cost);

}  // namespace wg
