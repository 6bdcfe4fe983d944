#version 460
#extension GL_GOOGLE_include_directive : require
// The stereo-aware obscuration estimate of papers/002 Sect. 3.1 for view 0, with view 1 the other
// eye. The samples lie on a world-space disk centred at P and perpendicular to the shared head
// forward axis (Fig. 3a), so both views place them alike; each is projected into both views and
// gives an HBAO+ obscurance in each: their mean where the sample's pixels are visible in both
// views (L, Case A), their maximum otherwise (Case B, Fig. 3d).
// With kFlagReproject (the right eye, Sect. 3.2) a pixel visible in both views takes the other
// view's estimate at its nearest pixel p* (no interpolation: over-interpolation is what the
// back-check avoids, Fig. 5); only the others are estimated here.
#include "renderer/passes/ssao/ssao_common.glsl"

// The obscurance of world sample S seen from view v, and whether its pixel there is visible in
// both views. Outside the area or on the sky it obscures nothing.
float sample_view(int v, vec3 S, vec3 P, vec3 N, out bool in_both) {
    in_both = false;
    ivec2 q = ivec2(floor(to_pixel(v, S).xy));
    if (!in_area(q)) return 0.0;
    float dq = depth_at(v, q);
    if (is_sky(dq)) return 0.0;
    in_both = other_pixel_at(v, q) != kNotVisible;
    return obscurance(N, world_at(v, q, dq) - P);
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (!in_area(p)) return;
    load_cameras();
    float d = depth_at(0, p);
    if (is_sky(d) || d > pc.skip_beyond) {
        imageStore(raw_ao0, p, vec4(1.0));
        return;
    }
    if ((pc.flags & kFlagReproject) != 0) {
        uint other = imageLoad(other_pixel0, p).r;
        if (other != kNotVisible) {
            imageStore(raw_ao0, p, imageLoad(raw_ao1, unpack_pixel(other)));
            return;
        }
    }
    vec3 P = world_at(0, p, d);
    vec3 N = normal_at(0, p, P);
    vec2 focal = cameras[0].focal_px;
    if (pc.radius * max(focal.x, focal.y) / clip_w(0, P) < 1.0) {
        imageStore(raw_ao0, p, vec4(1.0));
        return;
    }
    // The disk's axes: perpendicular to the head's forward axis, from it alone (the same in both
    // views).
    vec3 forward = cameras[0].head_forward;
    vec3 up = abs(forward.y) < 0.99 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    vec3 e1 = normalize(cross(forward, up));
    vec3 e2 = cross(e1, forward);
    // The random rotation and jitter are a function of the world position, not of the pixel, so
    // the two views draw the same pattern for the same point: P on a grid whose cell is about a
    // pixel's footprint at P's linear depth (a power of two, from d, which both views share).
    float cell = exp2(floor(log2(max(d, 1.0e-3) / max(focal.x, focal.y))));
    vec2 rnd = random2(uvec3(ivec3(floor(P / cell))));
    float sum = 0.0;
    for (int k = 0; k < pc.directions; ++k) {
        float angle = 2.0 * kPi * (float(k) + rnd.x) / float(pc.directions);
        vec3 dir = cos(angle) * e1 + sin(angle) * e2;
        for (int s = 0; s < pc.steps; ++s) {
            vec3 S = P + dir * (pc.radius * (float(s) + rnd.y) / float(pc.steps));
            bool both0;
            bool both1;
            float o0 = sample_view(0, S, P, N, both0);
            float o1 = sample_view(1, S, P, N, both1);
            sum += both0 && both1 ? 0.5 * (o0 + o1) : max(o0, o1);
        }
    }
    float ao = ao_from_obscurance(sum / float(pc.directions * pc.steps));
    imageStore(raw_ao0, p, vec4(ao));
}
