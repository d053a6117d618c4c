// GLSL for the runtime's own passes: the sky and the lit opaque scene. One body per shader,
// with a per-API header and uniform declarations: desktop GL and Vulkan clip with
// gl_ClipDistance, ES 3.0 (no clip distances without an extension) discards fragments on
// the wrong side of the plane instead. Vulkan GLSL has no loose uniforms and needs a
// location on every in/out: its header defines WG_LOCATION(n) as the layout qualifier
// (the GL headers as nothing, GLSL 330 and ES 300 allow none on varyings) and each
// program's uniforms become one push-constant block. The WebGPU form (webgpu_shader_form.h)
// declares the same interface, varyings included, from the same data.
#include <string>
#include <vector>

#include "codegen/target.h"
#include "runtime/scene.h"
#include "runtime/sky_glsl.h"
#include "runtime/webgpu_shader_form.h"

namespace wg::rt {
namespace {

// Each API's version (the first line, "#version " + it) and what follows that line before
// every body. WG_VERTEX_ID: Vulkan GLSL names the vertex index gl_VertexIndex.
constexpr const char* kGlPreamble = "#define WG_CLIP_DISTANCE 1\n#define WG_LOCATION(n)\n#define WG_VERTEX_ID gl_VertexID\n";
constexpr const char* kEsPreamble =
    "precision highp float;\nprecision highp int;\n#define WG_LOCATION(n)\n#define WG_VERTEX_ID gl_VertexID\n";
constexpr const char* kVulkanPreamble =
    "#define WG_CLIP_DISTANCE 1\n#define WG_LOCATION(n) layout(location = n)\n#define WG_VERTEX_ID gl_VertexIndex\n";
// WebGPU has no clip distances without an optional feature: the opaque scene discards, as on ES.
constexpr const char* kWebgpuPreamble = "#define WG_LOCATION(n) layout(location = n)\n#define WG_VERTEX_ID gl_VertexIndex\n";

// A program's uniforms: loose for GL, one push-constant block for Vulkan (the runtime's
// own passes have a few matrices and vectors, well under the 128 bytes every Vulkan
// device offers; the block's std140-like offsets are the members' order: mat4 0, then
// 16-byte aligned vectors).
std::string uniforms(SceneShaderApi api, const std::string& block, const std::vector<ShaderMember>& members) {
  std::string s;
  if (api == SceneShaderApi::Vulkan450) {
    s = "layout(push_constant) uniform " + block + " {\n";
    for (const ShaderMember& m : members) s += "  " + m.type + " " + m.name + ";\n";
    return s + "};\n";
  }
  for (const ShaderMember& m : members) s += "uniform " + m.type + " " + m.name + ";\n";
  return s;
}

// The programs' constants: u_clip_plane (keep dot(plane, (p, 1)) >= 0) before
// u_sun_direction in the opaque scene's, at 64 and 80.
const std::vector<ShaderMember> kSkyConstants = {{"mat4", "u_inverse_view_projection"}, {"vec3", "u_sun_direction"}};
const std::vector<ShaderMember> kOpaqueConstants = {
    {"mat4", "u_view_projection"}, {"vec4", "u_clip_plane"}, {"vec3", "u_sun_direction"}};

// The varyings from each program's vertex stage to its fragment stage.
const std::vector<ShaderVarying> kSkyVaryings = {{0, false, "vec2", "v_ndc", ""},
                                                 {1, true, "vec3", "v_sun", ""},
                                                 {2, true, "vec3", "v_sky_scale", ""},
                                                 {3, true, "float", "v_sky_fade", ""},
                                                 {4, true, "vec3", "v_ground", ""},
                                                 {5, true, "vec3", "v_sun_disc", ""}};
const std::vector<ShaderVarying> kOpaqueVaryings = {{0, false, "vec3", "v_world", ""},
                                                    {1, false, "vec3", "v_normal", ""},
                                                    {2, true, "float", "v_material", ""},
                                                    {3, false, "vec3", "v_sky_irradiance", ""},
                                                    {4, true, "vec3", "v_sun_irradiance", ""}};

// The scene mesh's attributes (the description's "mesh".attributes), declared with their
// locations in every API.
const std::vector<ShaderVarying> kOpaqueMeshInputs = {{0, false, "vec3", "a_position", ""},
                                                      {1, false, "vec3", "a_normal", ""},
                                                      {kSceneMaterialLocation, false, "float", "a_material", ""}};

std::string attributeDeclarations(const std::vector<ShaderVarying>& list) {
  std::string s;
  for (const ShaderVarying& a : list)
    s += "layout(location = " + std::to_string(a.location) + ") in " + a.type + " " + a.name + ";\n";
  return s;
}

// The GL, ES and Vulkan form of varyings: WG_LOCATION(n) is a layout qualifier on Vulkan only.
std::string varyingDeclarations(const std::vector<ShaderVarying>& list, const char* direction) {
  std::string s;
  for (const ShaderVarying& v : list)
    s += "WG_LOCATION(" + std::to_string(v.location) + ") " + (v.flat ? "flat " : "") + direction + " " + v.type + " " +
         v.name + ";\n";
  return s;
}

// The unit direction towards the sun the scene options set.
constexpr const char* kSceneSun = R"glsl(
vec3 wg_scene_sun() { return u_sun_direction * inversesqrt(max(dot(u_sun_direction, u_sun_direction), 1e-30)); }
)glsl";

// The sky: the daylight model of runtime/sky_model.h (runtime/sky_glsl.cpp holds its
// GLSL) in linear scene radiance (scene.h states the unit). What depends only on the sun
// is computed by the full-screen triangle's vertices and reaches every pixel flat.
constexpr const char* kSkyVertex = R"glsl(void main() {
  // One triangle covering the viewport, at the far plane (depth 1).
  vec2 p = vec2(WG_VERTEX_ID == 1 ? 3.0 : -1.0, WG_VERTEX_ID == 2 ? 3.0 : -1.0);
  v_ndc = p;
  gl_Position = vec4(p, 1.0, 1.0);
  WgSky k = wg_sky_state(wg_scene_sun());
  v_sun = k.sun;
  v_sky_scale = k.scale;
  v_sky_fade = k.fade;
  v_ground = wg_ground(k);
  v_sun_disc = wg_sun_disc_radiance(k.sun);
}
)glsl";

