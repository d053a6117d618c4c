#pragma once
// Our own GLSL (the library items of nodes/glsl/, and each expression the plan's statements
// hold: what a node, or the planner, wrote into a declaration or an assignment of main())
// printed as WGSL, with WGSL's rules kept by construction:
// - every expression's type is tracked, so GLSL's implicit widenings become explicit (a scalar
//   given to min/max/clamp/step/smoothstep beside a vector is splatted; a vector == becomes
//   all(==); a shift count becomes u32; mod becomes x - y * floor(x / y), GLSL's definition);
// - ?: becomes select() (the library computes both sides on purpose: see nodes/glsl/common.glsl);
// - an implicit-LOD texture() is textureSample only in the fragment stage and only where
//   control flow is still uniform (before any if/for/while of its function, outside the right
//   side of && and ||); elsewhere, and in the vertex stage (where GLSL samples level 0), it is
//   textureSampleLevel(..., 0.0). A library item that samples so gets a second form,
//   NAME_vertex, for the vertex stage;
// - names WGSL reserves get a trailing '_'; parameters a function assigns are copied to a var.
// The WGSL module's interface (uniform struct, bindings, entry points) is codegen/emit_wgsl.cpp's.
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "codegen/wgsl_types.h"

namespace wg {
struct GlslItem;
}

namespace wg::wgsl {

enum class StageMode { Vertex, Fragment };

class Translator {
 public:
  // A name the stage bodies read or write, and the WGSL text it becomes ("wg_u.u_time").
  void declareGlobal(const std::string& name, ValueType type, std::string wgsl);
  // A GLSL sampler: its WGSL texture and sampler variables.
  void declareSampler(const std::string& name, ValueType type, std::string texture, std::string sampler);

  // One library item in `mode`, appended to the module's functions unless its WGSL form is
  // there already (an item that does not sample is the same in both stages). Items must come
  // dependencies first (GlslLibrary::itemsNamed's order).
  void addItem(const GlslItem& item, StageMode mode);

  // A local of the entry point being printed, declared by the plan with `type`: the
  // expressions after it read it as `name`. Returns its WGSL name. clearLocals() forgets
  // them all (the next entry point).
  std::string declareLocal(const std::string& name, ValueType type);
  void clearLocals() { locals_.clear(); }

  // One expression of a planned statement, printed as WGSL of type `expected`: the names it
  // reads are the globals and the locals declared so far, with the types given for them;
  // no statement, no stage text. Throws std::logic_error (outside the subset, an unknown
  // name, a value of another type).
  std::string expression(std::string_view glsl, StageMode mode, ValueType expected);
  // A planned assignment `name = glsl` as WGSL (no ';'): `name` a global or a local, the
  // value of its type. Throws std::logic_error.
  std::string assignment(const std::string& name, std::string_view glsl, StageMode mode);

  // The translated items and the helpers they need (mod), in dependency order.
  std::string functionsText() const;

 private:
  friend class TranslationContext;
  struct FunctionInfo {
    ValueType result;
    std::vector<ValueType> params;
    bool samples = false;  // has an implicit-LOD sample (fragment form), directly or through a call
  };
  struct Local {
    ValueType type;
    std::string wgsl;
  };
  std::map<std::string, Local> locals_;  // the entry point's, by GLSL name
  std::map<std::string, ValueType> globalTypes_;
  std::map<std::string, std::string> globalText_;
  std::map<std::string, std::pair<std::string, std::string>> samplers_;
  std::map<std::string, FunctionInfo> functions_;  // by GLSL name
  std::map<std::string, ValueType> constants_;     // library constants by GLSL name
  std::set<std::string> emitted_;                  // WGSL names of the items already in functions_
  std::set<std::string> helpers_;                  // "f32", "vec3<f32>": mod helpers
  std::vector<std::string> items_;                 // WGSL text of each item, in order
};

// The WGSL name of the mod helper for `t` ("wgsl_mod_vec3f").
std::string modHelperName(const ValueType& t);

}  // namespace wg::wgsl
