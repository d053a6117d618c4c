// The interface tables: one row per enumerator, in enumerator order (the look-ups index
// by it), names unique, and the cross-references between tables consistent.
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "core/interface_tables.h"
#include "core/node_spec.h"

namespace wg {
namespace {

template <class Table, class Field>
void expectOrderedAndUnique(Table table, Field field, const char* what) {
  std::set<std::string> names;
  for (size_t i = 0; i < table.size(); ++i) {
    EXPECT_EQ(static_cast<size_t>(table[i].id), i) << what << " row " << i << " is out of enumerator order";
    EXPECT_TRUE(names.insert(std::string(table[i].*field)).second) << what << " name repeated: " << table[i].*field;
  }
}

TEST(InterfaceTables, EveryTableListsItsEnumInOrderWithUniqueNames) {
  expectOrderedAndUnique(builtinTable(), &BuiltinRow::name, "builtin");
  expectOrderedAndUnique(builtinUniformTable(), &BuiltinUniformRow::meaning, "builtin uniform");
  expectOrderedAndUnique(builtinUniformTable(), &BuiltinUniformRow::glslName, "builtin uniform GLSL name");
  expectOrderedAndUnique(outputSlotTable(), &OutputSlotRow::name, "output slot");
  expectOrderedAndUnique(renderPassTable(), &RenderPassRow::name, "render pass");
  expectOrderedAndUnique(sceneResourceTable(), &SceneResourceRow::name, "scene resource");
  expectOrderedAndUnique(sceneSamplerTable(), &SceneSamplerRow::glslName, "scene sampler");
  expectOrderedAndUnique(sceneSamplerTable(), &SceneSamplerRow::target, "scene sampler target");
  expectOrderedAndUnique(builtinTextureTable(), &BuiltinTextureRow::name, "builtin texture");
  // The last enumerators have rows too (an added enumerator without a row fails here).
  EXPECT_EQ(builtinTable().size(), static_cast<size_t>(Builtin::PixelAngle) + 1);
  EXPECT_EQ(builtinUniformTable().size(), static_cast<size_t>(BuiltinUniform::TimePhase) + 1);
  EXPECT_EQ(outputSlotTable().size(), static_cast<size_t>(OutputSlot::FragmentAlpha) + 1);
  EXPECT_EQ(renderPassTable().size(), kRenderPassCount);
  EXPECT_EQ(sceneResourceTable().size(), static_cast<size_t>(SceneResource::Underwater) + 1);
  EXPECT_EQ(sceneSamplerTable().size(), static_cast<size_t>(SceneSampler::WaterSurface) + 1);
  EXPECT_EQ(builtinTextureTable().size(), static_cast<size_t>(BuiltinTexture::WaterNormal) + 1);
}

TEST(InterfaceTables, NamesParseBack) {
  for (const auto& r : builtinTable()) EXPECT_EQ(parseBuiltin(r.name), r.id);
  for (const auto& r : builtinUniformTable()) EXPECT_EQ(parseBuiltinUniform(r.meaning), r.id);
  for (const auto& r : outputSlotTable()) EXPECT_EQ(parseOutputSlot(r.name), r.id);
  for (const auto& r : renderPassTable()) EXPECT_EQ(parseRenderPass(r.name), r.id);
  for (const auto& r : sceneResourceTable()) EXPECT_EQ(parseSceneResource(r.name), r.id);
  for (const auto& r : sceneSamplerTable()) EXPECT_EQ(findSceneSampler(r.glslName), &r);
  for (const auto& r : builtinTextureTable()) EXPECT_EQ(parseBuiltinTexture(r.name), r.id);
  EXPECT_FALSE(parseSceneResource("scene_colour"));
  EXPECT_EQ(outputSlotList(), "(vertex: position, normal; fragment: color, alpha)");
}

TEST(InterfaceTables, CrossReferencesAgree) {
  // A builtin's uniform carries that builtin, with its type.
  for (const auto& b : builtinTable()) {
    const BuiltinUniformRow& u = builtinUniformRow(b.uniform);
    EXPECT_EQ(u.carries, b.id) << b.name;
    EXPECT_EQ(u.type, b.type) << b.name;
  }
  // A resource's own sampler belongs to it; every resource has one and is produced by a
  // pass other than the frame's own.
  for (const auto& r : sceneResourceTable()) {
    EXPECT_EQ(sceneSamplerRow(r.sampler).resource, r.id) << r.name;
    EXPECT_NE(r.pass, RenderPass::OpaqueScene) << r.name;
    EXPECT_NE(r.pass, RenderPass::WaterSurface) << r.name;
    EXPECT_FALSE(r.caseKeys[0].empty()) << r.name << " has no probe case key";
  }
  for (const auto& s : sceneSamplerTable()) EXPECT_TRUE(s.type == Type::Sampler2D || s.type == Type::SamplerCube);
  // The CPU environment reads each builtin from its own member.
  EvalEnvironment env;
  for (const auto& b : builtinTable()) EXPECT_EQ(&env.builtin(b.id), &(env.*b.environment)) << b.name;
  env.uv = Value::vector({0.25, 0.75});
  EXPECT_EQ(env.builtin(Builtin::Uv)[1], 0.75);
}

}  // namespace
}  // namespace wg
