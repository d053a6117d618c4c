#pragma once
// The daylight model of runtime/sky_model.h as GLSL (valid in GLSL 330, ES 300 and Vulkan
// 450), for the runtime's sky and opaque-scene shaders (runtime/scene_shaders.cpp).
#include <string>

namespace wg::rt {

// Constants (written from sky_model.h's, so the two cannot drift) and functions:
//   vec3 wg_sky_radiance(vec3 d, vec3 s)    the sky pass: diffuse sky + capped sun disc
//   vec3 wg_sun_irradiance(vec3 s)          uncapped, on a plane facing the sun
//   vec3 wg_sky_irradiance(vec3 n, vec3 s)  sky and ground on a plane of normal n
// d and n are unit directions, s the unit direction towards the sun. The text declares
// no uniforms; every function is finite and >= 0 for all unit inputs.
std::string skyGlsl();

}  // namespace wg::rt
