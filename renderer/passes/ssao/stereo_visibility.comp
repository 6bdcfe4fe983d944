#version 460
#extension GL_GOOGLE_include_directive : require
// The visibility map L of view 0 (papers/002 Sect. 3.1, Fig. 5d): a pixel's world point is
// projected into the other view, the nearest pixel p* there is reconstructed and projected back;
// the pixel is visible in both views when the round trip lands within back_check_px of its
// centre (the back-check) and neither pixel is sky. Stores p* (which the reprojection of
// Sect. 3.2 and the filter of Sect. 3.3 use) or kNotVisible.
#include "renderer/passes/ssao/ssao_common.glsl"

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (!in_area(p)) return;
    load_cameras();
    uint result = kNotVisible;
    float d = depth_at(0, p);
    if (!is_sky(d)) {
        vec3 there = to_pixel(1, world_at(0, p, d));
        ivec2 q = ivec2(floor(there.xy));
        if (in_area(q)) {
            float dq = depth_at(1, q);
            if (!is_sky(dq)) {
                vec3 back = to_pixel(0, world_at(1, q, dq));
                if (distance(back.xy, vec2(p) + 0.5) <= pc.back_check_px) result = pack_pixel(q);
            }
        }
    }
    imageStore(other_pixel0, p, uvec4(result));
}