constexpr const char* kSkyFragment = R"glsl(layout(location = 0) out vec4 o_color;
void main() {
  vec4 n = u_inverse_view_projection * vec4(v_ndc, -1.0, 1.0);
  vec4 f = u_inverse_view_projection * vec4(v_ndc, 1.0, 1.0);
  vec3 d = f.xyz / f.w - n.xyz / n.w;
  d *= inversesqrt(max(dot(d, d), 1e-30));
  // The pixel's angular footprint: the chord to its neighbours' directions, from the
  // derivatives (here, in uniform control flow). The disc is band-limited to it, so a disc
  // smaller than a texel of the environment cube is not a one-texel spike (sky_model.h).
  float footprint = max(length(dFdx(d)), length(dFdy(d)));
  o_color = vec4(wg_sky_radiance(WgSky(v_sun, v_sky_scale, v_sky_fade), v_ground, v_sun_disc, d, footprint), 1.0);
}
)glsl";

constexpr const char* kOpaqueVertex = R"glsl(void main() {
  v_world = a_position;
  v_normal = a_normal;
  v_material = a_material;
  // The light, per vertex (it varies slowly with the normal; the sun's not at all): the
  // sky and ground on this normal's plane, and the uncapped sun on a plane facing it.
  vec3 sun = wg_scene_sun();
  v_sky_irradiance = wg_sky_irradiance(a_normal * inversesqrt(max(dot(a_normal, a_normal), 1e-30)), sun);
  v_sun_irradiance = wg_sun_irradiance(sun);
  gl_Position = u_view_projection * vec4(a_position, 1.0);
#ifdef WG_CLIP_DISTANCE
  gl_ClipDistance[0] = dot(u_clip_plane, vec4(a_position, 1.0));
#endif
}
)glsl";

constexpr const char* kOpaqueFragment = R"glsl(layout(location = 0) out vec4 o_color;

vec3 terrainAlbedo(vec3 p) {
  // Pool tiles (1 m, dark grout) on the floor and walls; sand on the shore slope.
  vec2 f = fract(p.xz);
  float g = min(min(f.x, 1.0 - f.x), min(f.y, 1.0 - f.y));
  float grout = 1.0 - smoothstep(0.02, 0.04, g);
  vec3 tile = mix(vec3(0.62, 0.78, 0.80), vec3(0.30, 0.36, 0.38), grout);
  float checker = mod(floor(p.x) + floor(p.z), 2.0);
  tile *= 0.94 + 0.06 * checker;
  vec3 sand = vec3(0.78, 0.69, 0.50) * (0.95 + 0.05 * sin(p.x * 7.0 + p.z * 3.0));
  float sandy = smoothstep(2.0, 5.0, -p.x) * (1.0 - smoothstep(18.5, 19.5, abs(p.z)));
  return mix(tile, sand, sandy);
}

