/* shading.c - tangent-space normal mapping (shading.h). */
#include "render/shading.h"

/* Below this a tangent (after removing its normal component) or a result has no direction. */
#define SHADING_DEGENERATE 1e-6f

vec3 render_normal_map(vec3 n, vec3 tangent, float bitangent_sign, vec3 rgb, float strength)
{
	vec3 t = v3_sub(tangent, v3_scale(n, v3_dot(tangent, n))); /* Gram-Schmidt */
	if (v3_length(t) < SHADING_DEGENERATE)
		return n;
	t = v3_normalize(t);
	vec3 b = v3_scale(v3_cross(n, t), bitangent_sign < 0.0f ? -1.0f : 1.0f);
	vec3 m = v3(strength * (2.0f * rgb.x - 1.0f), strength * (2.0f * rgb.y - 1.0f), 2.0f * rgb.z - 1.0f);
	vec3 out = v3_add(v3_add(v3_scale(t, m.x), v3_scale(b, m.y)), v3_scale(n, m.z));
	if (!(m.z > 0.0f) || v3_length(out) < SHADING_DEGENERATE || !v3_is_finite(out))
		return n;
	return v3_normalize(out);
}
