#version 460
#extension GL_GOOGLE_include_directive : require
// The monoscopic HBAO+ estimate (NVIDIA 2016, as summarised in papers/002 Sect. 2 and by
// Vermeer et al. 2021) of one view: `directions` screen-space directions rotated by a per-pixel
// random angle, `steps` samples along each over the projected radius, each sample the surface
// seen at its pixel. Writes the unfiltered AO to raw_ao0.
#include "renderer/passes/ssao/ssao_common.glsl"

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (!in_area(p)) return;
    load_cameras();
    float d = depth_at(0, p);
    if (is_sky(d) || d > pc.skip_beyond) {
        imageStore(raw_ao0, p, vec4(1.0));
        return;
    }
    vec3 P = world_at(0, p, d);
    vec3 N = normal_at(0, p, P);
    // The world radius R seen at P's distance, per axis (pixels need not be square).
    vec2 radius_px = pc.radius * cameras[0].focal_px / clip_w(0, P);
    if (max(radius_px.x, radius_px.y) < 1.0) {  // the disk fits in the pixel: nothing to find
        imageStore(raw_ao0, p, vec4(1.0));
        return;
    }
    vec2 rnd = random2(uvec3(p, 0x55a0u));
    vec2 centre = vec2(p) + 0.5;
    float sum = 0.0;
    for (int k = 0; k < pc.directions; ++k) {
        float angle = 2.0 * kPi * (float(k) + rnd.x) / float(pc.directions);
        vec2 dir = vec2(cos(angle), sin(angle));
        for (int s = 0; s < pc.steps; ++s) {
            vec2 offset = dir * radius_px * ((float(s) + rnd.y) / float(pc.steps));
            if (dot(offset, offset) < 1.0) offset = dir;  // at least one pixel away, as HBAO+
            ivec2 q = ivec2(floor(centre + offset));
            if (!in_area(q) || q == p) continue;
            float dq = depth_at(0, q);
            if (is_sky(dq)) continue;  // the sky never occludes
            sum += obscurance(N, world_at(0, q, dq) - P);
        }
    }
    float ao = ao_from_obscurance(sum / float(pc.directions * pc.steps));
    imageStore(raw_ao0, p, vec4(ao));
}
