#pragma once
// The daylight model of runtime/sky_model.h as GLSL (valid in GLSL 330, ES 300 and Vulkan
// 450), for the runtime's sky and opaque-scene shaders (runtime/scene_shaders.cpp).
#include <string>

namespace wg::rt {

// Constants (written from sky_model.h's, so the two cannot drift) and functions:
//   WgSky wg_sky_state(vec3 s)              what the sky depends on besides d (a struct)
//   vec3 wg_ground(WgSky k)                 the radiance below the horizon
//   vec3 wg_sun_disc_radiance(vec3 s)       the disc as drawn (capped)
//   vec3 wg_sky_radiance(WgSky k, vec3 ground, vec3 disc, vec3 d, float footprint)
//                                           the sky pass: diffuse sky + the disc
//                                           band-limited to the pixel's footprint
//   vec3 wg_sun_irradiance(vec3 s)          uncapped, on a plane facing the sun
//   vec3 wg_sky_irradiance(vec3 n, vec3 s)  sky and ground on a plane of normal n
// d and n are unit directions, s the unit direction towards the sun. The text declares
// no uniforms; every function is finite and >= 0 for all unit inputs.
std::string skyGlsl();

}  // namespace wg::rt