vec3 pillarAlbedo(vec3 p, vec3 n) {
  // Horizontal bands every 0.5 m so refraction and reflection bend something visible;
  // plain caps.
  float band = n.y > 0.5 ? 0.0 : step(0.5, fract(p.y));
  return mix(vec3(0.78, 0.74, 0.68), vec3(0.55, 0.30, 0.24), band);
}

void main() {
#ifndef WG_CLIP_DISTANCE
  if (dot(u_clip_plane, vec4(v_world, 1.0)) < 0.0) discard;
#endif
  vec3 n = v_normal * inversesqrt(max(dot(v_normal, v_normal), 1e-30));
  // 2 rock; 3 and 4 a floating buoy's red body and white top.
  vec3 albedo = v_material < 0.5 ? terrainAlbedo(v_world)
              : v_material < 1.5 ? pillarAlbedo(v_world, n)
              : v_material < 2.5 ? vec3(0.40, 0.37, 0.33)
              : v_material < 3.5 ? vec3(0.62, 0.06, 0.04) : vec3(0.85, 0.85, 0.82);
  // Lambertian: radiance = albedo E / pi, E the sun's irradiance on this plane (no
  // shadows) plus the sky's.
  vec3 e = v_sun_irradiance * max(dot(n, wg_scene_sun()), 0.0) + v_sky_irradiance;
  o_color = vec4(albedo * e * 0.3183098861837907, 1.0);  // 1 / pi
}
)glsl";

// Deferred water: one triangle covering the viewport; the graph's fragment shader reads
// everything it needs from textures.
constexpr const char* kFullscreenVertex = R"glsl(
void main() {
  vec2 p = vec2(WG_VERTEX_ID == 1 ? 3.0 : -1.0, WG_VERTEX_ID == 2 ? 3.0 : -1.0);
  gl_Position = vec4(p, 0.0, 1.0);
}
)glsl";

// Deferred water's G-buffer, written behind the graph's own vertex shader (displacement
// included) from its fixed-name varyings: world position and depth-buffer value; the
// upward unit normal's x and z (y is recovered as sqrt(1 - x^2 - z^2)) and the uv.
constexpr const char* kWaterGbufferFragment = R"glsl(
layout(location = 0) out vec4 o_surface;
layout(location = 1) out vec4 o_normal_uv;
void main() {
  vec3 n = v_normal * inversesqrt(max(dot(v_normal, v_normal), 1e-30));
  if (dot(n, n) < 0.5) n = vec3(0.0, 1.0, 0.0);
  if (n.y < 0.0) n = -n;
  o_surface = vec4(v_world_position, gl_FragCoord.z);
  o_normal_uv = vec4(n.x, n.z, v_uv);
}
)glsl";

}  // namespace

std::string_view glslVersion(SceneShaderApi api) {
  // The compiler's own versions (codegen/target.h): the runtime's shaders and the graph's
  // stages of one API share the line.
  switch (api) {
    case SceneShaderApi::Gl330: return targetGlslVersion(Target::Glsl330);
    case SceneShaderApi::Es300: return targetGlslVersion(Target::Es300);
    case SceneShaderApi::Vulkan450:
    case SceneShaderApi::WebGpu450: return targetGlslVersion(Target::Vk450);
  }
  return targetGlslVersion(Target::Glsl330);
}

std::string glslVersionLine(SceneShaderApi api) { return "#version " + std::string(glslVersion(api)) + "\n"; }

std::string sceneShaderPreamble(SceneShaderApi api) {
  switch (api) {
    case SceneShaderApi::Gl330: return kGlPreamble;
    case SceneShaderApi::Es300: return kEsPreamble;
    case SceneShaderApi::Vulkan450: return kVulkanPreamble;
    case SceneShaderApi::WebGpu450: return kWebgpuPreamble;
  }
  return kGlPreamble;
}

