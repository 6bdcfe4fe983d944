// The body of sky.frag and its variants (velocity, single-pass stereo).
// The sky behind the geometry: drawn after it where the depth buffer still holds the far plane.
#if defined(MONOPLANE_STEREO_GS) || defined(MONOPLANE_STEREO_INSTANCED)
// The eye stereo_duplicate.geom drew this copy for, or the eye of the instance drawn (instanced).
layout(location = 5) flat in int in_view;
#define MONOPLANE_VIEW_INDEX in_view
#endif
#include "renderer/passes/shared/view_block.glsl"
#include "renderer/passes/shared/sky.glsl"

layout(location = 0) in vec2 in_uv;
layout(location = 0) out vec4 out_color;
layout(location = 1) out float out_linear_depth;
#ifdef MONOPLANE_WRITE_VELOCITY
#include "renderer/passes/shared/velocity.glsl"
layout(location = 2) out vec2 out_velocity;  // NDC units, for TAA: the sky at infinity
#endif

void main() {
    vec2 ndc = in_uv * 2.0 - 1.0;
    vec4 near_point = view.inv_view_proj * vec4(ndc, 1.0, 1.0);
    vec4 far_point = view.inv_view_proj * vec4(ndc, 0.5, 1.0);
    vec3 direction = far_point.xyz / far_point.w - near_point.xyz / near_point.w;
    out_color = vec4(sky_radiance(direction, view), 1.0);
    out_linear_depth = MONOPLANE_SKY_LINEAR_DEPTH;
#ifdef MONOPLANE_WRITE_VELOCITY
    out_velocity = ndc_velocity(vec4(direction, 0.0));
#endif
}
