// The body of forward.frag and its variants (show routing, velocity, and the
// single-pass stereo forms of view_block.glsl).
// Forward shading as in Fink et al. 2019, Sect. 5: a directional light with a shadow map and
// 3x3 percentage-closer filtering, sky reflections, albedo (procedural patterns), HDR output.
#if defined(MONOPLANE_STEREO_GS) || defined(MONOPLANE_STEREO_INSTANCED)
// The eye stereo_duplicate.geom drew this copy for, or the eye of the instance drawn (instanced).
layout(location = 5) flat in int in_view;
#define MONOPLANE_VIEW_INDEX in_view
#endif
#include "renderer/passes/shared/view_block.glsl"
layout(set = 0, binding = 1) uniform sampler2DShadow shadow_map;
#ifdef MONOPLANE_SHOW_ROUTING
#include "renderer/passes/culling/cull_constants.h"
// Per chunk, the lists the culling pass put it in this frame (MONOPLANE_ROUTE_*).
layout(std430, set = 1, binding = 1) readonly buffer Routing { uint routing[]; };
layout(location = 4) flat in uint in_chunk;
#endif

#include "renderer/passes/shared/sky.glsl"

layout(location = 0) in vec3 in_world;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec4 in_albedo;
layout(location = 8) flat in float in_alpha_cutoff;
layout(location = 3) flat in uint in_material;
layout(location = 6) in vec2 in_uv;
layout(location = 7) flat in uvec4 in_texture;
#define MONOPLANE_SCENE_TEXTURES_FRAGMENT
#include "renderer/passes/shared/scene_textures.glsl"
#ifdef MONOPLANE_AFTER_COMPOSITE
// Hybrid's blended chunks nearer than m or straddling it, drawn per eye after the composite:
// tested against the composite's linear depth (the eye's near content, and C's content mapped into
// the eye), which no depth buffer holds for C's part.
layout(set = 1, binding = 0) uniform sampler2D composite_linear_depth;
float composite_depth_at(ivec2 pixel) {
    return texelFetch(composite_linear_depth, pixel, 0).r;
}
#endif

// The alphaMode of the chunks this pipeline draws (scenes::AlphaMode): 0 opaque, 1 mask (drop
// the fragments below the chunk's cut-off), 2 blend (alpha out, for the pipeline's blending).
layout(constant_id = 1) const int kAlphaMode = 0;
// MSAA with alphaMode MASK: the pipeline turns alpha into sample coverage instead (alpha to
// coverage), so cut-out edges are anti-aliased like triangle edges.
layout(constant_id = 2) const bool kAlphaToCoverage = false;
layout(location = 0) out vec4 out_color;
// Distance in front of the eyes' plane along the head's forward axis: the same for all three
// cameras of the rig (they share the head's orientation), so hybrid can assemble it per pixel.
layout(location = 1) out float out_linear_depth;
#ifdef MONOPLANE_WRITE_VELOCITY
#include "renderer/passes/shared/velocity.glsl"
layout(location = 2) out vec2 out_velocity;  // NDC units, for TAA
#endif

const float PI = 3.14159265358979;

float hash12(vec2 p) {
    vec3 p3 = fract(vec3(p.xyx) * 0.1031);
    p3 += dot(p3, p3.yzx + 33.33);
    return fract((p3.x + p3.y) * p3.z);
}

float value_noise(vec2 p) {
    vec2 i = floor(p);
    vec2 f = fract(p);
    vec2 u = f * f * (3.0 - 2.0 * f);
    return mix(mix(hash12(i), hash12(i + vec2(1, 0)), u.x),
               mix(hash12(i + vec2(0, 1)), hash12(i + vec2(1, 1)), u.x), u.y);
}

// Procedural albedo modulation selected by the material's pattern (scenes/scene.h).
vec3 patterned_albedo(vec3 albedo, uint pattern, vec3 p) {
    if (pattern == 1u) {  // terrain: two octaves of noise, world-space, so both eyes agree
        float n = 0.6 * value_noise(p.xz * 0.7) + 0.4 * value_noise(p.xz * 3.1);
        return albedo * (0.75 + 0.5 * n);
    }
    if (pattern == 2u) {  // stripes across beams
        float s = step(0.5, fract(dot(p, vec3(1.0)) * 1.0));
        return albedo * mix(0.8, 1.1, s);
    }
    return albedo;
}

// 3x3 PCF: nine hardware-compared taps (each itself a 2x2 bilinear comparison).
float sun_visibility(vec3 world, vec3 normal) {
    vec4 clip = view.light_view_proj * vec4(world + normal * 0.02, 1.0);
    vec3 ndc = clip.xyz / clip.w;
    vec2 uv = ndc.xy * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))) || ndc.z > 1.0) return 1.0;
    float reference = ndc.z - view.shadow_params.y;
    float texel = view.shadow_params.x;
    float lit = 0.0;
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x)
            lit += texture(shadow_map, vec3(uv + vec2(x, y) * texel, reference));
    return lit / 9.0;
}