std::vector<SceneShaderInterface> sceneShaderInterfaces(const GbufferInputLocations& gbuffer) {
  // The G-buffer's inputs are the graph's varyings: a WebGPU host sets their locations by
  // these defines (the manifest's "webgpu".varyings), the text defaults them to `gbuffer`.
  const std::vector<ShaderVarying> gbufferInputs = {
      {gbuffer.worldPosition, false, "vec3", "v_world_position", "WG_LOCATION_V_WORLD_POSITION"},
      {gbuffer.normal, false, "vec3", "v_normal", "WG_LOCATION_V_NORMAL"},
      {gbuffer.uv, false, "vec2", "v_uv", "WG_LOCATION_V_UV"}};
  return {{"sky_vertex", "vertex", {"SkyConstants", kSkyConstants, {}, {}, kSkyVaryings}},
          {"sky_fragment", "fragment", {"SkyConstants", kSkyConstants, {}, kSkyVaryings, {}}},
          {"opaque_vertex", "vertex", {"OpaqueConstants", kOpaqueConstants, {}, kOpaqueMeshInputs, kOpaqueVaryings}},
          {"opaque_fragment", "fragment", {"OpaqueConstants", kOpaqueConstants, {}, kOpaqueVaryings, {}}},
          {"fullscreen_vertex", "vertex", {}},
          {"water_gbuffer_fragment", "fragment", {"", {}, {}, gbufferInputs, {}}}};
}

namespace {

// Every scene shader's body in its WebGPU form: the declarations of its interface, the library it
// uses, and its body (a vertex body inside the clip-space wrapper).
SceneShaderSources webgpuSceneShaderBodies(const GbufferInputLocations& gbuffer) {
  const std::vector<SceneShaderInterface> interfaces = sceneShaderInterfaces(gbuffer);
  auto form = [&](size_t k, const std::string& library, const char* body) {
    const bool vertex = interfaces[k].stage == std::string("vertex");
    return kWebgpuPreamble + webgpuDeclarations(interfaces[k].interface) + library + "\n" +
           (vertex ? webgpuVertexBodyBefore() : "") + body + (vertex ? webgpuVertexBodyAfter() : "");
  };
  const std::string skyModel = skyGlsl() + kSceneSun;
  SceneShaderSources s;
  s.skyVertex = form(0, skyModel, kSkyVertex);
  s.skyFragment = form(1, skyModel, kSkyFragment);
  s.opaqueVertex = form(2, skyModel, kOpaqueVertex);
  s.opaqueFragment = form(3, kSceneSun, kOpaqueFragment);
  s.fullscreenVertex = form(4, "", kFullscreenVertex);
  s.waterGbufferFragment = form(5, "", kWaterGbufferFragment);
  return s;
}

}  // namespace

SceneShaderSources sceneShaderBodies(SceneShaderApi api, const GbufferInputLocations& gbuffer) {
  if (api == SceneShaderApi::WebGpu450) return webgpuSceneShaderBodies(gbuffer);
  const std::string h = sceneShaderPreamble(api);
  const std::string sky = uniforms(api, "SkyConstants", kSkyConstants);
  const std::string opaque = uniforms(api, "OpaqueConstants", kOpaqueConstants);
  auto in = [&](int location, const char* declaration) {
    return (api == SceneShaderApi::Vulkan450 ? "layout(location = " + std::to_string(location) + ") " : std::string()) +
           "in " + declaration + ";\n";
  };
  SceneShaderSources s;
  const std::string skyModel = skyGlsl() + kSceneSun;
  s.skyVertex = h + sky + skyModel + "\n" + varyingDeclarations(kSkyVaryings, "out") + kSkyVertex;
  s.skyFragment = h + sky + skyModel + "\n" + varyingDeclarations(kSkyVaryings, "in") + kSkyFragment;
  s.opaqueVertex = h + opaque + skyModel + "\n" + attributeDeclarations(kOpaqueMeshInputs) +
                   varyingDeclarations(kOpaqueVaryings, "out") + kOpaqueVertex;
  s.opaqueFragment = h + opaque + kSceneSun + "\n" + varyingDeclarations(kOpaqueVaryings, "in") + kOpaqueFragment;
  s.fullscreenVertex = h + kFullscreenVertex;
  s.waterGbufferFragment = h + in(gbuffer.worldPosition, "vec3 v_world_position") + in(gbuffer.normal, "vec3 v_normal") +
                           in(gbuffer.uv, "vec2 v_uv") + kWaterGbufferFragment;
  return s;
}

SceneShaderSources sceneShaderSources(SceneShaderApi api, const GbufferInputLocations& gbuffer) {
  SceneShaderSources s = sceneShaderBodies(api, gbuffer);
  const std::string line = glslVersionLine(api);
  for (std::string* text : {&s.skyVertex, &s.skyFragment, &s.opaqueVertex, &s.opaqueFragment, &s.fullscreenVertex,
                            &s.waterGbufferFragment})
    text->insert(0, line);
  return s;
}

SceneShaderSources sceneShaderSources(bool es) {
  return sceneShaderSources(es ? SceneShaderApi::Es300 : SceneShaderApi::Gl330);
}

}  // namespace wg::rt
