#version 460
// The first step of the merged depth pyramid: each eye's depth reduced to 4 x 4 blocks (the
// farthest, i.e. minimum, reversed-Z depth of each block), so that the step into C's image space
// reads a few block values per eye instead of every eye pixel. Four gathers per block.
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform sampler2D eye_depth[2];  // reversed Z, cleared to 0 at m
layout(set = 0, binding = 2, r32f) uniform writeonly image2DArray blocks;  // layer = eye

void main() {
    ivec3 id = ivec3(gl_GlobalInvocationID);
    int eye = id.z;
    if (any(greaterThanEqual(id.xy, imageSize(blocks).xy))) return;
    vec2 size = vec2(textureSize(eye_depth[eye], 0));
    float farthest = 1.0;
    for (int y = 0; y < 2; ++y) {
        for (int x = 0; x < 2; ++x) {
            // The gather's footprint is the 2 x 2 texels around this point; clamp-to-edge
            // sampling repeats the last row or column at the image's odd end, which is harmless
            // for a minimum.
            vec2 centre = (vec2(id.xy * 4 + ivec2(x, y) * 2) + 1.0) / size;
            vec4 four = textureGather(eye_depth[eye], centre, 0);
            farthest = min(farthest, min(min(four.x, four.y), min(four.z, four.w)));
        }
    }
    imageStore(blocks, ivec3(id.xy, eye), vec4(farthest));
}
