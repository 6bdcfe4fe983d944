// The body of composite.frag, composite_velocity.frag and composite_display.frag (compiled three
// times). Fills an eye's pixels that no near (stereo) content covered with the mono camera C's
// image (Fink et al. 2019, Sect. 4.2), and writes their linear depth. The eye's far plane is the
// mono plane m, so such pixels still hold the cleared depth; the pipeline's depth test selects
// them. With MONOPLANE_WRITE_DISPLAY the colour is tone mapped into the eye's display image
// instead of its HDR image (one full-screen pass per eye: CompositePass::record_display).
#include "renderer/passes/shared/view_constants.h"
#ifdef MONOPLANE_WRITE_DISPLAY
#include "renderer/passes/tonemap/tone_mapping.glsl"
#endif

#include "renderer/passes/composite/composite_push.glsl"

layout(set = 0, binding = 0) uniform sampler2D mono_hdr;           // bilinear, clamped
layout(set = 0, binding = 1) uniform sampler2D mono_linear_depth;  // read texel-exact

layout(location = 0) in vec2 in_uv;  // pixel centre / eye size
// The eye's HDR colour, or with MONOPLANE_WRITE_DISPLAY its display image (tone mapped).
layout(location = 0) out vec4 out_color;
layout(location = 1) out float out_linear_depth;
#ifdef MONOPLANE_WRITE_VELOCITY
// C's screen-space velocity (TAA), read texel-exact like depth: Sect. 4.5 warns that filtering
// velocities linearly mixes the motion of near and far content at edges.
layout(set = 0, binding = 2) uniform sampler2D mono_velocity;
layout(location = 2) out vec2 out_velocity;
#endif

const float kMapProjective = 0.0;  // monoplane's hybrid: exact plane-induced mapping, bilinear
const float kMapOffsetCopy = 1.0;  // hybrid-farfield: C's pixels copied with a constant offset
const float kMapNothing = 2.0;     // debug "stereo only": the far region left black

void main() {
    float mapping = eye_extent_mode.z;
    vec3 color = vec3(0.0);
    float depth = MONOPLANE_SKY_LINEAR_DEPTH;
    ivec2 mono_texel = ivec2(-1);
    vec2 eye_ndc = in_uv * 2.0 - 1.0;
    vec4 c = vec4(0.0, 0.0, 0.0, 1.0);
    if (mapping == kMapProjective) {
        // The pixel's point on the mono plane: eye NDC with depth 0, the eye's far plane, which
        // is the mono plane (for a canted eye an oblique one: rig/rig.h).
        c = eye_to_mono * vec4(eye_ndc, 0.0, 1.0);
        vec2 uv = (c.xy / c.w * 0.5 + 0.5) * uv_limits.xy;
        // Keep the bilinear footprint inside C's viewport when it is a sub-range of the image.
        uv = clamp(uv, uv_limits.zw, uv_limits.xy - uv_limits.zw);
        color = texture(mono_hdr, uv).rgb;
        // Depth is never filtered: a bilinear mix of near and far depths is no surface at all.
        ivec2 size = textureSize(mono_linear_depth, 0);
        ivec2 texel = clamp(ivec2(uv * vec2(size)), ivec2(0), size - 1);
        depth = texelFetch(mono_linear_depth, texel, 0).r;
        mono_texel = texel;
    } else if (mapping == kMapOffsetCopy) {
        ivec2 size = textureSize(mono_hdr, 0);
        ivec2 texel = clamp(ivec2(gl_FragCoord.xy) + ivec2(offset_exposure.xy), ivec2(0), size - 1);
        color = texelFetch(mono_hdr, texel, 0).rgb;
        depth = texelFetch(mono_linear_depth, texel, 0).r;
        mono_texel = texel;
    }
    // Debug view "mono region tinted": a cool tint over everything C contributed.
    color = mix(color, color * vec3(0.45, 0.7, 1.6) + vec3(0.0, 0.02, 0.08), eye_extent_mode.w);
#ifdef MONOPLANE_WRITE_DISPLAY
    // The separate passes store this colour in the eye's half-float HDR image before tone mapping
    // it. Cutting the mantissa to a half float's 10 bits rounds as that store does on llvmpipe
    // (toward zero), so the display images are theirs bit for bit there; a device whose store
    // rounds to nearest differs by at most one half-float step, under 1/255 after tone mapping.
    // (The colours here are far inside the half-float range: no overflow or subnormal to mimic.)
    vec3 stored = uintBitsToFloat(floatBitsToUint(color) & 0xFFFFE000u);
    out_color = vec4(monoplane_tone_map(stored, offset_exposure.z), 1.0);
#else
    out_color = vec4(color, 1.0);
#endif
    out_linear_depth = depth;
#ifdef MONOPLANE_WRITE_VELOCITY
    // Eq. 9: v_{L,R} = 1/2 S v_C, C's velocity carried into the eye's NDC, never interpolated.
    vec2 mono_velocity_ndc = mono_texel.x >= 0 ? texelFetch(mono_velocity, mono_texel, 0).xy : vec2(0.0);
    if (mapping == kMapProjective) {
        // The general form of eq. 9: through the plane-induced homography, whose Jacobian is
        // constant (1/2 S) only for eyes parallel to C. J maps eye NDC to C's NDC at this pixel,
        // g(e) = (G e).xy / (G e).w with G = eye_to_mono at depth 0, so the eye's velocity is
        // J^-1 v_C (for a canted eye the mapping is projective and J varies over the image).
        vec2 g = c.xy / c.w;
        mat2 eye_to_mono_jacobian = mat2(eye_to_mono[0].xy - g * eye_to_mono[0].w,
                                         eye_to_mono[1].xy - g * eye_to_mono[1].w) / c.w;
        out_velocity = inverse(eye_to_mono_jacobian) * mono_velocity_ndc;
    } else {
        out_velocity = velocity_scale.xy * mono_velocity_ndc;
    }
#endif
}