// The alpha written to the colour target: 1 for opaque; the base colour's alpha for blending;
// for alpha to coverage, alpha against the cut-off sharpened to about one pixel's ramp.
float output_alpha(float alpha) {
    if (kAlphaMode == 2) return alpha;
    if (kAlphaMode == 1 && kAlphaToCoverage) return coverage_alpha(alpha, in_alpha_cutoff);
    return 1.0;
}

void main() {
    float linear_depth = dot(in_world - view.head_position.xyz, view.head_forward.xyz);
#ifdef MONOPLANE_AFTER_COMPOSITE
    if (linear_depth >= composite_depth_at(ivec2(gl_FragCoord.xy))) discard;
#endif
    // Hybrid (Sect. 4.3): across a band below m the eye's view vector turns into C's, so that
    // highlights and reflections meet C's shading at the mono plane without a seam.
    vec3 origin = view.camera_position.xyz;
    float band = view.view_blend.y;
    if (band > 0.0) {
        float m = view.view_blend.x;
        origin = mix(origin, view.mono_camera_position.xyz, smoothstep(m - band, m, linear_depth));
    }
    vec3 n = normalize(in_normal);
    vec3 v = normalize(origin - in_world);
    if (dot(n, v) < 0.0) n = -n;  // thin two-sided geometry
    vec3 l = view.sun_direction.xyz;
    float roughness = float(in_material & 0xffu) / 255.0;
    float specular = float((in_material >> 8) & 0xffu) / 255.0;
    uint pattern = (in_material >> 16) & 0xffu;
    // glTF: the base colour is factor x vertex colour (in_albedo) x texture. The slot is flat,
    // so the branch is uniform within every primitive and the texture's gradients are valid.
    vec4 base_colour = in_albedo;
    if (in_texture.x != MONOPLANE_NO_TEXTURE) base_colour *= base_colour_texture(in_texture, in_uv);
    if (kAlphaMode == 1 && !kAlphaToCoverage && base_colour.a < in_alpha_cutoff) discard;
    vec3 albedo = base_colour.rgb;
    albedo = patterned_albedo(albedo, pattern, in_world);

    float n_dot_l = max(dot(n, l), 0.0);
    float visibility = n_dot_l > 0.0 ? sun_visibility(in_world, n) : 0.0;

    // Blinn-Phong lobe normalised for energy, exponent from roughness.
    vec3 h = normalize(l + v);
    float shininess = 2.0 / max(roughness * roughness, 1e-3) - 2.0;
    float lobe = (shininess + 8.0) / (8.0 * PI) * pow(max(dot(n, h), 0.0), shininess);
    float fresnel = specular + (1.0 - specular) * pow(1.0 - max(dot(n, v), 0.0), 5.0);

    vec3 sun = view.sun_radiance.rgb * n_dot_l * visibility;
    vec3 diffuse = albedo / PI * sun;
    vec3 highlight = sun * lobe * specular;

    // Sky light: a hemisphere term for diffuse (the sky's average colour above, light bounced
    // off the ground below), weaker than the sun as under a clear sky; the sky itself in the
    // mirror direction.
    vec3 sky_average = mix(view.sky_horizon.rgb, view.sky_zenith.rgb, 0.5);
    vec3 ground_bounce = view.ground_albedo.rgb * view.sun_radiance.rgb * max(view.sun_direction.y, 0.0) / PI;
    vec3 ambient = albedo * mix(ground_bounce, sky_average, 0.5 + 0.5 * n.y) * 0.45;
    vec3 reflected = sky_radiance(reflect(-v, n), view);
    float glossiness = (1.0 - roughness) * (1.0 - roughness);

    vec3 color = diffuse + highlight + ambient + reflected * fresnel * glossiness;
#ifdef MONOPLANE_SHOW_ROUTING
    // Hue by routing, brightness kept: green drawn by the eyes only, blue by C only, magenta by
    // both (the chunk straddles the overlap band, or its box does: candidates for force-mono).
    uint route = routing[in_chunk];
    bool by_eyes = (route & (MONOPLANE_ROUTE_LEFT | MONOPLANE_ROUTE_RIGHT)) != 0u;
    bool by_mono = (route & MONOPLANE_ROUTE_MONO) != 0u;
    vec3 hue = by_eyes && by_mono ? vec3(1.0, 0.1, 0.9)
                                  : (by_mono ? vec3(0.1, 0.35, 1.0) : vec3(0.1, 0.9, 0.15));
    color = hue * (0.3 + 0.7 * dot(color, vec3(0.2126, 0.7152, 0.0722)));
#endif
    out_color = vec4(color, output_alpha(base_colour.a));
    out_linear_depth = linear_depth;
#ifdef MONOPLANE_WRITE_VELOCITY
    out_velocity = ndc_velocity(vec4(in_world, 1.0));
#endif
}
