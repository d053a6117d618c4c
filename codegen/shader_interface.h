#pragma once
// The fixed interface between generated shaders and whoever runs them (the runtime, the
// three.js client, an engine): attribute locations, builtin uniform names, the output.
// Parameter uniforms are "p_" + the parameter's sanitised name; the manifest lists the
// exact names, types, defaults and ranges of everything a shader declares.
namespace wg::iface {

// Vertex attributes (object space).
inline constexpr int kPositionLocation = 0;  // vec3 a_position
inline constexpr int kNormalLocation = 1;    // vec3 a_normal
inline constexpr int kUvLocation = 2;        // vec2 a_uv
inline constexpr const char* kPositionAttribute = "a_position";
inline constexpr const char* kNormalAttribute = "a_normal";
inline constexpr const char* kUvAttribute = "a_uv";

// Builtin uniforms, declared only when used.
inline constexpr const char* kModel = "u_model";                    // mat4, object -> world
inline constexpr const char* kViewProjection = "u_view_projection"; // mat4, world -> clip
inline constexpr const char* kCameraPosition = "u_camera_position"; // vec3, world
inline constexpr const char* kTime = "u_time";                      // float, seconds
inline constexpr const char* kViewportSize = "u_viewport_size";     // vec2, pixels
inline constexpr const char* kCameraNearFar = "u_camera_near_far";  // vec2, near and far planes
inline constexpr const char* kView = "u_view";                      // mat4, world -> view
inline constexpr const char* kProjection = "u_projection";          // mat4, view -> clip
inline constexpr const char* kSunDirection = "u_sun_direction";     // vec3, unit, towards the sun

// Scene textures the runtime binds when the manifest lists the resource (and so the pass
// that renders it). Declared only by graphs whose nodes read them.
inline constexpr const char* kSceneDepthTexture = "u_scene_depth";      // sampler2D, resource scene_depth
inline constexpr const char* kSceneColorTexture = "u_scene_color";      // sampler2D, resource scene_color
inline constexpr const char* kReflectionTexture = "u_reflection";       // sampler2D, resource planar_reflection
inline constexpr const char* kRefractionTexture = "u_refraction";       // sampler2D, resource refraction
inline constexpr const char* kEnvironmentTexture = "u_environment";     // samplerCube, resource environment
// The water G-buffer of the deferred_water pass (resource underwater), RGBA32F, nearest:
// the surface's world position (xyz) and depth-buffer value (w; 1.0 where no water), and
// its upward normal's x and z with the mesh uv. A graph with an underwater node runs its
// fragment shader full-screen and reads its surface builtins from these.
inline constexpr const char* kWaterSurfaceTexture = "u_water_surface";      // sampler2D, resource underwater
inline constexpr const char* kWaterNormalUvTexture = "u_water_normal_uv";   // sampler2D, resource underwater

// Fragment output.
inline constexpr int kColorLocation = 0;
inline constexpr const char* kColorOutput = "o_color";  // vec4

// vk450: every non-opaque uniform lives in this block at set 0, binding 0 (std140);
// samplers take bindings from 1 upward in manifest order.
inline constexpr const char* kUniformBlock = "WgUniforms";
inline constexpr int kUniformBlockBinding = 0;

}  // namespace wg::iface
