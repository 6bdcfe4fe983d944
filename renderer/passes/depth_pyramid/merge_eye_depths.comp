#version 460
// Level 2 of the merged depth pyramid (Fink et al. 2019, Sect. 4.4, "Merged Depth Map"), in C's
// image space: each texel covers 4 x 4 of C's pixels (levels 0 and 1 are never written) and holds
// the farthest reversed-Z depth (the minimum) of every eye pixel, left or right, whose composite
// sample reads those pixels. An eye pixel q reads C bilinearly at H_e(q) (the homography through
// the mono plane, eq. 5), touching C's texels within one pixel of that point; so the texel's
// region, grown by one pixel, is mapped into each eye and the eye pixels whose centres fall in it
// are visited. An uncovered eye pixel still holds the cleared far depth 0: the texel becomes 0
// and C's content there is needed. A region no eye pixel reads keeps 1 (nothing needs it).
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform sampler2D eye_depth[2];  // reversed Z, cleared to 0 at m
layout(set = 0, binding = 1, r32f) uniform writeonly image2D level2;
layout(set = 0, binding = 3, r32f) uniform readonly image2DArray blocks;  // 4 x 4 minima, per eye
layout(push_constant) uniform Push {
    // Rows of the homography from C's pixels to eye e's pixels (x right, y down, centres at
    // i + 0.5): mono_to_eye[3 * e + row].xyz.
    vec4 mono_to_eye[6];
};

// Above this many eye blocks per texel (a grazing mapping) the texel is declared needed rather
// than visited: conservative, never wrong.
const int kMaxVisited = 8 * 8;

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, imageSize(level2)))) return;
    vec2 lo = vec2(texel * 4) - 1.0;
    vec2 hi = vec2(texel * 4 + 4) + 1.0;
    vec2 corners[4] = vec2[](lo, vec2(hi.x, lo.y), vec2(lo.x, hi.y), hi);
    float farthest = 1.0;
    for (int e = 0; e < 2 && farthest > 0.0; ++e) {
        vec2 eye_min = vec2(1e30);
        vec2 eye_max = vec2(-1e30);
        bool behind = false;
        for (int c = 0; c < 4; ++c) {
            vec3 p = vec3(corners[c], 1.0);
            vec3 h = vec3(dot(mono_to_eye[3 * e].xyz, p), dot(mono_to_eye[3 * e + 1].xyz, p),
                          dot(mono_to_eye[3 * e + 2].xyz, p));
            behind = behind || h.z <= 1e-9;
            eye_min = min(eye_min, h.xy / h.z);
            eye_max = max(eye_max, h.xy / h.z);
        }
        if (behind) {
            farthest = 0.0;
            break;
        }
        ivec2 size = textureSize(eye_depth[e], 0);
        ivec2 first = max(ivec2(ceil(eye_min - 0.5)), ivec2(0));
        ivec2 last = min(ivec2(floor(eye_max - 0.5)), size - 1);
        if (any(greaterThan(first, last))) continue;  // no pixel of this eye reads here
        first >>= 2;  // the blocks holding those pixels
        last >>= 2;
        ivec2 span = last - first + 1;
        if (span.x * span.y > kMaxVisited) {
            farthest = 0.0;
            break;
        }
        for (int y = first.y; y <= last.y && farthest > 0.0; ++y) {
            for (int x = first.x; x <= last.x; ++x) {
                farthest = min(farthest, imageLoad(blocks, ivec3(x, y, e)).r);
            }
        }
    }
    imageStore(level2, texel, vec4(farthest));
}
