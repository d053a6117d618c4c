// Deferred water: when an op reads the underwater resource, the fragment stage runs as a
// full-screen pass after the runtime's water G-buffer pass, and takes the surface builtins
// of each pixel from that G-buffer instead of from varyings.
#include "codegen/plan_body.h"

namespace wg {
namespace {

// Which G-buffer textures the fragment's builtins need.
struct GBufferReads {
  bool surface = false;   // u_water_surface: world position, depth
  bool normalUv = false;  // u_water_normal_uv: normal.xz, uv
};

GBufferReads gBufferReads(const StageBody& fragment) {
  const auto& b = fragment.builtins;
  return {b.count(Builtin::WorldPosition) > 0 || b.count(Builtin::ViewDirection) > 0 || b.count(Builtin::FragDepth) > 0,
          b.count(Builtin::Normal) > 0 || b.count(Builtin::Uv) > 0};
}

std::string gBufferSampler(SceneSampler s) { return std::string(sceneSamplerRow(s).glslName); }

}  // namespace

// Declared once the fragment body is written, so the samplers are in the interface; the
// reads themselves are deferredLocals.
void planDeferredSamplers(BodyWriter& writer, StageBody& fragment) {
  GBufferReads reads = gBufferReads(fragment);
  if (!reads.surface && !reads.normalUv) return;
  writer.builtinExpr(fragment, Builtin::ScreenUv);
  if (reads.surface) writer.sceneSampler(fragment, SceneSampler::WaterSurface);
  if (reads.normalUv) writer.sceneSampler(fragment, SceneSampler::WaterNormalUv);
}

std::vector<TextureFetch> deferredFetches(const StageBody& fragment) {
  GBufferReads reads = gBufferReads(fragment);
  std::vector<TextureFetch> fetches;
  if (reads.surface) fetches.push_back({gBufferSampler(SceneSampler::WaterSurface), "b_screen_uv", true});
  if (reads.normalUv) fetches.push_back({gBufferSampler(SceneSampler::WaterNormalUv), "b_screen_uv", true});
  return fetches;
}

// The normal faces up, so its y is sqrt(1 - x^2 - z^2).
StageLocals deferredLocals(const StageBody& fragment) {
  const auto& b = fragment.builtins;
  GBufferReads reads = gBufferReads(fragment);
  StageLocals lines;
  if (b.count(Builtin::ScreenUv))
    lines.add(Type::Vec2, "b_screen_uv",
              "gl_FragCoord.xy / " + GlslExpr::name(std::string(builtinUniformRow(BuiltinUniform::ViewportSize).glslName)));
  if (reads.surface) {
    lines.add(Type::Vec4, "b_water_surface", "texture(" + GlslExpr::name(gBufferSampler(SceneSampler::WaterSurface)) + ", b_screen_uv)");
    lines.add(Type::Vec3, "v_world_position", GlslExpr("b_water_surface.xyz"));
  }
  if (reads.normalUv) {
    lines.add(Type::Vec4, "b_water_normal_uv",
              "texture(" + GlslExpr::name(gBufferSampler(SceneSampler::WaterNormalUv)) + ", b_screen_uv)");
    if (b.count(Builtin::Normal))
      lines.add(Type::Vec3, "v_normal",
                GlslExpr("vec3(b_water_normal_uv.x, sqrt(max(1.0 - dot(b_water_normal_uv.xy, b_water_normal_uv.xy), 0.0)), "
                         "b_water_normal_uv.y)"));
    if (b.count(Builtin::Uv)) lines.add(Type::Vec2, "v_uv", GlslExpr("b_water_normal_uv.zw"));
  }
  return lines;
}

}  // namespace wg
