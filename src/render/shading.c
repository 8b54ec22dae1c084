/* shading.c - tangent-space normal mapping (shading.h). */
#include "render/shading.h"

/* Below this a tangent (after removing its normal component), relative to its length, or a result
 * has no direction. Relative: the tangent arrives in world units (a mesh's unit tangent through
 * the instance's transform), so an absolute bound dropped every normal map below scale 1e-6. */
#define SHADING_DEGENERATE 1e-6f

vec3 render_normal_map(vec3 n, vec3 tangent, float bitangent_sign, vec3 rgb, float strength)
{
	float size = v3_max_comp(v3_abs(tangent));
	if (!(size > 0.0f) || !isfinite(size))
		return n;
	tangent = v3_scale(tangent, 1.0f / size); /* its largest component 1: no underflow below */
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
