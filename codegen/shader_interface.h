#pragma once
// The fixed interface between generated shaders and whoever runs them (the runtime, the
// three.js client, an engine): attribute locations, the output, the Vulkan block.
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

// Builtin uniforms and scene samplers are rows of core/interface_tables.h
// (builtinUniformTable, sceneSamplerTable): declared only when used.

// Fragment output.
inline constexpr int kColorLocation = 0;
inline constexpr const char* kColorOutput = "o_color";  // vec4

// vk450: every non-opaque uniform lives in this block at set 0, binding 0 (std140);
// samplers take bindings from 1 upward in manifest order.
inline constexpr const char* kUniformBlock = "WgUniforms";
inline constexpr int kUniformBlockBinding = 0;

}  // namespace wg::iface
