#version 460
#extension GL_GOOGLE_include_directive : require
// One pass of the separable cross-bilateral filter (papers/002 Sect. 3.3): horizontal (raw_ao ->
// filtered_x) or, with kFlagVertical, vertical (filtered_x -> ao). Taps are weighted by
// G_sigma(|P - K_i|) on world-space distance, sigma = r / 3 where r is the world length of N
// (taps) pixels at P's distance, clamped to [sigma_min, sigma_max]: F(p) alone per view.
// With kFlagStereo, for a pixel visible in both views, F and W are also evaluated around its
// other-view pixel p* (weights still against P) and blended:
// A(p) = w F(p) + (1 - w) F(p*), w = smoothstep(0.5 - eta, 0.5, alpha), alpha = W(p) / (W(p) + W(p*)).
#include "renderer/passes/ssao/ssao_common.glsl"

float input_at(int v, ivec2 q, bool vertical) {
    if (v == 0) return vertical ? imageLoad(filtered_x0, q).r : imageLoad(raw_ao0, q).r;
    return vertical ? imageLoad(filtered_x1, q).r : imageLoad(raw_ao1, q).r;
}

// (F, W) over the taps of view v centred at `centre` along `axis`; the sky and pixels outside the
// area take no part.
vec2 filter_taps(int v, ivec2 centre, ivec2 axis, vec3 P, float sigma, bool vertical) {
    float inv_two_sigma2 = 0.5 / (sigma * sigma);
    float norm = 1.0 / (sqrt(2.0 * kPi) * sigma);
    float f = 0.0;
    float w = 0.0;
    int half_taps = pc.taps / 2;
    for (int i = -half_taps; i <= half_taps; ++i) {
        ivec2 q = centre + i * axis;
        if (!in_area(q)) continue;
        float dq = depth_at(v, q);
        if (is_sky(dq)) continue;
        vec3 K = world_at(v, q, dq);
        float g = norm * exp(-dot(P - K, P - K) * inv_two_sigma2);
        f += g * input_at(v, q, vertical);
        w += g;
    }
    return vec2(w > 0.0 ? f / w : 1.0, w);
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (!in_area(p)) return;
    bool vertical = (pc.flags & kFlagVertical) != 0;
    load_cameras();
    float result = 1.0;
    float d = depth_at(0, p);
    if (!is_sky(d)) {
        vec3 P = world_at(0, p, d);
        ivec2 axis = vertical ? ivec2(0, 1) : ivec2(1, 0);
        float focal = vertical ? cameras[0].focal_px.y : cameras[0].focal_px.x;
        float r = float(pc.taps) * clip_w(0, P) / focal;
        float sigma = clamp(r / 3.0, pc.sigma_min, pc.sigma_max);
        vec2 own = filter_taps(0, p, axis, P, sigma, vertical);
        result = own.x;
        if ((pc.flags & kFlagStereo) != 0) {
            uint other = imageLoad(other_pixel0, p).r;
            if (other != kNotVisible) {
                vec2 theirs = filter_taps(1, unpack_pixel(other), axis, P, sigma, vertical);
                if (theirs.y > 0.0) {
                    float alpha = own.y / (own.y + theirs.y);
                    float w = smoothstep(0.5 - pc.eta, 0.5, alpha);
                    result = w * own.x + (1.0 - w) * theirs.x;
                }
            }
        }
    }
    if (vertical) {
        imageStore(ao0, p, vec4(result));
    } else {
        imageStore(filtered_x0, p, vec4(result));
    }
}
