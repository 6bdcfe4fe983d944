#version 460
#extension GL_GOOGLE_include_directive : require
// The depth-only draws of alphaMode MASK chunks (the depth pre-pass, the shadow map): fragments
// whose alpha (base-colour factor x vertex colour x texture) is below the chunk's cut-off are
// dropped, the others write their depth. MONOPLANE_ALPHA_TO_COVERAGE (MSAA): the alpha goes out
// sharpened for the pipeline's alpha to coverage instead (coverage_alpha).
layout(location = 2) in vec4 in_albedo;
layout(location = 6) in vec2 in_uv;
layout(location = 7) flat in uvec4 in_texture;
layout(location = 8) flat in float in_alpha_cutoff;
#define MONOPLANE_SCENE_TEXTURES_FRAGMENT
#include "renderer/passes/shared/scene_textures.glsl"
#ifdef MONOPLANE_ALPHA_TO_COVERAGE
layout(location = 0) out vec4 out_color;
#endif

void main() {
    float alpha = surface_alpha(in_albedo.a, in_texture, in_uv);
#ifdef MONOPLANE_ALPHA_TO_COVERAGE
    out_color = vec4(0.0, 0.0, 0.0, coverage_alpha(alpha, in_alpha_cutoff));
#else
    if (alpha < in_alpha_cutoff) discard;
#endif
}
