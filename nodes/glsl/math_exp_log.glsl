// The exponential vocabulary's guarded forms. Each equals the GLSL built-in wherever that
// is finite and gives a documented finite value elsewhere; emitters call the raw built-in
// instead where value facts prove the guard dead.

// exp with x capped at 88: exp(88) = 1.65e38, where exp(89) overflows float to +inf.
float wg_safe_exp_float(float x) { return exp(min(x, 88.0)); }
vec2 wg_safe_exp_vec2(vec2 x) { return exp(min(x, 88.0)); }
vec3 wg_safe_exp_vec3(vec3 x) { return exp(min(x, 88.0)); }
vec4 wg_safe_exp_vec4(vec4 x) { return exp(min(x, 88.0)); }

// exp2 with x capped at 127: 2^127 = 1.70e38, where 2^128 overflows float to +inf.
float wg_safe_exp2_float(float x) { return exp2(min(x, 127.0)); }
vec2 wg_safe_exp2_vec2(vec2 x) { return exp2(min(x, 127.0)); }
vec3 wg_safe_exp2_vec3(vec3 x) { return exp2(min(x, 127.0)); }
vec4 wg_safe_exp2_vec4(vec4 x) { return exp2(min(x, 127.0)); }

// log with x floored at FLT_MIN (2^-126, the smallest normal float): x <= 0 gives
// log(2^-126) = -87.34 where GLSL gives -inf (x = 0) or leaves it undefined (x < 0).
float wg_safe_log_float(float x) { return log(max(x, 1.17549435e-38)); }
vec2 wg_safe_log_vec2(vec2 x) { return log(max(x, 1.17549435e-38)); }
vec3 wg_safe_log_vec3(vec3 x) { return log(max(x, 1.17549435e-38)); }
vec4 wg_safe_log_vec4(vec4 x) { return log(max(x, 1.17549435e-38)); }

// log2 with x floored at FLT_MIN: x <= 0 gives -126.
float wg_safe_log2_float(float x) { return log2(max(x, 1.17549435e-38)); }
vec2 wg_safe_log2_vec2(vec2 x) { return log2(max(x, 1.17549435e-38)); }
vec3 wg_safe_log2_vec3(vec3 x) { return log2(max(x, 1.17549435e-38)); }
vec4 wg_safe_log2_vec4(vec4 x) { return log2(max(x, 1.17549435e-38)); }

// sqrt with x floored at 0: a negative x (GLSL: undefined) gives 0.
float wg_safe_sqrt_float(float x) { return sqrt(max(x, 0.0)); }
vec2 wg_safe_sqrt_vec2(vec2 x) { return sqrt(max(x, 0.0)); }
vec3 wg_safe_sqrt_vec3(vec3 x) { return sqrt(max(x, 0.0)); }
vec4 wg_safe_sqrt_vec4(vec4 x) { return sqrt(max(x, 0.0)); }

// inversesqrt with x floored at FLT_MIN: x <= 0 gives 2^63 = 9.22e18 where GLSL gives
// +inf (x = 0) or leaves it undefined (x < 0).
float wg_safe_inversesqrt_float(float x) { return inversesqrt(max(x, 1.17549435e-38)); }
vec2 wg_safe_inversesqrt_vec2(vec2 x) { return inversesqrt(max(x, 1.17549435e-38)); }
vec3 wg_safe_inversesqrt_vec3(vec3 x) { return inversesqrt(max(x, 1.17549435e-38)); }
vec4 wg_safe_inversesqrt_vec4(vec4 x) { return inversesqrt(max(x, 1.17549435e-38)); }
